#ifndef softgrasp_base_program_arguments_h
#define softgrasp_base_program_arguments_h

#include <map>
#include <string>
#include <vector>

namespace softgrasp
{
  /// An option a program accepts beyond the common ones: "--name" alone,
  /// or "--name value" if @p value names what follows (e.g. "k").
  struct ProgramOption
  {
    std::string name;  ///< with the dashes: "--level"
    std::string value; ///< "" for a flag, else the value's placeholder
    std::string help;  ///< one line for --help
  };

  /**
   * The command line of a study program:
   *   program [--print-parameters] [--dry-run] [--help | -h] [options]
   *           [file.prm]
   * parsed once. An unknown option ("-x") or an option without its value
   * leaves an error message with the fix; the last file name wins; none
   * gives the default file.
   */
  struct ProgramArguments
  {
    bool print_parameters = false;
    bool help             = false;
    /// --dry-run: read and check the file, then stop (report_dry_run()).
    bool        dry_run = false;
    std::string parameter_file;
    std::string error; ///< "" if the command line is valid
    /// The program's own options that were given, with their values ("" for
    /// a flag).
    std::map<std::string, std::string> options;

    static ProgramArguments
    parse(int                               argc,
          char                            **argv,
          const std::string                &default_file,
          const std::vector<ProgramOption> &accepted = {});

    /// Whether the option @p name ("--level") was given.
    bool has(const std::string &name) const
    {
      return options.count(name) > 0;
    }

    /**
     * What a program does with help or a bad command line: prints the
     * usage line (with @p description and the default file) or the error
     * on rank 0 (@p root) and returns the exit code (0 or 1); -1 if the
     * program should run.
     */
    int handle(const std::string &program,
               const std::string &description,
               const bool         root) const;

    /**
     * What a program prints on rank 0 (@p root) after a dry run of
     * @p program on @p file: the file was read and checked, nothing was
     * run or written.
     */
    static void report_dry_run(const std::string &program,
                               const std::string &file,
                               bool               root);

  private:
    std::string                default_file;
    std::vector<ProgramOption> accepted;
  };
} // namespace softgrasp

#endif
