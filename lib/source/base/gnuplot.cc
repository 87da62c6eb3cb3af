#include <cstdlib>
#include <softgrasp/base/gnuplot.h>

namespace softgrasp
{
  bool run_gnuplot(const std::string &directory,
                   const std::string &script,
                   std::ostream      &log)
  {
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    {
      log << "gnuplot not found: " << script
          << " not run (its data files are there; "
             "scripts/install-dependencies.sh installs gnuplot).\n";
      return false;
    }
    const std::string command =
        "cd '" + directory + "' && gnuplot '" + script + "' 2>/dev/null";
    if (std::system(command.c_str()) != 0)
    {
      log << "gnuplot failed on " << directory << "/" << script
          << " (its data files are there).\n";
      return false;
    }
    return true;
  }
} // namespace softgrasp
