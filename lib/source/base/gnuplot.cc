#include <cstdio>
#include <cstdlib>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/base/run_manifest.h>

namespace softgrasp
{
  bool run_gnuplot(const std::string              &directory,
                   const std::string              &script,
                   const std::vector<std::string> &pictures,
                   std::ostream                   &log)
  {
    RunManifest::note(directory + "/" + script);
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    {
      log << "gnuplot not found: " << script
          << " not run (its data files are there; "
             "scripts/install-dependencies.sh installs gnuplot).\n";
      return false;
    }
    for (const auto &picture : pictures)
      RunManifest::note(directory + "/" + picture);
    const std::string command =
        "cd '" + directory + "' && gnuplot '" + script + "' 2>/dev/null";
    bool ok = std::system(command.c_str()) == 0;
    if (!ok)
      log << "gnuplot failed on " << directory << "/" << script
          << " (its data files are there).\n";
    const std::string png_end = "IEND\xAE\x42\x60\x82";
    for (const auto &picture : pictures)
    {
      const std::string file    = directory + "/" + picture;
      const std::string partial = AtomicFile::temporary_name(file);
      const std::string problem =
          ok ? AtomicFile::check_written(partial, png_end, false) : "";
      if (ok && problem.empty())
        AtomicFile::commit(partial, file);
      else
      {
        if (ok)
          log << "The picture " << file << " is not complete (" << problem
              << "); the earlier one, if any, is kept.\n";
        std::remove(partial.c_str());
        ok = false;
      }
    }
    return ok;
  }
} // namespace softgrasp
