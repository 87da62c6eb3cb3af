// The rigid half of the grasp-and-pull sweep with the parallel-jaw gripper
// (issue 54), set up by the sweep's .prm entries alone: the jaws (slide
// joints, mesh pads) close across the fixed rigid arm, each level's jaw
// closure is found and the gripper pulls 2 cm along the arm.
//  - 3 levels from the equilibrium grip to 12 N on the right pad, each
//    reached within 2 % (MuJoCo's settled answer to the jaw targets), with
//    growing closures (in m);
//  - the base moves the pull distance (within the servo's lag, 5 %);
//  - Coulomb's law holds for both pads at every level (lateral force at
//    most mu times the normal force, averaged over the second half of the
//    pull), and on the rigid arm the pads slide.
#include "../tests.h"

#include <filesystem>
#include <softgrasp/mujoco/grasp_pull_sweep.h>
#include <softgrasp/solvers/solver_program.h>

using namespace softgrasp;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  GraspPullSweep::declare_parameters(prm);
  SolverProgram::read_parameters<3>(prm,
                                    PARAMETER_FILES "/grasp_pull_sweep.prm");
  prm.parse_input_from_string(
      "subsection Grasp-and-pull sweep\n"
      " set Grip link = right_jaw/right_pad\n set Levels = 3\n"
      " set Highest grip force = 12\n set Pull samples = 10\nend\n"
      "subsection Rigid environment\n"
      " set Scene file = mjcf/parallel_jaw_gripper.xml\n"
      " set Base position = 0, 0, 0.07\n"
      " set Finger joints = left_jaw_joint, right_jaw_joint\n"
      " set Contact links = left_pad, right_pad\n"
      " set Closing speed = 0.05\n set Grip = 0.002\n"
      " subsection Indentation\n  set Extra joint angle = 0.01\n"
      "  set Joint weights =\n end\nend\n"
      "subsection Output\n set Directory = output-gripper-sweep\nend\n",
      "",
      true);

  std::filesystem::remove_all("output-gripper-sweep");
  PullSweepStudy study(MPI_COMM_WORLD, prm);
  GraspPullSweep sweep(
      MPI_COMM_WORLD, prm, PARAMETER_FILES "/grasp_pull_sweep.prm", study);
  std::ostringstream log;
  sweep.run_rigid(log);
  const auto &levels = sweep.rigid_levels();
  const auto &p      = sweep.parameters().rigid;
  SG_CHECK(levels.size() == 3, "three levels");
  const double mu               = levels.front().friction;
  double       previous_closure = -1;
  for (const auto &level : levels)
  {
    SG_CHECK(level.matched, "every level reached");
    SG_CHECK_CLOSE(level.reached_force,
                   level.target_force,
                   0.02,
                   0,
                   "grip force of the level");
    SG_CHECK(level.closure > previous_closure, "closures grow");
    previous_closure = level.closure;
    SG_CHECK(level.slide.back() > 0.95 * p.pull_distance &&
                 level.slide.back() <= p.pull_distance + 1e-6,
             "the base moves the pull distance");
    for (const auto &link : level.links)
      if (link.geom == "left_pad" || link.geom == "right_pad")
      {
        SG_CHECK(link.lateral_mean <= mu * link.normal_mean * (1 + 1e-6) + 1e-9,
                 "Coulomb: lateral <= mu N on " + link.geom);
        SG_CHECK(link.slides, "the pad slides on the rigid arm");
      }
  }
  dealii::deallog << "3 levels from the equilibrium grip to 12 N on the "
                     "right pad, each within 2 %, with growing closures (m)"
                  << std::endl;
  dealii::deallog << "both pads: lateral <= mu N (mu = " << mu
                  << "), sliding on the rigid arm" << std::endl;
}
