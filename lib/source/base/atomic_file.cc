#include <cstdio>
#include <filesystem>
#include <fstream>
#include <softgrasp/base/atomic_file.h>
#include <stdexcept>

namespace softgrasp
{
  namespace AtomicFile
  {
    std::string temporary_name(const std::string &filename)
    {
      return filename + ".partial";
    }

    void write(const std::string &filename, const std::string &content)
    {
      const std::string tmp = temporary_name(filename);
      {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << content;
        out.flush();
        if (!out)
          throw std::runtime_error(
              "Cannot write the file '" + tmp +
              "'. Fix: check that the output directory exists, is "
              "writable and the disk is not full.");
      }
      commit(tmp, filename);
    }

    void commit(const std::string &from, const std::string &to)
    {
      std::error_code error;
      std::filesystem::rename(from, to, error);
      if (error)
        throw std::runtime_error("Cannot rename '" + from + "' to '" + to +
                                 "': " + error.message() + ".");
    }
  } // namespace AtomicFile
} // namespace softgrasp
