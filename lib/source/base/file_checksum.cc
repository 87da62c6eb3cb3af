#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <softgrasp/base/file_checksum.h>
#include <sstream>
#include <vector>

namespace softgrasp
{
  namespace fs = std::filesystem;

  namespace
  {
    constexpr std::uint64_t fnv_offset = 14695981039346656037ull;
    constexpr std::uint64_t fnv_prime  = 1099511628211ull;

    void hash_bytes(std::uint64_t &hash, const char *data, const std::size_t n)
    {
      for (std::size_t i = 0; i < n; ++i)
        hash = (hash ^ static_cast<unsigned char>(data[i])) * fnv_prime;
    }

    std::string hex(const std::uint64_t hash)
    {
      std::ostringstream out;
      out << std::hex << std::setw(16) << std::setfill('0') << hash;
      return out.str();
    }
  } // namespace

  std::string file_checksum(const fs::path &file)
  {
    std::ifstream     in(file, std::ios::binary);
    std::uint64_t     hash = fnv_offset;
    std::vector<char> buffer(1 << 16);
    while (in)
    {
      in.read(buffer.data(), buffer.size());
      hash_bytes(hash, buffer.data(), static_cast<std::size_t>(in.gcount()));
    }
    return hex(hash);
  }

  std::string entry_fingerprint(const fs::path &entry)
  {
    std::error_code ignored;
    const auto      status = fs::symlink_status(entry, ignored);
    if (fs::is_regular_file(status))
      return std::to_string(fs::file_size(entry, ignored)) + " " +
             file_checksum(entry);
    if (!fs::is_directory(status))
      return "";
    std::vector<std::pair<std::string, std::uintmax_t>> files;
    for (fs::recursive_directory_iterator it(entry, ignored), end; it != end;
         it.increment(ignored))
      if (it->is_regular_file(ignored))
        files.emplace_back(fs::relative(it->path(), entry).string(),
                           it->file_size(ignored));
    std::sort(files.begin(), files.end());
    std::uint64_t  hash  = fnv_offset;
    std::uintmax_t total = 0;
    for (const auto &[name, size] : files)
    {
      const std::string item = name + '\0' + std::to_string(size) + '\0';
      hash_bytes(hash, item.data(), item.size());
      total += size;
    }
    return std::to_string(total) + " " + hex(hash);
  }
} // namespace softgrasp
