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
   * a directory never mixes two runs. The results of a run are exactly what
   * its manifest lists (RunManifest): a run records every file and folder
   * it creates, and a later run moves or deletes only those, never a
   * user's input, notes or folders, whatever their names. All checks run
   * on rank 0; an error reaches every rank as the same InputError, so no
   * rank waits forever. The destructor removes the lock and ends the
   * recording.
   */
  class RunDirectory
  {
  public:
    RunDirectory(MPI_Comm           comm,
                 const std::string &directory,
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
    /// the directory whose manifest records this run (rank 0)
    std::string manifest_directory;
  };
} // namespace softgrasp

#endif
