// The finite element half of the grasp-and-pull sweep on a coarse arm (16
// cells around, no fascia), 2 levels, a 5 mm pull, the sweep's friction
// (mu = 1) and damping; run three ways, as a user would:
//  - the whole sweep (GraspPullSweep::run_fe) in one go:
//    - every level is reached: the closing stops at the first record where
//      the grip link's normal force is at or above the level's;
//    - every pull runs to its end, with the link forces balancing the
//      humerus' reaction (within 5 % of the largest link force: the rest
//      is the inertia of the explicit run; 2 % here) and no node inside a
//      link by more than 1 micrometre;
//    - Coulomb: at every record of every pull, every link's friction-only
//      force is at most mu times the sum of its nodes' normal forces;
//    - the links meet a drag against the pull: at its end the total force
//      on them along the pull axis exceeds 5 % of their total normal force
//      (11 and 9 % here; it is 0 when the pull starts);
//    - a collect run (a new sweep object, as a new process) reads the same
//      levels back from their records, and does not run MuJoCo again;
//  - level 2 alone (--level 2) in a fresh directory: the same level 2;
//  - a sweep killed after level 1 (--level 1 ran) and run again: level 1
//    is not run again (its record is untouched) and both levels equal the
//    uninterrupted sweep's.
#include "../tests.h"
#include "grasp_helpers.h"

#include <filesystem>
#include <softgrasp/mujoco/grasp_pull_sweep.h>

using namespace softgrasp;
using softgrasp_tests::CoarseSweep;

namespace
{
  void check_physics(const std::vector<FeGripLevel> &levels, const double mu)
  {
    SG_CHECK(levels.size() == 2, "two levels");
    for (const auto &level : levels)
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
          for (std::size_t i = 0; i < link.time.size(); ++i)
            SG_CHECK(link.friction[i] <=
                         mu * link.nodal_normal[i] * (1 + 1e-9) + 1e-12,
                     "Coulomb on " + link.link);
        }
      SG_CHECK(drag > 0.05 * normal, "the links meet a drag");
    }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  // a run of the test starts afresh (its directory is kept between runs)
  for (const char *directory : {"output-full", "output-level", "output-resume"})
    std::filesystem::remove_all(directory);
  std::vector<FeGripLevel> full;
  {
    CoarseSweep s("output-full");
    s.sweep->run_fe(s.log);
    full = s.sweep->fe_levels();
    check_physics(full, 1.0);
  }
  dealii::deallog << "2 levels reached, pulled to the end, link forces "
                     "balance the humerus within 5 %, no penetration, "
                     "friction within Coulomb's bound, a drag above 5 % of "
                     "the normal force"
                  << std::endl;
  {
    CoarseSweep s("output-full");
    SG_CHECK(s.log.str().find("not run again") != std::string::npos,
             "the rigid stage's record is reused");
    s.sweep->collect(s.log);
    const auto &read = s.sweep->fe_levels();
    SG_CHECK(read.size() == 2 &&
                 softgrasp_tests::level_difference(read[0], full[0]) == 0 &&
                 softgrasp_tests::level_difference(read[1], full[1]) == 0,
             "collect reads the levels back");
  }
  dealii::deallog << "collect: the levels read back from their records"
                  << std::endl;
  {
    CoarseSweep s("output-level");
    s.sweep->close(s.log, 2);
    s.sweep->pull(2, s.log);
    const auto &alone = s.sweep->fe_levels();
    SG_CHECK(alone.size() == 2 && !alone[0].pulled, "only level 2 pulled");
    SG_CHECK(softgrasp_tests::level_difference(alone[1], full[1]) < 1e-9,
             "level 2 alone equals level 2 of the sweep");
  }
  dealii::deallog << "--level 2 alone: level 2 of the whole sweep" << std::endl;
  {
    namespace fs = std::filesystem;
    {
      CoarseSweep s("output-resume");
      s.sweep->close(s.log, 1);
      s.sweep->pull(1, s.log);
    }
    CoarseSweep       s("output-resume");
    const std::string record = s.study->record_file(1);
    const auto        before = fs::last_write_time(record);
    s.sweep->run_fe(s.log);
    SG_CHECK(fs::last_write_time(record) == before &&
                 s.log.str().find("Level 1: finished") != std::string::npos,
             "level 1 is not run again");
    const auto &resumed = s.sweep->fe_levels();
    SG_CHECK(resumed.size() == 2 &&
                 softgrasp_tests::level_difference(resumed[0], full[0]) <
                     1e-9 &&
                 softgrasp_tests::level_difference(resumed[1], full[1]) < 1e-9,
             "the resumed sweep equals the uninterrupted one");
  }
  dealii::deallog << "resumed after level 1: level 1 not run again, both "
                     "levels equal the uninterrupted sweep's"
                  << std::endl;
}
