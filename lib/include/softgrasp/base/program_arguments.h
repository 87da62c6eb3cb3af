#ifndef softgrasp_base_program_arguments_h
#define softgrasp_base_program_arguments_h

#include <string>

namespace softgrasp
{
  /**
   * The command line of a study program:
   *   program [--print-parameters] [--help | -h] [file.prm]
   * parsed once. An unknown option ("-x") leaves an error message with
   * the fix; the last file name wins; none gives the default file.
   */
  struct ProgramArguments
  {
    bool        print_parameters = false;
    bool        help             = false;
    std::string parameter_file;
    std::string error; ///< "" if the command line is valid

    static ProgramArguments
    parse(int argc, char **argv, const std::string &default_file);

    /**
     * What a program does with help or a bad command line: prints the
     * usage line (with @p description and the default file) or the error
     * on rank 0 (@p root) and returns the exit code (0 or 1); -1 if the
     * program should run.
     */
    int handle(const std::string &program,
               const std::string &description,
               const bool         root) const;

  private:
    std::string default_file;
  };
} // namespace softgrasp

#endif
