#ifndef softgrasp_base_file_checksum_h
#define softgrasp_base_file_checksum_h

#include <filesystem>
#include <string>

namespace softgrasp
{
  /**
   * The 64-bit FNV-1a hash of the bytes of @p file as 16 hex digits: the
   * proof that a file is the one a run wrote (run manifests, checkpoint
   * manifests). Not a cryptographic hash: it detects damage and edits, not
   * forgery. An unreadable file hashes as if empty.
   */
  std::string file_checksum(const std::filesystem::path &file);

  /**
   * The fingerprint "<size> <hash>" of a file, or of a folder (the total
   * size of its regular files and the FNV-1a hash of their sorted relative
   * paths and sizes, so that a file added, removed or resized inside
   * changes it); "" if @p entry does not exist or is neither.
   */
  std::string entry_fingerprint(const std::filesystem::path &entry);
} // namespace softgrasp

#endif
