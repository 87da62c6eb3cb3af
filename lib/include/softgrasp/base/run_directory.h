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
   * its manifest lists with a matching proof (RunManifest): a run records
   * every file and folder it creates, with its size and checksum once
   * complete, and a later run moves or deletes only those that still
   * match, never the running program's inputs or a user's notes or
   * folders, whatever their names or the manifest says; listed entries
   * that do not match are kept and named. All checks run
   * on rank 0; an error reaches every rank as the same InputError, so no
   * rank waits forever. The destructor names the entries that look like
   * the run's output (they begin with @p base_name) but that it did not
   * write, removes the lock and ends the recording.
   */
  class RunDirectory
  {
  public:
    RunDirectory(MPI_Comm           comm,
                 const std::string &directory,
                 ExistingResults    existing,
                 bool               resume,
                 const std::string &base_name,
                 std::ostream      &log);
    ~RunDirectory();
    RunDirectory(const RunDirectory &)            = delete;
    RunDirectory &operator=(const RunDirectory &) = delete;

    /// The name of the lock file inside a run directory.
    static constexpr const char *lock_name = ".softgrasp.lock";

  private:
    /**
     * Warn about entries of the directory named like the run's output
     * ("<base name>_*", "<base name>.*") that the run did not write (an
     * earlier run's it could not prove, a user's): they stay, untouched.
     */
    void report_strangers() const;

    std::string   base_name; ///< prefix of the run's output names, or ""
    std::ostream *log;
    std::string   lock_file; ///< empty on ranks other than 0
    /// the directory whose manifest records this run (rank 0)
    std::string manifest_directory;
  };
} // namespace softgrasp

#endif
