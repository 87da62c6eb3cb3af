#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <signal.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/run_directory.h>
#include <softgrasp/base/run_manifest.h>
#include <unistd.h>
#include <vector>

namespace softgrasp
{
  namespace fs = std::filesystem;

  namespace
  {
    std::string host_name()
    {
      char name[256] = {};
      gethostname(name, sizeof(name) - 1);
      return name;
    }

    /// Whether process @p pid of this host is running (a zombie, a killed
    /// process not yet reaped by its parent, is not).
    bool running(const long pid)
    {
      if (pid <= 0 || (kill(static_cast<pid_t>(pid), 0) != 0 && errno != EPERM))
        return false;
      std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
      std::string   line;
      if (!std::getline(stat, line))
        return true; // no /proc: trust kill()
      const auto        close = line.rfind(')');
      const std::string state =
          close == std::string::npos ? "" : line.substr(close + 2, 1);
      return state != "Z" && state != "X";
    }

    /// Take the lock of @p directory for this process; "" or an error.
    std::string take_lock(const std::string &directory, const std::string &file)
    {
      for (int attempt = 0; attempt < 2; ++attempt)
      {
        const int fd = open(file.c_str(), O_CREAT | O_EXCL | O_WRONLY, 0644);
        if (fd >= 0)
        {
          const std::string owner =
              host_name() + " " + std::to_string(getpid()) + "\n";
          const bool written = write(fd, owner.data(), owner.size()) ==
                               static_cast<ssize_t>(owner.size());
          close(fd);
          if (written)
            return "";
          unlink(file.c_str());
          return "Cannot write into the output directory '" + directory +
                 "' (is the disk full?). Fix: free disk space or choose "
                 "another 'Output/Directory'.";
        }
        if (errno != EEXIST)
          return "The output directory '" + directory + "' is not writable (" +
                 std::strerror(errno) +
                 "). Fix: change its permissions or choose another "
                 "'Output/Directory'.";
        std::ifstream in(file);
        std::string   host;
        long          pid = 0;
        if (!(in >> host >> pid) || pid <= 0)
          return "The lock file '" + file + "' of the output directory '" +
                 directory +
                 "' is damaged: it names no host and process (a run killed "
                 "while it took the lock, or an edited file), so this run "
                 "cannot tell whether another run is writing there. Fix: if "
                 "no run is writing into '" +
                 directory + "', delete '" + file + "'.";
        const bool alive = running(pid);
        if (host == host_name() && (!alive || pid == getpid()))
        {
          // left by a run that was killed, or by an earlier solver of
          // this very process
          unlink(file.c_str());
          continue;
        }
        return "Another run (process " + std::to_string(pid) + " on host '" +
               host + "') is writing into the output directory '" + directory +
               "'. Fix: wait for it to finish or choose another "
               "'Output/Directory'. If no such run exists any more, delete '" +
               file + "'.";
      }
      return "Cannot lock the output directory '" + directory + "'.";
    }

    /**
     * The entries of @p directory that an earlier run wrote, as its
     * manifest lists them (and the temporary files of those it was killed
     * writing); never anything else.
     */
    std::vector<fs::path> earlier_results(const std::string &directory)
    {
      std::vector<fs::path> found;
      std::error_code       ignored;
      for (const auto &name : RunManifest::read(directory))
        for (const auto &candidate : {name, name + ".partial"})
        {
          const fs::path path = fs::path(directory) / candidate;
          if (fs::exists(fs::symlink_status(path, ignored)))
            found.push_back(path);
        }
      return found;
    }

    /// Apply @p policy to an earlier run's results; "" or an error.
    std::string clear_earlier_results(const std::string    &directory,
                                      const ExistingResults policy,
                                      std::ostream         &log)
    {
      const auto     found = earlier_results(directory);
      const fs::path manifest =
          fs::path(directory) / RunManifest::manifest_name;
      if (found.empty())
        return "";
      if (policy == ExistingResults::refuse)
        return "The output directory '" + directory +
               "' holds the results of an earlier run (e.g. '" +
               found.front().filename().string() + "'; its '" +
               RunManifest::manifest_name +
               "' lists them all). Fix: set 'Output/Existing results' to "
               "'move aside' (kept in a subfolder) or 'replace' (deleted), "
               "choose another 'Output/Directory', or set 'Checkpoint/Resume "
               "= true' to continue that run.";
      if (policy == ExistingResults::replace)
      {
        for (const auto &path : found)
          fs::remove_all(path);
        fs::remove(manifest);
        log << "Deleted " << found.size() << " file(s) and folder(s) of an "
            << "earlier run in '" << directory
            << "' ('Output/Existing results = replace'; only what its "
            << RunManifest::manifest_name << " listed, nothing else)."
            << std::endl;
        return "";
      }
      unsigned int n = 1;
      while (fs::exists(fs::path(directory) /
                        ("previous-run-" + std::to_string(n))))
        ++n;
      const fs::path aside =
          fs::path(directory) / ("previous-run-" + std::to_string(n));
      fs::create_directory(aside);
      for (const auto &path : found)
        fs::rename(path, aside / path.filename());
      fs::rename(manifest, aside / manifest.filename());
      log << "Moved " << found.size() << " file(s) and folder(s) of an "
          << "earlier run in '" << directory << "' to '" << aside.string()
          << "' (only what its " << RunManifest::manifest_name
          << " listed; delete the folder when no longer needed; "
             "'Output/Existing results' chooses what happens to earlier "
             "results)."
          << std::endl;
      return "";
    }
  } // namespace

  RunDirectory::RunDirectory(MPI_Comm              comm,
                             const std::string    &directory,
                             const ExistingResults existing,
                             const bool            resume,
                             std::ostream         &log)
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    {
      try
      {
        std::error_code code;
        if (fs::exists(directory) && !fs::is_directory(directory))
          error = "'Output/Directory' = '" + directory +
                  "' is a file, not a directory. Fix: choose another "
                  "'Output/Directory' or remove the file.";
        else if (!fs::create_directories(directory, code) && code)
          error = "Cannot create the output directory '" + directory + "' (" +
                  code.message() +
                  "). Fix: choose an 'Output/Directory' in a writable "
                  "place.";
        else
          error = take_lock(directory, directory + "/" + lock_name);
        if (error.empty())
        {
          lock_file = directory + "/" + lock_name;
          if (!resume)
            error = clear_earlier_results(directory, existing, log);
          if (error.empty())
          {
            RunManifest::open(directory, resume);
            manifest_directory = directory;
          }
        }
      }
      catch (const InputError &e)
      {
        error = e.what();
      }
      catch (const std::exception &e)
      {
        error = "Cannot prepare the output directory '" + directory +
                "': " + e.what() +
                " Fix: check its permissions and the free disk space.";
      }
    }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
    {
      if (!lock_file.empty())
        unlink(lock_file.c_str());
      throw InputError(error);
    }
  }

  RunDirectory::~RunDirectory()
  {
    if (!manifest_directory.empty())
      RunManifest::close(manifest_directory);
    if (!lock_file.empty())
      unlink(lock_file.c_str());
  }
} // namespace softgrasp
