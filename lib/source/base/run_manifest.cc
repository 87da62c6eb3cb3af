#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <softgrasp/base/file_checksum.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/run_directory.h>
#include <softgrasp/base/run_manifest.h>
#include <sstream>
#include <stdexcept>

namespace softgrasp
{
  namespace RunManifest
  {
    namespace fs = std::filesystem;

    namespace
    {
      /// The state of one held directory's manifest.
      struct Ledger
      {
        std::string           directory;
        std::string           file;
        Listing               listing;   ///< what the manifest says, as written
        std::set<std::string> owned;     ///< entries this run may write over
        std::size_t           lines = 0; ///< lines in the file (for compaction)
        std::ostream         *log   = nullptr;
        std::string aside; ///< folder for entries not the run's, or ""
      };

      /// The directories the runs of this process hold, by canonical path.
      std::map<std::string, Ledger> &ledgers()
      {
        static std::map<std::string, Ledger> held;
        return held;
      }

      /// The inputs of the running program, by canonical path.
      std::set<std::string> &inputs()
      {
        static std::set<std::string> protect;
        return protect;
      }

      std::string key(const fs::path &path)
      {
        std::error_code ignored;
        return fs::weakly_canonical(fs::absolute(path), ignored)
            .lexically_normal()
            .string();
      }

      /// Whether @p name can be an entry the manifest lists.
      bool listable(const std::string &name)
      {
        return !name.empty() && name != "." && name != ".." &&
               name.find('/') == std::string::npos &&
               name.find('\0') == std::string::npos &&
               name.find('\n') == std::string::npos &&
               name.rfind(manifest_name, 0) != 0 &&
               name != RunDirectory::lock_name;
      }

      const char *const signature = "# softgrasp run manifest";
      const char *const header =
          "# softgrasp run manifest, format 2: the files and folders that a "
          "run wrote into this directory, one name per line, and once each "
          "is complete '+ <size> <FNV-1a checksum> <name>'.\n"
          "# 'Output/Existing results' of a later run moves or deletes only "
          "these, and only if they match; nothing else here is ever "
          "touched.\n";

      /// "<size> <checksum>" if @p text is one, else "".
      std::string parse_proof(std::istringstream &in)
      {
        std::string size, sum;
        if (!(in >> size >> sum) ||
            size.find_first_not_of("0123456789") != std::string::npos ||
            sum.size() != 16 ||
            sum.find_first_not_of("0123456789abcdef") != std::string::npos)
          return "";
        return size + " " + sum;
      }

      /// Add @p line (line @p number) of the manifest @p file to @p listing.
      void add_line(Listing           &listing,
                    const std::string &line,
                    const std::size_t  number,
                    const std::string &file)
      {
        std::string name = line, proof;
        if (line.rfind("+ ", 0) == 0)
        {
          std::istringstream in(line.substr(2));
          proof           = parse_proof(in);
          const auto rest = in.tellg();
          name = proof.empty() || rest < 0 ? "" : line.substr(2 + rest + 1);
        }
        if (!listable(name))
          throw InputError(
              "The run manifest '" + file + "' is damaged: its line " +
              std::to_string(number) + " ('" + line.substr(0, 80) +
              "') is neither the name of an entry of its directory nor a "
              "proof '+ <size> <checksum> <name>' (an edited or damaged "
              "file). Nothing was moved or deleted. Fix: delete the line, or "
              "move the manifest out of the directory (its files are then "
              "left alone).");
        if (listing.proofs.count(name) == 0 &&
            std::find(listing.names.begin(), listing.names.end(), name) ==
                listing.names.end())
          listing.names.push_back(name);
        if (!proof.empty())
          listing.proofs[name] = proof;
      }

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

      /// The text of @p listing as a manifest.
      std::string text_of(const Listing &listing)
      {
        std::string text = header;
        for (const auto &name : listing.names)
        {
          const auto proof = listing.proofs.find(name);
          text += proof == listing.proofs.end()
                      ? name + "\n"
                      : "+ " + proof->second + " " + name + "\n";
        }
        return text;
      }

      /// Rewrite @p ledger's manifest whole (temporary file and rename), so
      /// that a file rewritten at every step keeps one line.
      void compact(Ledger &ledger)
      {
        const std::string temporary = ledger.file + ".partial";
        std::remove(temporary.c_str());
        append(temporary, text_of(ledger.listing));
        if (std::rename(temporary.c_str(), ledger.file.c_str()) != 0)
          throw std::runtime_error("Cannot rename '" + temporary + "' to '" +
                                   ledger.file + "' (" + std::strerror(errno) +
                                   ").");
        ledger.lines = 2 + ledger.listing.names.size();
      }

      /// Append @p line to @p ledger's manifest, compacting it now and then.
      void add(Ledger &ledger, const std::string &line)
      {
        if (ledger.lines > 64 + 3 * ledger.listing.names.size())
          compact(ledger);
        else
        {
          append(ledger.file, line);
          ++ledger.lines;
        }
      }

      /// Move the existing entry @p path, not this run's, out of the way.
      void move_aside(Ledger &ledger, const fs::path &path)
      {
        if (ledger.aside.empty())
        {
          unsigned int n = 1;
          while (fs::exists(
              fs::symlink_status(fs::path(ledger.directory) /
                                 ("moved-aside-" + std::to_string(n)))))
            ++n;
          ledger.aside = (fs::path(ledger.directory) /
                          ("moved-aside-" + std::to_string(n)))
                             .string();
          fs::create_directory(ledger.aside);
        }
        fs::rename(path, fs::path(ledger.aside) / path.filename());
        if (ledger.log != nullptr)
          *ledger.log << "Moved '" << path.string()
                      << "', which this run did not write (no proof in the "
                         "run manifest that a softgrasp run did), to '"
                      << ledger.aside
                      << "' instead of writing over it. Nothing else "
                         "changed there."
                      << std::endl;
      }

      /// The ledger of the directory @p path lies in, if held, and its name.
      std::pair<Ledger *, std::string> held_entry(const std::string &path)
      {
        if (ledgers().empty())
          return {nullptr, ""};
        const fs::path    entry(path);
        const std::string name = entry.filename().string();
        const auto        held = ledgers().find(
            key(entry.has_parent_path() ? entry.parent_path() : fs::path(".")));
        if (held == ledgers().end() || !listable(name))
          return {nullptr, ""};
        return {&held->second, name};
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

    Listing read(const std::string &directory)
    {
      check_regular(directory);
      Listing           listing;
      const std::string file = (fs::path(directory) / manifest_name).string();
      std::ifstream     in(file, std::ios::binary);
      if (!in)
        return listing;
      const std::string content((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
      if (!content.empty() && content.rfind(signature, 0) != 0)
        throw InputError(
            "The file '" + file +
            "' is not a softgrasp run manifest (it does not start with '" +
            signature +
            "'), so this run cannot tell which files there an earlier run "
            "wrote. Nothing was moved or deleted. Fix: move or rename '" +
            file + "', or choose another 'Output/Directory'.");
      std::size_t begin = 0, number = 1;
      for (std::size_t end = content.find('\n'); end != std::string::npos;
           begin = end + 1, end = content.find('\n', begin), ++number)
      {
        const std::string line = content.substr(begin, end - begin);
        if (line.rfind('#', 0) != 0)
          add_line(listing, line, number, file);
      }
      return listing;
    }

    bool proven(const std::string &directory,
                const Listing     &listing,
                const std::string &name)
    {
      const auto proof = listing.proofs.find(name);
      return proof != listing.proofs.end() &&
             entry_fingerprint(fs::path(directory) / name) == proof->second;
    }

    void open(const std::string &directory,
              const bool         append_to_earlier,
              std::ostream      &log)
    {
      Ledger ledger;
      ledger.directory = directory;
      ledger.file      = (fs::path(directory) / manifest_name).string();
      ledger.log       = &log;
      if (append_to_earlier && fs::exists(ledger.file))
      {
        ledger.listing = read(directory);
        for (const auto &name : ledger.listing.names)
          if (proven(directory, ledger.listing, name) ||
              !fs::exists(fs::symlink_status(fs::path(directory) / name)))
            ledger.owned.insert(name);
        // continued as it is (a refused resume leaves it byte for byte),
        // unless a killed run left an unfinished last line
        std::ifstream     in(ledger.file, std::ios::binary);
        const std::string content((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
        ledger.lines = std::count(content.begin(), content.end(), '\n');
        if (content.empty() || content.back() != '\n')
          compact(ledger);
      }
      else
      {
        check_regular(directory);
        std::remove(ledger.file.c_str());
        compact(ledger);
      }
      ledgers()[key(directory)] = std::move(ledger);
    }

    void close(const std::string &directory)
    {
      ledgers().erase(key(directory));
    }

    void note(const std::string &path)
    {
      auto [ledger, name] = held_entry(path);
      if (ledger == nullptr || ledger->owned.count(name) != 0)
        return;
      if (is_input(path))
        throw InputError("This run would write over its own input '" + path +
                         "'. Fix: choose another 'Output/Base name' or "
                         "'Output/Directory'.");
      if (fs::exists(fs::symlink_status(path)))
        move_aside(*ledger, path);
      ledger->owned.insert(name);
      auto &names = ledger->listing.names;
      if (std::find(names.begin(), names.end(), name) == names.end())
        names.push_back(name);
      ledger->listing.proofs.erase(name);
      add(*ledger, name + "\n");
    }

    void record(const std::string &path)
    {
      auto [ledger, name] = held_entry(path);
      if (ledger == nullptr)
        return;
      if (ledger->owned.count(name) == 0)
        return; // never noted: not this run's to prove
      const std::string proof = entry_fingerprint(path);
      if (proof.empty() || ledger->listing.proofs[name] == proof)
        return;
      ledger->listing.proofs[name] = proof;
      add(*ledger, "+ " + proof + " " + name + "\n");
    }

    std::vector<std::string> written(const std::string &directory)
    {
      const auto held = ledgers().find(key(directory));
      return held == ledgers().end() ? std::vector<std::string>()
                                     : held->second.listing.names;
    }

    void protect_input(const std::string &path)
    {
      inputs().insert(key(path));
    }

    bool is_input(const std::string &path)
    {
      return inputs().count(key(path)) != 0;
    }
  } // namespace RunManifest
} // namespace softgrasp
