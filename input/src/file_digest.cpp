#include <gmcc/input/file_digest.h>
#include <nettle/sha2.h>

#include <mutex>

namespace gmcc {
namespace {

std::mutex& log_mutex() {
  static std::mutex m;
  return m;
}
std::vector<FileDigest>& log() {
  static std::vector<FileDigest> files;
  return files;
}

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  sha256_ctx ctx;
  sha256_init(&ctx);
  sha256_update(&ctx, bytes.size(), reinterpret_cast<const std::uint8_t*>(bytes.data()));
  std::uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(&ctx, SHA256_DIGEST_SIZE, digest);
  static const char hex[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 * SHA256_DIGEST_SIZE);
  for (const std::uint8_t b : digest) {
    out += hex[b >> 4];
    out += hex[b & 15];
  }
  return out;
}

void record_file_read(const std::string& path, std::string_view bytes) {
  FileDigest d{path, bytes.size(), sha256_hex(bytes)};
  const std::lock_guard<std::mutex> lock(log_mutex());
  for (const FileDigest& seen : log())
    if (seen.path == d.path && seen.sha256 == d.sha256) return;
  log().push_back(std::move(d));
}

std::vector<FileDigest> files_read() {
  const std::lock_guard<std::mutex> lock(log_mutex());
  return log();
}

}  // namespace gmcc
