#ifndef softgrasp_base_atomic_file_h
#define softgrasp_base_atomic_file_h

#include <sstream>
#include <string>

namespace softgrasp
{
  /**
   * Output files are written whole or not at all: the content goes to a
   * temporary file next to the target, which is then renamed over it
   * (rename is atomic on POSIX file systems). A reader, or a run killed
   * mid-write, never sees a half-written file. A file written or committed
   * into an output directory that a run holds is listed in that run's
   * manifest first (RunManifest).
   */
  namespace AtomicFile
  {
    /// The temporary name used for @p filename while it is being written.
    std::string temporary_name(const std::string &filename);

    /// Write @p content to @p filename atomically; throws on I/O failure.
    void write(const std::string &filename, const std::string &content);

    /// Rename @p from to @p to (atomic replace); throws on failure.
    void commit(const std::string &from, const std::string &to);

    /// A message for a failed write of @p filename with @p cause, naming
    /// the directory and the fix.
    std::string write_error(const std::string &filename,
                            const std::string &cause);

    /**
     * Why the file @p filename, written by another library (MPI-IO, HDF5,
     * gnuplot), is not complete, or "" if it is: it must end with
     * @p ending and, if @p text, contain no zero byte.
     */
    std::string check_written(const std::string &filename,
                              const std::string &ending,
                              bool               text);

    /**
     * A text output file built in memory and written whole by commit()
     * (write() above: listed in the run's manifest, atomic, with its
     * proof): the writer of a CSV file or a gnuplot script uses it as it
     * would an std::ofstream, then commits it.
     */
    class TextFile : public std::ostringstream
    {
    public:
      explicit TextFile(std::string filename)
          : filename(std::move(filename))
      {
      }

      /// Write the text so far to the file; throws on I/O failure.
      void commit() const
      {
        AtomicFile::write(filename, str());
      }

    private:
      std::string filename;
    };
  } // namespace AtomicFile
} // namespace softgrasp

#endif
