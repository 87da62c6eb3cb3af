#ifndef softgrasp_base_run_manifest_h
#define softgrasp_base_run_manifest_h

#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The ledger of what a run wrote into its output directory: a text file
   * (manifest_name) in that directory listing, one per line, the names of
   * the files and folders the run created there. A later run moves or
   * deletes only what an earlier run's manifest lists (RunDirectory), so
   * that no input, note or folder of a user is ever touched.
   *
   * While a RunDirectory holds a directory (open() to close()), every file
   * that AtomicFile commits into it is listed before it gets its name, and
   * writers that create folders or files by other means (checkpoints)
   * call note() first: a run killed at any moment leaves no entry of its
   * own unlisted. Only direct children of the directory are listed; what
   * lies in a listed folder goes with it. Each process keeps the ledgers
   * of the directories its runs hold; calls on ranks that hold none do
   * nothing.
   */
  namespace RunManifest
  {
    /// The manifest's file name inside an output directory.
    constexpr const char *manifest_name = "softgrasp-run-files.txt";

    /**
     * The names an earlier run's manifest in @p directory lists, in order,
     * without repetitions; empty if there is none. Lines that cannot be
     * names of entries of the directory (empty, "." or "..", containing
     * '/', the manifest's or the lock's own name) and an unfinished last
     * line are ignored, so an edited or damaged manifest never points
     * outside the directory.
     */
    std::vector<std::string> read(const std::string &directory);

    /**
     * Throws an InputError naming the manifest of @p directory and the fix
     * if it exists but is not a regular file (a directory, a symbolic link
     * to a list elsewhere, a device): a run never reads or follows it.
     */
    void check_regular(const std::string &directory);

    /**
     * Start recording into @p directory's manifest: a new manifest (an
     * earlier one is replaced), or, if @p append, the existing one
     * continued (a resumed run).
     */
    void open(const std::string &directory, bool append);

    /// Stop recording into @p directory's manifest (the file stays).
    void close(const std::string &directory);

    /**
     * List @p path in the manifest of the directory it lies in, if a run
     * of this process holds that directory; otherwise nothing happens.
     * Call before the entry is created. Throws if the manifest cannot be
     * written (the entry is then not created either).
     */
    void note(const std::string &path);
  } // namespace RunManifest
} // namespace softgrasp

#endif
