#ifndef softgrasp_base_run_directory_h
#define softgrasp_base_run_directory_h

#include <deal.II/base/mpi.h>
#include <ostream>
#include <string>

namespace softgrasp
{
  /// What a new run does with an earlier run's results in its directory.
  enum class ExistingResults
  {
    move_aside, ///< into "<directory>/previous-run-<n>"
    replace,    ///< delete them
    refuse      ///< stop with an error
  };

  /**
   * The output directory of one run, held for the run's lifetime: created
   * if missing, checked to be a writable directory, locked against a second
   * run (a lock file with the owner's host and process id; a stale lock of
   * a process that no longer exists is taken over), and, for a new run,
   * cleared of an earlier run's results as ExistingResults says, so that
   * a directory never mixes two runs. The results of a run are the files
   * and folders whose names start with its base name, and its checkpoints.
   * All checks run on rank 0; an error reaches every rank as the same
   * InputError, so no rank waits forever. The lock is removed by the
   * destructor.
   */
  class RunDirectory
  {
  public:
    RunDirectory(MPI_Comm           comm,
                 const std::string &directory,
                 const std::string &base_name,
                 ExistingResults    existing,
                 bool               resume,
                 std::ostream      &log);
    ~RunDirectory();
    RunDirectory(const RunDirectory &)            = delete;
    RunDirectory &operator=(const RunDirectory &) = delete;

    /// The name of the lock file inside a run directory.
    static constexpr const char *lock_name = ".softgrasp.lock";

  private:
    std::string lock_file; ///< empty on ranks other than 0
  };
} // namespace softgrasp

#endif
