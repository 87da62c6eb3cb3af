// Recovering a grasp-and-pull sweep by the steps doc/studies.md gives, on
// the coarse arm of grasp_pull_fe (2 levels, a 5 mm pull):
//  - a changed 'Checkpoint/Interval' keeps every record (it cannot change a
//    result): the run finds both levels finished;
//  - level 1's record (level.h5) deleted and a smaller 'Time/Time step'
//    (the doc's retry of a level): level 1 is pulled again from its closed
//    state (the same grip force, not closed again), level 2's record is
//    untouched;
//  - level 1's directory deleted (as the message on a damaged record
//    advises): level 1 is closed again from the start, not from the
//    closing's latest state (which lies beyond it), and equals the first
//    sweep's level 1; level 2's record is untouched;
//  - level 2's directory deleted: closed again from level 1's closed state;
//    it equals the first sweep's level 2;
//  - level 1's closing.h5 deleted (its level.h5 kept): level 1 is computed
//    again and equals the first sweep's;
//  - both level directories and closing_progress.txt deleted (a sweep
//    killed while closing level 2, as far as the files tell): the closing's
//    latest checkpoint lies beyond both, so both are closed again from the
//    start and equal the first sweep's;
//  - the closed states of levels 1 and 2 swapped, both still to pull: each
//    is refused against its record's checksum, both are closed again and
//    pulled from their own states, equal to the first sweep's.
#include "../tests.h"
#include "grasp_helpers.h"

#include <filesystem>
#include <softgrasp/mujoco/grasp_pull_sweep.h>

using namespace softgrasp;
using softgrasp_tests::CoarseSweep;

int
main(int argc, char **argv)
{
  namespace fs = std::filesystem;
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  const std::string directory = "output-recovery";
  fs::remove_all(directory);
  std::vector<FeGripLevel> full;
  {
    CoarseSweep s(directory);
    s.sweep->run_fe(s.log);
    full = s.sweep->fe_levels();
    SG_CHECK(full.size() == 2 && full[0].pulled && full[1].pulled &&
                 full[0].time < full[1].time,
             "two levels of distinct states, pulled");
  }
  const auto level_record = [&](const unsigned int k)
  { return directory + "/level_0" + std::to_string(k) + "/level.h5"; };

  {
    CoarseSweep s(directory,
                  [](dealii::ParameterHandler &prm) {
                    softgrasp_tests::set(prm, {"Checkpoint"}, "Interval", "7");
                  });
    s.sweep->run_fe(s.log);
    SG_CHECK(s.log.str().find("Level 1: finished") != std::string::npos &&
                 s.log.str().find("Level 2: finished") != std::string::npos,
             "a changed checkpoint interval keeps the records");
  }
  dealii::deallog << "Checkpoint/Interval changed: both records kept"
                  << std::endl;

  {
    const auto before  = fs::last_write_time(level_record(2));
    const auto closing = fs::last_write_time(directory + "/fe_closing");
    fs::remove(level_record(1));
    CoarseSweep s(directory,
                  [](dealii::ParameterHandler &prm) {
                    softgrasp_tests::set(prm, {"Time"}, "Time step", "0.01");
                  });
    s.sweep->run_fe(s.log);
    const auto &levels = s.sweep->fe_levels();
    SG_CHECK(levels.size() == 2 && levels[0].pulled &&
                 levels[0].reached_force == full[0].reached_force &&
                 levels[0].time == full[0].time,
             "level 1 pulled again from its closed state");
    SG_CHECK(fs::last_write_time(directory + "/fe_closing") == closing,
             "not closed again");
    SG_CHECK(fs::last_write_time(level_record(2)) == before,
             "level 2's record untouched");
  }
  dealii::deallog << "level.h5 of level 1 deleted, smaller time step: level 1 "
                     "pulled again from its closed state, level 2 untouched"
                  << std::endl;

  for (const unsigned int k : {1u, 2u})
  {
    const unsigned int other  = 3 - k;
    const auto         before = fs::last_write_time(level_record(other));
    fs::remove_all(directory + "/level_0" + std::to_string(k));
    CoarseSweep s(directory);
    s.sweep->run_fe(s.log);
    const auto &levels = s.sweep->fe_levels();
    SG_CHECK(levels.size() == 2, "two levels");
    SG_CHECK(softgrasp_tests::level_difference(levels[k - 1], full[k - 1]) <
                 1e-9,
             "level " + std::to_string(k) +
                 " closed again from below equals the first sweep's");
    SG_CHECK(fs::last_write_time(level_record(other)) == before,
             "the other level's record untouched");
  }
  dealii::deallog << "a level's directory deleted: closed again from the "
                     "state below it (level 1 from the start, level 2 from "
                     "level 1's), equal to the first sweep's, the other "
                     "level untouched"
                  << std::endl;

  const auto level_dir = [&](const unsigned int k)
  { return directory + "/level_0" + std::to_string(k); };
  // runs the sweep after @p damage; both levels equal the first sweep's
  const auto recovers = [&](const std::string &what, auto damage)
  {
    damage();
    CoarseSweep s(directory);
    s.sweep->run_fe(s.log);
    const auto &levels = s.sweep->fe_levels();
    SG_CHECK(levels.size() == 2 && levels[0].pulled && levels[1].pulled,
             what + ": both levels pulled");
    for (const unsigned int k : {1u, 2u})
      SG_CHECK(softgrasp_tests::level_difference(levels[k - 1], full[k - 1]) <
                   1e-9,
               what + ": level " + std::to_string(k) +
                   " equals the first sweep's");
    return s.log.str();
  };
  recovers("closing.h5 of level 1 deleted",
           [&] { fs::remove(level_dir(1) + "/closing.h5"); });
  dealii::deallog << "closing.h5 of level 1 deleted: level 1 computed again, "
                     "equal to the first sweep's"
                  << std::endl;
  recovers("both levels and closing_progress.txt deleted",
           [&]
           {
             fs::remove_all(level_dir(1));
             fs::remove_all(level_dir(2));
             fs::remove(directory + "/closing_progress.txt");
           });
  dealii::deallog << "both levels and the closing progress deleted: closed "
                     "again from the start, equal to the first sweep's"
                  << std::endl;
  const std::string log = recovers(
      "closed states swapped",
      [&]
      {
        for (const unsigned int k : {1u, 2u})
          fs::remove(level_record(k));
        fs::rename(level_dir(1) + "/closed", directory + "/closed_1");
        fs::rename(level_dir(2) + "/closed", level_dir(1) + "/closed");
        fs::rename(directory + "/closed_1", level_dir(2) + "/closed");
      });
  SG_CHECK(log.find("Level 1: its closed state '" + level_dir(1) +
                    "/closed' is not the one its record") != std::string::npos,
           "the swapped state is named");
  dealii::deallog << "closed states of levels 1 and 2 swapped: each refused "
                     "against its record, both closed again, equal to the "
                     "first sweep's"
                  << std::endl;
}
