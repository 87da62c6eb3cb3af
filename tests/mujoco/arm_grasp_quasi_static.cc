// The coarse arm grasp of tests/mujoco/arm_grasp, quasi-static: on this
// frictional grasp (mu = 1) a skin node sits in the crease between the
// thumb's proximal and distal links. Held against whichever link was
// nearest, it changed link and stick/slip state at every Newton iteration
// and the run stopped at 44 % of the closure; a node now keeps its link
// within a load step (doc/contact.md, "Nodes between two geoms").
//  - the whole closure is run (0.15 rad);
//  - the link forces balance the humerus' reaction to round-off (a
//    quasi-static equilibrium: 1e-8 of the largest link force);
//  - no node penetrates a link by more than 1 micrometre;
//  - the distal links carry the grip (more than 10 N each on this coarse
//    mesh).
#include "../tests.h"

#include <softgrasp/grasp/arm_grasp_study.h>
#include <softgrasp/mechanics/solver_program.h>
#include <softgrasp/mujoco/grasp_parameters.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;

namespace
{
  void set(dealii::ParameterHandler       &prm,
           const std::vector<std::string> &path,
           const std::string              &entry,
           const std::string              &value)
  {
    for (const auto &section : path)
      prm.enter_subsection(section);
    prm.set(entry, value);
    for (std::size_t i = 0; i < path.size(); ++i)
      prm.leave_subsection();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  GraspParameters::declare_parameters(prm);
  ArmGraspStudy::declare_parameters(prm);
  SolverProgram::read_parameters<3>(prm, PARAMETER_FILES "/arm_grasp.prm");
  set(prm, {"Mesh", "Layered limb"}, "Circumferential cells", "16");
  set(prm, {"Mesh", "Layered limb"}, "Radial cells", "1, 1, 1, 2");
  set(prm, {"Mesh", "Layered limb"}, "Grasp zone cells", "4");
  set(prm, {"Mesh", "Layered limb"}, "Fascia thickness", "0");
  set(prm, {"Indentation study"}, "Pictures", "false");
  set(prm, {"Indentation study"}, "Target normal force", "0");
  set(prm, {"Time"}, "Integrator", "quasi-static");
  set(prm, {"Output"}, "Directory", "output-arm-qs");
  set(prm, {"Output"}, "VTU interval", "0");

  ArmGraspStudy   study(MPI_COMM_WORLD, prm);
  GraspParameters grasp;
  grasp.parse_parameters(prm, PARAMETER_FILES);
  grasp.scene_file = study.rigid_scene(grasp.scene_file, "output-arm-qs");
  std::ostringstream   log;
  GraspSimulation      simulation(grasp, log);
  const KinematicsData data = simulation.run();
  study.run(data);

  const auto &s = study.summary();
  SG_CHECK_CLOSE(s.closure, 0.15, 1e-12, 0, "the whole closure");
  SG_CHECK(s.balance < 1e-8, "link forces balance the humerus' reaction");
  SG_CHECK(s.penetration < 1e-6, "no penetration beyond 1 micrometre");
  dealii::deallog << "quasi-static: the whole closure of 0.15 rad; link "
                     "forces balance the reaction to 1e-8, no penetration"
                  << std::endl;
  for (const auto &link : study.link_forces())
    if (link.link.find("distal") != std::string::npos)
      SG_CHECK(link.normal.back() > 10,
               "every distal link presses: " + link.link);
  dealii::deallog << "every distal link presses with more than 10 N"
                  << std::endl;
}
