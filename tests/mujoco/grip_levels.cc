// The rigid half of the grasp-and-pull sweep (GraspPullSweep::run_rigid) on
// the shipped grasp_pull_sweep.prm with 4 levels: MuJoCo closes the large
// hand on the fixed rigid arm, finds each level's closure and pulls 2 cm
// along the arm.
//  - every level reaches its grip force on the thumb's proximal link
//    within 2 % (MuJoCo's settled answer to the actuator targets), the
//    levels run from the equilibrium grip to 40 N and their closures grow;
//  - the base moves the pull distance (within the servo's lag, 5 %);
//  - Coulomb's law holds for every link at every level: the lateral force
//    averaged over the second half of the pull is at most mu times the
//    normal force averaged over it (MuJoCo's elliptic cone);
//  - on the rigid arm the grip link slides at every level, with a lateral
//    force of mu N (within 2 %): a rigid body cannot hold the pull;
//  - the tables and the figure's data are written.
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
  prm.enter_subsection("Grasp-and-pull sweep");
  prm.set("Levels", "4");
  prm.set("Pull samples", "10");
  prm.leave_subsection();
  prm.enter_subsection("Output");
  prm.set("Directory", "output-sweep");
  prm.leave_subsection();

  // a run of the test starts afresh: a record left by an earlier run would
  // be reused, with no levels run
  std::filesystem::remove_all("output-sweep");
  PullSweepStudy study(MPI_COMM_WORLD, prm);
  GraspPullSweep sweep(
      MPI_COMM_WORLD, prm, PARAMETER_FILES "/grasp_pull_sweep.prm", study);
  std::ostringstream log;
  sweep.run_rigid(log);
  const auto &levels = sweep.rigid_levels();
  const auto &p      = sweep.parameters().rigid;
  SG_CHECK(levels.size() == 4, "four levels");
  const double mu = levels.front().friction;
  SG_CHECK_CLOSE(levels.back().target_force, 40, 1e-12, 0, "top level");
  double previous_closure = -1;
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
    {
      SG_CHECK(link.lateral_mean <= mu * link.normal_mean * (1 + 1e-6) + 1e-9,
               "Coulomb: lateral <= mu N on " + link.geom);
      if (link.geom == p.grip_link)
      {
        SG_CHECK(link.slides, "the grip link slides on the rigid arm");
        SG_CHECK_CLOSE(link.lateral_mean,
                       mu * link.normal_mean,
                       0.02,
                       0,
                       "sliding grip link: lateral = mu N");
      }
    }
  }
  dealii::deallog << "4 levels from the equilibrium grip to 40 N, each "
                     "within 2 %, with growing closures"
                  << std::endl;
  dealii::deallog << "every link: lateral <= mu N (mu = " << mu
                  << "); the grip link slides with lateral = mu N" << std::endl;
  for (const char *file :
       {"sweep_rigid_levels.csv", "sweep_rigid_pulls.csv", "sweep_figure.dat"})
    SG_CHECK(std::filesystem::exists(std::string("output-sweep/") + file),
             std::string("written: ") + file);
  dealii::deallog << "tables and figure data written" << std::endl;
}
