#ifndef softgrasp_base_run_manifest_h
#define softgrasp_base_run_manifest_h

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The ledger of what a run wrote into its output directory: a text file
   * (manifest_name) in that directory listing, one per line, the names of
   * the files and folders the run created there, and, once each is
   * complete, its proof: a line "+ <size> <checksum> <name>" with its size
   * in bytes and 64-bit FNV-1a checksum (a folder: the total size and the
   * checksum of its files' relative paths and sizes; entry_fingerprint).
   * A later run moves or deletes only entries an earlier run's manifest
   * lists and whose proof matches them (RunDirectory), and never the
   * inputs of the running program (protect_input), so that no input, note
   * or folder of a user is ever touched, whatever the manifest says.
   *
   * While a RunDirectory holds a directory (open() to close()), every file
   * that AtomicFile commits into it is listed before it gets its name and
   * proven once it has it; writers that create folders or files by other
   * means (checkpoints) call note() first and record() when done: a run
   * killed at any moment leaves no entry of its own unlisted. An entry that
   * exists but is not this run's (a user's file of the same name, or an
   * earlier run's that cannot be proven) is moved aside into
   * "moved-aside-<n>/" before the run writes over it, and the log says so.
   * Only direct children of the directory are listed; what lies in a
   * listed folder goes with it. Each process keeps the ledgers of the
   * directories its runs hold; calls on ranks that hold none do nothing.
   */
  namespace RunManifest
  {
    /// The manifest's file name inside an output directory.
    constexpr const char *manifest_name = "softgrasp-run-files.txt";

    /// What an earlier run's manifest lists.
    struct Listing
    {
      /// the names listed, in order, without repetitions
      std::vector<std::string> names;
      /// name -> "<size> <checksum>" of the entry as the run completed it
      /// last (absent for entries listed before their proof was written)
      std::map<std::string, std::string> proofs;
    };

    /**
     * What the manifest in @p directory lists; empty if there is none. An
     * unfinished last line (a run killed while writing it) is ignored.
     * Throws an InputError naming the manifest and the fix if it is not a
     * regular file (check_regular), was not written by softgrasp (foreign)
     * or has a line that is neither a name of an entry of the directory nor
     * a proof (damaged: a path with '/', '.', '..', a malformed proof), so
     * that an edited manifest never points outside the directory.
     */
    Listing read(const std::string &directory);

    /**
     * Throws an InputError naming the manifest of @p directory and the fix
     * if it exists but is not a regular file (a directory, a symbolic link
     * to a list elsewhere, a device): a run never reads or follows it.
     */
    void check_regular(const std::string &directory);

    /**
     * Whether the entry @p name of @p directory is what @p listing's proof
     * of it records (same size and checksum); false without a proof.
     */
    bool proven(const std::string &directory,
                const Listing     &listing,
                const std::string &name);

    /**
     * Start recording into @p directory's manifest: a new manifest (an
     * earlier one is replaced), or, if @p append, the existing one
     * continued (a resumed run: its listed entries that match their proofs
     * are this run's). Moves of entries that are not the run's are reported
     * on @p log.
     */
    void open(const std::string &directory, bool append, std::ostream &log);

    /// Stop recording into @p directory's manifest (the file stays).
    void close(const std::string &directory);

    /**
     * List @p path in the manifest of the directory it lies in, if a run
     * of this process holds that directory; otherwise nothing happens.
     * Call before the entry is created. An existing entry of that name that
     * is not this run's is first moved aside (and said so); the program's
     * own input is never written over (an InputError). Throws if the
     * manifest cannot be written (the entry is then not created either).
     */
    void note(const std::string &path);

    /**
     * Write the proof of @p path (its size and checksum, entry_fingerprint)
     * into the manifest of the directory it lies in, as note() does; call
     * when the entry is complete, and again whenever it changes.
     */
    void record(const std::string &path);

    /**
     * The names of the entries of @p directory that this process's run
     * listed (in order), if it holds @p directory.
     */
    std::vector<std::string> written(const std::string &directory);

    /**
     * Mark @p path as an input of the running program (its parameter file,
     * a mesh, a scene): no run of this process moves, deletes or writes
     * over it, whatever a manifest says.
     */
    void protect_input(const std::string &path);

    /// Whether @p path is an input marked by protect_input().
    bool is_input(const std::string &path);
  } // namespace RunManifest
} // namespace softgrasp

#endif
