#pragma once
/// \file file_digest.h
/// The input files a run has read, each with its size and SHA-256 (FIPS 180-4, computed by
/// Nettle), for the provenance every output records (docs/cli.md "Provenance"). Every file
/// gmcc reads goes through read_text_file (text_file.h), which records it here.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace gmcc {

/// One input file as read: the path as given, its size in bytes and its SHA-256.
struct FileDigest {
  std::string path;         ///< the path as the caller gave it (not made absolute)
  std::uint64_t bytes = 0;  ///< the size of what was read, in bytes
  std::string sha256;  ///< 64 lower-case hexadecimal digits
};

/// The SHA-256 of `bytes` as 64 lower-case hexadecimal digits.
std::string sha256_hex(std::string_view bytes);

/// Record that `path` was read with content `bytes` (read_text_file calls it). A path read again
/// with the same content is recorded once; with other content (a FIFO read twice), again.
/// Thread-safe.
void record_file_read(const std::string& path, std::string_view bytes);

/// Every file recorded so far in this process, in the order first read. Thread-safe.
std::vector<FileDigest> files_read();

}  // namespace gmcc
