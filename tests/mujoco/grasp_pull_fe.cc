// The finite element half of the grasp-and-pull sweep (GraspPullSweep::
// run_fe) on a coarse arm (16 cells around, no fascia), 2 levels, a 5 mm
// pull, the sweep's friction (mu = 1) and damping.
//  - every level is reached: the closing stops at the first record where
//    the grip link's normal force is at or above the level's;
//  - every pull runs to its end, with the link forces balancing the
//    humerus' reaction (within 5 % of the largest link force: the rest is
//    the inertia of the explicit run; 2 % here) and no node inside a link
//    by more than 1 micrometre;
//  - the links meet a drag against the pull: at its end the total force
//    on them along the pull axis exceeds 5 % of their total normal force
//    (11 and 9 % here; it is 0 when the pull starts).
#include "../tests.h"
#include "grasp_helpers.h"

#include <softgrasp/mujoco/grasp_pull_sweep.h>

using namespace softgrasp;
using softgrasp_tests::set;

namespace
{
  /// Total drag (force on the links against the pull, world y) and total
  /// link normal force at the end of each level's pull (N).
  std::vector<std::pair<double, double>> run(const std::string &directory)
  {
    dealii::ParameterHandler prm;
    GraspPullSweep::declare_parameters(prm);
    SolverProgram::read_parameters<3>(prm,
                                      PARAMETER_FILES "/grasp_pull_sweep.prm");
    set(prm, {"Mesh", "Layered limb"}, "Circumferential cells", "16");
    set(prm, {"Mesh", "Layered limb"}, "Radial cells", "1, 1, 1, 2");
    set(prm, {"Mesh", "Layered limb"}, "Grasp zone cells", "4");
    set(prm, {"Mesh", "Layered limb"}, "Fascia thickness", "0");
    set(prm, {"Grasp-and-pull sweep"}, "Levels", "2");
    set(prm, {"Grasp-and-pull sweep"}, "Highest grip force", "30");
    set(prm, {"Grasp-and-pull sweep"}, "Pull distance", "0.005");
    set(prm, {"Grasp-and-pull sweep"}, "Pull samples", "10");
    set(prm, {"Output"}, "Directory", directory);
    set(prm, {"Output"}, "VTU interval", "0");
    PullSweepStudy study(MPI_COMM_WORLD, prm);
    GraspPullSweep sweep(
        MPI_COMM_WORLD, prm, PARAMETER_FILES "/grasp_pull_sweep.prm", study);
    std::ostringstream log;
    sweep.run_rigid(log);
    sweep.run_fe(log);
    std::vector<std::pair<double, double>> totals;
    for (const auto &level : sweep.fe_levels())
    {
      SG_CHECK(level.reached, "level reached");
      SG_CHECK(level.reached_force >= level.target_force, "at or above it");
      SG_CHECK(level.pulled, "pull to its end: " + level.failure);
      SG_CHECK(level.balance < 0.05, "link forces balance the humerus");
      SG_CHECK(level.penetration < 1e-6, "no penetration");
      double drag = 0, normal = 0;
      for (const auto &link : level.links)
        if (!link.time.empty())
        {
          drag -= link.force.back()[1];
          normal += link.normal.back();
        }
      totals.emplace_back(drag, normal);
    }
    return totals;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  const auto totals = run("output-pull");
  dealii::deallog << "2 levels reached, pulled to the end, link forces "
                     "balance the humerus within 5 %, no penetration"
                  << std::endl;
  for (const auto &[drag, normal] : totals)
    SG_CHECK(drag > 0.05 * normal, "the links meet a drag");
  dealii::deallog << "the links' drag exceeds 5 % of their normal force"
                  << std::endl;
}
