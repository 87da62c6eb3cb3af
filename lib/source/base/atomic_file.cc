#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/run_manifest.h>
#include <stdexcept>

namespace softgrasp
{
  namespace AtomicFile
  {
    namespace fs = std::filesystem;

    std::string temporary_name(const std::string &filename)
    {
      return filename + ".partial";
    }

    std::string write_error(const std::string &filename,
                            const std::string &cause)
    {
      const std::string directory =
          fs::path(filename).parent_path().empty()
              ? "."
              : fs::path(filename).parent_path().string();
      return "Cannot write '" + filename + "' (" + cause +
             "); the earlier version of the file, if any, is kept. Fix: "
             "check that the directory '" +
             directory + "' is writable and its disk is not full.";
    }

    void write(const std::string &filename, const std::string &content)
    {
      RunManifest::note(filename);
      const std::string tmp = temporary_name(filename);
      std::FILE        *out = std::fopen(tmp.c_str(), "wb");
      if (out == nullptr)
        throw std::runtime_error(write_error(filename, std::strerror(errno)));
      const bool written =
          std::fwrite(content.data(), 1, content.size(), out) ==
              content.size() &&
          std::fflush(out) == 0;
      const int error = errno;
      if (std::fclose(out) != 0 || !written)
      {
        std::remove(tmp.c_str());
        throw std::runtime_error(
            write_error(filename, std::strerror(written ? errno : error)));
      }
      commit(tmp, filename);
    }

    void commit(const std::string &from, const std::string &to)
    {
      RunManifest::note(to);
      std::error_code error;
      fs::rename(from, to, error);
      if (error)
        throw std::runtime_error("Cannot rename '" + from + "' to '" + to +
                                 "': " + error.message() + ".");
      RunManifest::record(to);
    }

    std::string check_written(const std::string &filename,
                              const std::string &ending,
                              const bool         text)
    {
      std::error_code      error;
      const std::uintmax_t size = fs::file_size(filename, error);
      if (error)
        return "it was not written (" + error.message() + ")";
      if (size < ending.size())
        return "it is truncated (" + std::to_string(size) + " bytes)";
      std::ifstream in(filename, std::ios::binary);
      if (text)
      {
        // A failed or partial parallel write leaves zero bytes (holes).
        std::string buffer(1 << 16, '\0');
        while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0)
          if (std::memchr(buffer.data(), '\0', in.gcount()) != nullptr)
            return "part of it is missing (it contains zero bytes)";
        in.clear();
      }
      std::string tail(ending.size(), '\0');
      in.seekg(size - ending.size());
      in.read(tail.data(), tail.size());
      if (!in || tail != ending)
        return "it is truncated (it does not end as it should)";
      return "";
    }
  } // namespace AtomicFile
} // namespace softgrasp
