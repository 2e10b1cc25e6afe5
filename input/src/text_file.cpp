#include <gmcc/input/text_file.h>

#include <gmcc/input/file_digest.h>

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

namespace gmcc {
namespace {

// Closes the descriptor on every way out of the reader.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// Appends what was read, applying the size limit and the NUL check to it (the check that the
// parsers also make, made here so that an endless device fails on its first block).
class Accumulator {
 public:
  Accumulator(const std::string& path, const TextFileRules& rules) : path_(path), rules_(rules) {}

  void add(const char* data, std::size_t n) {
    if (n > rules_.max_bytes - text_.size())
      throw InputError(path_, 0, "larger than the " + std::to_string(rules_.max_bytes >> 20) +
                                     " MiB limit for " + rules_.noun + "s");
    if (const void* nul = rules_.binary ? nullptr : std::memchr(data, '\0', n)) {
      const auto at = static_cast<std::size_t>(static_cast<const char*>(nul) - data);
      const std::size_t line =
          lines_before_ + static_cast<std::size_t>(std::count(data, data + at, '\n')) + 1;
      throw InputError(path_, line, "binary data (a NUL byte): expected " + rules_.expected);
    }
    lines_before_ += static_cast<std::size_t>(std::count(data, data + n, '\n'));
    text_.append(data, n);
  }
  std::string take() { return std::move(text_); }

 private:
  const std::string& path_;
  const TextFileRules& rules_;
  std::string text_;
  std::size_t lines_before_ = 0;
};

[[noreturn]] void cannot_read(const std::string& path, int error) {
  throw InputError(path, 0, std::string("cannot read: ") + std::strerror(error));
}

// A regular file or a device: blocking reads until end of file.
std::string read_stream(int fd, const std::string& path, const TextFileRules& rules) {
  Accumulator text(path, rules);
  char block[65536];
  for (;;) {
    const ssize_t n = ::read(fd, block, sizeof block);
    if (n > 0) {
      text.add(block, static_cast<std::size_t>(n));
    } else if (n == 0) {
      return text.take();
    } else if (errno != EINTR) {
      cannot_read(path, errno);
    }
  }
}

// A FIFO or pipe, opened non-blocking. A read of 0 bytes means no writer has it open: end of
// file if a writer has been there (poll reports POLLHUP once one has come and gone, Linux),
// otherwise none has come yet, and it is waited for up to fifo_writer_wait_seconds.
std::string read_fifo(int fd, const std::string& path, const TextFileRules& rules) {
  Accumulator text(path, rules);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::seconds(fifo_writer_wait_seconds);
  bool writer_seen = false;
  char block[65536];
  for (;;) {
    const ssize_t n = ::read(fd, block, sizeof block);
    if (n > 0) {
      writer_seen = true;
      text.add(block, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    pollfd p{fd, POLLIN, 0};
    if (n < 0) {
      if (errno != EAGAIN) cannot_read(path, errno);
      writer_seen = true;  // a writer has it open and has not written yet: wait for it
      if (::poll(&p, 1, -1) < 0 && errno != EINTR) cannot_read(path, errno);
      continue;
    }
    if (writer_seen) return text.take();
    if (::poll(&p, 1, 0) > 0 && (p.revents & POLLHUP)) return text.take();
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0)
      throw InputError(path, 0,
                       "a FIFO that no program opened for writing within " +
                           std::to_string(fifo_writer_wait_seconds) +
                           " s: start the program that writes it (gmcc does not wait longer)");
    if (::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000))) < 0 &&
        errno != EINTR)
      cannot_read(path, errno);
  }
}

// The bytes of the file, by its kind (read_text_file's contract).
std::string read_whole(const std::string& path, const TextFileRules& rules) {
  // Non-blocking, so that opening a FIFO with no writer returns at once (a blocking open would
  // wait for a writer forever); other files are switched back to blocking reads.
  Descriptor in{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (in.fd < 0) {
    const int error = errno;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISSOCK(st.st_mode))
      throw InputError(path, 0, "is a socket, not a " + rules.noun);
    throw InputError(path, 0, std::string("cannot open: ") + std::strerror(error));
  }
  struct stat st {};
  if (::fstat(in.fd, &st) != 0) cannot_read(path, errno);
  if (S_ISDIR(st.st_mode)) throw InputError(path, 0, "is a directory, not a " + rules.noun);
  if (S_ISFIFO(st.st_mode)) return read_fifo(in.fd, path, rules);
  if (S_ISREG(st.st_mode) && static_cast<std::size_t>(st.st_size) > rules.max_bytes)
    throw InputError(path, 0, "larger than the " + std::to_string(rules.max_bytes >> 20) +
                                  " MiB limit for " + rules.noun + "s");
  const int flags = ::fcntl(in.fd, F_GETFL);
  if (flags < 0 || ::fcntl(in.fd, F_SETFL, flags & ~O_NONBLOCK) < 0) cannot_read(path, errno);
  return read_stream(in.fd, path, rules);
}

}  // namespace

std::string read_text_file(const std::string& path, const TextFileRules& rules) {
  std::string bytes = read_whole(path, rules);
  record_file_read(path, bytes);
  return bytes;
}

void require_regular_file(const std::string& path, const std::string& noun) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  if (S_ISREG(st.st_mode)) return;
  const char* kind = S_ISFIFO(st.st_mode)  ? "a FIFO"
                     : S_ISDIR(st.st_mode) ? "a directory"
                     : S_ISSOCK(st.st_mode) ? "a socket"
                     : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                   : "a special file";
  throw InputError(path, 0, std::string("is ") + kind + ", not a " + noun + " (a dataset's files must be regular files)");
}

std::string read_binary_file(const std::string& path, std::size_t max_bytes,
                             const std::string& noun) {
  TextFileRules rules{max_bytes, noun, noun, true};
  return read_text_file(path, rules);
}

}  // namespace gmcc
