#include <iostream>
#include <softgrasp/base/program_arguments.h>

namespace softgrasp
{
  ProgramArguments ProgramArguments::parse(int                argc,
                                           char             **argv,
                                           const std::string &default_file)
  {
    ProgramArguments arguments;
    arguments.default_file   = default_file;
    arguments.parameter_file = default_file;
    for (int i = 1; i < argc; ++i)
    {
      const std::string arg = argv[i];
      if (arg == "--print-parameters")
        arguments.print_parameters = true;
      else if (arg == "--help" || arg == "-h")
        arguments.help = true;
      else if (!arg.empty() && arg[0] == '-')
        arguments.error = "unknown option '" + arg +
                          "'. Fix: use --print-parameters, --help or the "
                          "name of a .prm file.";
      else
        arguments.parameter_file = arg;
    }
    return arguments;
  }

  int ProgramArguments::handle(const std::string &program,
                               const std::string &description,
                               const bool         root) const
  {
    if (!error.empty())
    {
      if (root)
        std::cerr << "Error: " << error << std::endl;
      return 1;
    }
    if (!help)
      return -1;
    if (root)
      std::cout << "Usage: " << program << " [--print-parameters] [file.prm]\n"
                << description << "\nDefault parameter file: " << default_file
                << std::endl;
    return 0;
  }
} // namespace softgrasp
