// Coarse sphere_squeeze regression with physics checks, end to end from the
// shipped parameter file (one refinement less): MuJoCo closes the hand on the
// free sphere, the finite element solver indents the rubber sphere on the
// recorded poses.
//  - MuJoCo's equilibrium: every contact link touches; the sphere is free
//    and gravity is off, so the link forces on it sum to zero (within 1 %
//    of the largest);
//  - finite elements: the link forces equal the support reaction of the
//    core holding the sphere (within 1e-6 of the largest link force, i.e.
//    global equilibrium of the discrete problem with contact); no
//    penetration beyond 1 micrometre; the thumb's proximal link force grows
//    with the closure;
//  - with a target normal force on the thumb's proximal link the run stops
//    at the first step that reaches it.
#include "../tests.h"
#include "grasp_helpers.h"

#include <iomanip>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  softgrasp_tests::read_coarse_sphere_squeeze(prm);
  prm.enter_subsection("Output");
  prm.set("Directory", "fe_output");
  prm.leave_subsection();

  std::ostringstream   log;
  GraspSimulation      simulation(softgrasp_tests::sphere_grasp_parameters(prm),
                             log);
  const KinematicsData data = simulation.run();

  Eigen::Vector3d sum     = Eigen::Vector3d::Zero();
  double          largest = 0;
  unsigned int    links   = 0;
  for (const auto &f : data.equilibrium_forces)
  {
    sum += f.force;
    largest = std::max(largest, f.force.norm());
    links += f.geom.find("_link") != std::string::npos;
  }
  dealii::deallog << "MuJoCo equilibrium: finger links touching " << links
                  << ", |sum of forces on the free sphere| < 1 % of the "
                     "largest: "
                  << (sum.norm() < 0.01 * largest) << std::endl;
  SG_CHECK(links == 6, "all six finger links touch at equilibrium");
  SG_CHECK(sum.norm() < 0.01 * largest, "free sphere in equilibrium");

  IndentationStudy study(MPI_COMM_WORLD, prm);
  study.run(data);
  const auto &s = study.summary();
  dealii::deallog << "FE: closure " << s.closure << " rad in " << s.steps
                  << " steps, target force reached: " << s.target_met
                  << std::endl;
  dealii::deallog << "FE: link forces equal the support reaction: "
                  << (s.balance < 1e-6) << std::endl;
  dealii::deallog << "FE: penetration below 1 micrometre: "
                  << (s.penetration < 1e-6) << std::endl;
  SG_CHECK(s.balance < 1e-6, "force balance with the support");
  SG_CHECK(s.penetration < 1e-6, "no penetration");

  const auto       &table = study.link_table();
  const std::string thumb = "thumb_proximal/thumb_proximal_link:FE_normal";
  bool              grows = true;
  for (std::size_t row = 1; row < table.rows.size(); ++row)
    grows = grows && table.value(row, thumb) >= table.value(row - 1, thumb);
  SG_CHECK(grows && table.value(table.rows.size() - 1, thumb) > 1,
           "thumb proximal force grows with the closure");
  for (std::size_t l = 0; l < s.links.size(); ++l)
  {
    std::ostringstream line;
    line << s.links[l] << ": FE normal " << std::fixed << std::setprecision(1)
         << s.normal_fe[l] << " N, MuJoCo " << s.normal_rigid[l] << " N";
    dealii::deallog << line.str() << std::endl;
  }

  // The indented state defined by a target normal force on the thumb's
  // proximal link instead of the whole closure: the run stops at the first
  // step at which the force reaches 20 N.
  prm.enter_subsection("Indentation study");
  prm.set("Target link", "thumb_proximal/thumb_proximal_link");
  prm.set("Target normal force", "20");
  prm.leave_subsection();
  prm.enter_subsection("Output");
  prm.set("Directory", "fe_target");
  prm.leave_subsection();
  IndentationStudy targeted(MPI_COMM_WORLD, prm);
  targeted.run(data);
  const auto &t    = targeted.summary();
  const auto &rows = targeted.link_table();
  const auto  n    = rows.rows.size();
  SG_CHECK(t.target_met && rows.value(n - 1, thumb) >= 20 &&
               rows.value(n - 2, thumb) < 20 && t.closure < s.closure,
           "stopped at the target normal force");
  dealii::deallog << "target 20 N on the thumb proximal link: stopped at "
                  << "closure " << t.closure
                  << " rad, reached: " << t.target_met << std::endl;
}
