#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/run_directory.h>
#include <softgrasp/base/run_manifest.h>
#include <stdexcept>

namespace softgrasp
{
  namespace RunManifest
  {
    namespace fs = std::filesystem;

    namespace
    {
      /// The names listed so far in one held directory's manifest.
      struct Ledger
      {
        std::string           file;
        std::set<std::string> names;
      };

      /// The directories the runs of this process hold, by canonical path.
      std::map<std::string, Ledger> &ledgers()
      {
        static std::map<std::string, Ledger> held;
        return held;
      }

      std::string key(const fs::path &directory)
      {
        std::error_code ignored;
        return fs::weakly_canonical(fs::absolute(directory), ignored)
            .lexically_normal()
            .string();
      }

      /// Whether @p name can be an entry the manifest lists.
      bool listable(const std::string &name)
      {
        return !name.empty() && name != "." && name != ".." &&
               name.find('/') == std::string::npos &&
               name.find('\0') == std::string::npos && name != manifest_name &&
               name != RunDirectory::lock_name;
      }

      const char *const header =
          "# softgrasp run manifest, format 1: the files and folders that a "
          "run wrote into this directory, one name per line.\n"
          "# 'Output/Existing results' of a later run moves or deletes only "
          "these; nothing else here is ever touched.\n";

      /// Append @p text to @p file; throws with the cause.
      void append(const std::string &file, const std::string &text)
      {
        std::FILE *out = std::fopen(file.c_str(), "ab");
        const bool written =
            out != nullptr &&
            std::fwrite(text.data(), 1, text.size(), out) == text.size() &&
            std::fflush(out) == 0;
        const int error = errno;
        if (out != nullptr && std::fclose(out) != 0)
          throw std::runtime_error("Cannot write the run manifest '" + file +
                                   "' (" + std::strerror(errno) + ").");
        if (!written)
          throw std::runtime_error(
              "Cannot write the run manifest '" + file + "' (" +
              std::strerror(error) +
              "). Fix: check that the output directory is writable and its "
              "disk is not full.");
      }
    } // namespace

    void check_regular(const std::string &directory)
    {
      const fs::path  file = fs::path(directory) / manifest_name;
      std::error_code ignored;
      const auto      status = fs::symlink_status(file, ignored);
      if (!fs::exists(status) || fs::is_regular_file(status))
        return;
      const std::string what = fs::is_symlink(status) ? "a symbolic link"
                               : fs::is_directory(status)
                                   ? "a directory"
                                   : "not a regular file";
      throw InputError(
          "The run manifest '" + file.string() + "' is " + what +
          ". A run lists what it wrote in a regular file of that name and "
          "reads or follows nothing else: another file could make it move "
          "or delete files it did not write. Fix: move '" +
          file.string() +
          "' out of the output directory, or choose another "
          "'Output/Directory'.");
    }

    std::vector<std::string> read(const std::string &directory)
    {
      check_regular(directory);
      std::vector<std::string> names;
      std::ifstream in(fs::path(directory) / manifest_name, std::ios::binary);
      if (!in)
        return names;
      const std::string     content((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
      std::set<std::string> seen;
      std::size_t           begin = 0;
      for (std::size_t end = content.find('\n'); end != std::string::npos;
           begin = end + 1, end = content.find('\n', begin))
      {
        const std::string name = content.substr(begin, end - begin);
        if (name.rfind('#', 0) != 0 && listable(name) &&
            seen.insert(name).second)
          names.push_back(name);
      }
      return names;
    }

    void open(const std::string &directory, const bool append_to_earlier)
    {
      check_regular(directory);
      Ledger ledger;
      ledger.file = (fs::path(directory) / manifest_name).string();
      if (append_to_earlier && fs::exists(ledger.file))
      {
        const auto listed = read(directory);
        ledger.names.insert(listed.begin(), listed.end());
      }
      else
      {
        std::remove(ledger.file.c_str());
        append(ledger.file, header);
      }
      ledgers()[key(directory)] = std::move(ledger);
    }

    void close(const std::string &directory)
    {
      ledgers().erase(key(directory));
    }

    void note(const std::string &path)
    {
      if (ledgers().empty())
        return;
      const fs::path    entry(path);
      const std::string name = entry.filename().string();
      const auto        held = ledgers().find(
          key(entry.has_parent_path() ? entry.parent_path() : fs::path(".")));
      if (held == ledgers().end() || !listable(name) ||
          held->second.names.count(name) != 0)
        return;
      append(held->second.file, name + "\n");
      held->second.names.insert(name);
    }
  } // namespace RunManifest
} // namespace softgrasp
