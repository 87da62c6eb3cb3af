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
// The same closure with the potential on the faces ('Contact/Potential
// integration = faces', 'Penalty factor = 1000'), from the same rigid
// stage: several links press the shell at once, and the faces' points,
// not the nodes, decide which; the same checks hold (doc/studies.md, its
// forces against the nodes').
#include "../tests.h"
#include "grasp_helpers.h"

#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;
using softgrasp_tests::set;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_coarse_arm(prm, "output-arm-qs");
  set(prm, {"Time"}, "Integrator", "quasi-static");

  GraspParameters grasp;
  grasp.parse_parameters(prm, PARAMETER_FILES);
  grasp.scene_file = ArmGraspStudy(MPI_COMM_WORLD, prm)
                         .rigid_scene(grasp.scene_file, "output-arm-qs");
  std::ostringstream   log;
  GraspSimulation      simulation(grasp, log);
  const KinematicsData data = simulation.run();

  for (const std::string integration : {"nodes", "faces"})
  {
    set(prm, {"Contact"}, "Potential integration", integration);
    set(prm,
        {"Contact"},
        "Penalty factor",
        integration == "faces" ? "1000" : "100");
    set(prm, {"Output"}, "Directory", "output-arm-qs-" + integration);
    ArmGraspStudy study(MPI_COMM_WORLD, prm);
    study.run(data);
    const auto &s = study.summary();
    SG_CHECK_CLOSE(s.closure, 0.15, 1e-12, 0, "the whole closure");
    SG_CHECK(s.balance < 1e-8, "link forces balance the humerus' reaction");
    SG_CHECK(s.penetration < 1e-6, "no penetration beyond 1 micrometre");
    dealii::deallog << "quasi-static, " << integration
                    << ": the whole closure of 0.15 rad; link forces balance "
                       "the reaction to 1e-8, no penetration"
                    << std::endl;
    for (const auto &link : study.link_forces())
    {
      std::cout << integration << ": " << link.link << " " << link.normal.back()
                << " N" << std::endl;
      if (link.link.find("distal") != std::string::npos)
        SG_CHECK(link.normal.back() > 10,
                 "every distal link presses: " + link.link);
    }
    dealii::deallog << "every distal link presses with more than 10 N"
                    << std::endl;
  }
}
