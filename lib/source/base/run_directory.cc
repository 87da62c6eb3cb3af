#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <set>
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

    /// An earlier run's entries in a directory, by what may be done to them.
    struct EarlierEntries
    {
      std::vector<fs::path>    proven;   ///< listed and matching their proof
      std::vector<std::string> unproven; ///< listed, but changed or unproven
      std::vector<std::string> inputs;   ///< listed, but inputs of this run
    };

    /**
     * The entries of @p directory that an earlier run's manifest lists,
     * sorted by whether they can be proven that run's (and the temporary
     * files of those it was killed writing, "<name>.partial", which only a
     * run writes); an input of this run never counts as proven.
     */
    EarlierEntries earlier_results(const std::string &directory)
    {
      EarlierEntries  found;
      std::error_code ignored;
      const auto      listing = RunManifest::read(directory);
      for (const auto &name : listing.names)
      {
        const fs::path path = fs::path(directory) / name;
        if (fs::exists(fs::symlink_status(path, ignored)))
        {
          if (RunManifest::is_input(path.string()))
            found.inputs.push_back(name);
          else if (RunManifest::proven(directory, listing, name))
            found.proven.push_back(path);
          else
            found.unproven.push_back(name);
        }
        const fs::path partial = path.string() + ".partial";
        if (fs::is_regular_file(fs::symlink_status(partial, ignored)))
          found.proven.push_back(partial);
      }
      return found;
    }

    /// Up to 8 of @p names, quoted, and how many more.
    std::string some_of(const std::vector<std::string> &names)
    {
      std::string text;
      for (std::size_t i = 0; i < names.size() && i < 8; ++i)
        text += (i == 0 ? "'" : ", '") + names[i] + "'";
      if (names.size() > 8)
        text += " and " + std::to_string(names.size() - 8) + " more";
      return text;
    }

    /// Say which listed entries stay where they are, and why.
    void report_kept(const std::string    &directory,
                     const EarlierEntries &found,
                     std::ostream         &log)
    {
      if (!found.unproven.empty())
        log << "Kept " << found.unproven.size()
            << (found.unproven.size() == 1 ? " entry" : " entries") << " in '"
            << directory << "' that its " << RunManifest::manifest_name
            << " lists but that do not match the proof it records (changed "
               "since, listed by hand, or written before proofs existed): "
            << some_of(found.unproven)
            << ". They are not moved or deleted; one that this run writes is "
               "moved aside first. Delete them by hand if they are old "
               "results."
            << std::endl;
      if (!found.inputs.empty())
        log << "Kept " << some_of(found.inputs) << " in '" << directory
            << "': listed in its " << RunManifest::manifest_name
            << ", but an input of this run." << std::endl;
    }

    /// Apply @p policy to an earlier run's results; "" or an error.
    std::string clear_earlier_results(const std::string    &directory,
                                      const ExistingResults policy,
                                      std::ostream         &log)
    {
      const auto     found = earlier_results(directory);
      const fs::path manifest =
          fs::path(directory) / RunManifest::manifest_name;
      if (found.proven.empty())
      {
        report_kept(directory, found, log);
        return "";
      }
      if (policy == ExistingResults::refuse)
        return "The output directory '" + directory +
               "' holds the results of an earlier run (e.g. '" +
               found.proven.front().filename().string() + "'; its '" +
               RunManifest::manifest_name +
               "' lists them all). Fix: set 'Output/Existing results' to "
               "'move aside' (kept in a subfolder) or 'replace' (deleted), "
               "choose another 'Output/Directory', or set 'Checkpoint/Resume "
               "= true' to continue that run.";
      report_kept(directory, found, log);
      if (policy == ExistingResults::replace)
      {
        for (const auto &path : found.proven)
          fs::remove_all(path);
        fs::remove(manifest);
        log << "Deleted " << found.proven.size()
            << " file(s) and folder(s) of an earlier run in '" << directory
            << "' ('Output/Existing results = replace'; only what its "
            << RunManifest::manifest_name
            << " listed with a matching size and checksum, nothing else)."
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
      for (const auto &path : found.proven)
        fs::rename(path, aside / path.filename());
      fs::rename(manifest, aside / manifest.filename());
      log << "Moved " << found.proven.size() << " file(s) and folder(s) of an "
          << "earlier run in '" << directory << "' to '" << aside.string()
          << "' (only what its " << RunManifest::manifest_name
          << " listed with a matching size and checksum; delete the folder "
             "when no longer needed; 'Output/Existing results' chooses what "
             "happens to earlier results)."
          << std::endl;
      return "";
    }
  } // namespace

  RunDirectory::RunDirectory(MPI_Comm              comm,
                             const std::string    &directory,
                             const ExistingResults existing,
                             const bool            resume,
                             const std::string    &base_name,
                             std::ostream         &log)
      : base_name(base_name)
      , log(&log)
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
            RunManifest::open(directory, resume, log);
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

  void RunDirectory::report_strangers() const
  {
    const auto listed = RunManifest::written(manifest_directory);
    const std::set<std::string> own(listed.begin(), listed.end());
    std::vector<std::string>    strangers;
    for (const auto &entry : fs::directory_iterator(manifest_directory))
    {
      const std::string name = entry.path().filename().string();
      if ((name.rfind(base_name + "_", 0) == 0 ||
           name.rfind(base_name + ".", 0) == 0) &&
          own.count(name) == 0 && !RunManifest::is_input(entry.path()))
        strangers.push_back(name);
    }
    std::sort(strangers.begin(), strangers.end());
    if (!strangers.empty())
      *log << "Warning: '" << manifest_directory << "' also holds "
           << strangers.size()
           << " entries named like this run's output but not written by it "
              "(kept as they were, and not in this run's PVD): "
           << some_of(strangers)
           << ". Fix: move or delete them by hand if they are old results."
           << std::endl;
  }

  RunDirectory::~RunDirectory()
  {
    if (!manifest_directory.empty())
    {
      try
      {
        if (!base_name.empty())
          report_strangers();
      }
      catch (const std::exception &)
      {
        // a listing that fails changes nothing: the run is over
      }
      RunManifest::close(manifest_directory);
    }
    if (!lock_file.empty())
      unlink(lock_file.c_str());
  }
} // namespace softgrasp
