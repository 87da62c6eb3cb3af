#include <iostream>
#include <softgrasp/base/program_arguments.h>

namespace softgrasp
{
  ProgramArguments
  ProgramArguments::parse(int                               argc,
                          char                            **argv,
                          const std::string                &default_file,
                          const std::vector<ProgramOption> &accepted)
  {
    ProgramArguments arguments;
    arguments.default_file   = default_file;
    arguments.parameter_file = default_file;
    arguments.accepted       = accepted;
    std::string valid        = "--print-parameters, --dry-run, --help";
    for (const auto &option : accepted)
      valid += ", " + option.name +
               (option.value.empty() ? "" : " <" + option.value + ">");
    for (int i = 1; i < argc; ++i)
    {
      const std::string    arg = argv[i];
      const ProgramOption *own = nullptr;
      for (const auto &option : accepted)
        if (option.name == arg)
          own = &option;
      if (own != nullptr && arguments.options.count(arg) > 0)
        arguments.error = "the option '" + arg +
                          "' is given twice. Fix: give it once (run the "
                          "program once per value).";
      else if (arg == "--print-parameters")
        arguments.print_parameters = true;
      else if (arg == "--dry-run")
        arguments.dry_run = true;
      else if (arg == "--help" || arg == "-h")
        arguments.help = true;
      else if (own != nullptr && !own->value.empty())
      {
        if (i + 1 >= argc || argv[i + 1][0] == '-')
          arguments.error = "the option '" + arg +
                            "' needs a value. Fix: " + arg + " <" + own->value +
                            ">.";
        else
          arguments.options[arg] = argv[++i];
      }
      else if (own != nullptr)
        arguments.options[arg] = "";
      else if (!arg.empty() && arg[0] == '-')
        arguments.error = "unknown option '" + arg + "'. Fix: use " + valid +
                          " or the name of a .prm file.";
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
    {
      std::cout << "Usage: " << program << " [--print-parameters] [--dry-run]";
      for (const auto &option : accepted)
        std::cout << " [" << option.name
                  << (option.value.empty() ? "" : " <" + option.value + ">")
                  << "]";
      std::cout << " [file.prm]\n"
                << description << "\n"
                << "  --dry-run: read and check the file, then stop (nothing "
                   "is run or written)\n";
      for (const auto &option : accepted)
        std::cout << "  " << option.name
                  << (option.value.empty() ? "" : " <" + option.value + ">")
                  << ": " << option.help << "\n";
      std::cout << "Default parameter file: " << default_file << std::endl;
    }
    return 0;
  }
  void ProgramArguments::report_dry_run(const std::string &program,
                                        const std::string &file,
                                        const bool         root)
  {
    if (root)
      std::cout << "Dry run: '" << file << "' was read as a " << program
                << " file and every parameter checked; nothing was run or "
                   "written. What only the run can check (a mesh, the "
                   "contact set-up, the output directory) is checked when "
                   "it starts."
                << std::endl;
  }
} // namespace softgrasp
