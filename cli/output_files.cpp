#include "output_files.h"

#include "exit_cleanup.h"
#include "limit_exit.h"

#include <gmcc/input/input_error.h>
#include <gmcc/input/text_file.h>

#include <fcntl.h>
#include <linux/magic.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

namespace gmcc::cli {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void cannot_write(const fs::path& path, const std::string& why) {
  throw InputError(path.string(), 0, "cannot write: " + why);
}

// The descriptor a path names the way the shell reads it: /dev/stdout, /dev/stderr,
// /dev/fd/N, /proc/self/fd/N.
std::optional<int> descriptor_named(const std::string& path) {
  if (path == "/dev/stdout") return 1;
  if (path == "/dev/stderr") return 2;
  for (const char* prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    const std::size_t n = std::strlen(prefix);
    if (path.size() > n && path.size() <= n + 9 && path.compare(0, n, prefix) == 0 &&
        path.find_first_not_of("0123456789", n) == std::string::npos)
      return std::stoi(path.substr(n));
  }
  return std::nullopt;
}

// Where a chain of symbolic links ends (the last component only: a link among the directories
// does not matter to a rename within one directory). The end may not exist yet.
fs::path final_target(const fs::path& path) {
  fs::path p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::string link(4096, '\0');
    const ssize_t n = ::readlink(p.c_str(), link.data(), link.size());
    if (n < 0 || static_cast<std::size_t>(n) >= link.size()) return p;
    link.resize(static_cast<std::size_t>(n));
    p = fs::path(link).is_absolute() ? fs::path(link) : p.parent_path() / link;
  }
  cannot_write(path, "too many levels of symbolic links");
}

// The name of a kernel file system, where no file can be made ("" for others).
const char* kernel_file_system(const fs::path& dir) {
  struct statfs fs {};
  if (::statfs(dir.c_str(), &fs) != 0) return "";
  switch (static_cast<unsigned long>(fs.f_type)) {
    case PROC_SUPER_MAGIC: return "proc";
    case SYSFS_MAGIC: return "sysfs";
    case CGROUP_SUPER_MAGIC: case CGROUP2_SUPER_MAGIC: return "cgroup";
    case DEBUGFS_MAGIC: return "debugfs";
    case TRACEFS_MAGIC: return "tracefs";
    case SECURITYFS_MAGIC: return "securityfs";
    default: return "";
  }
}

// Why the temporary file could not be made in `dir` (errno `error`), said about the output.
[[noreturn]] void cannot_create_in(const fs::path& path, const fs::path& dir, int error) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0)
    cannot_write(path, errno == ENOENT ? "the directory " + dir.string() + " does not exist"
                                       : dir.string() + ": " + std::strerror(errno));
  if (!S_ISDIR(st.st_mode)) cannot_write(path, dir.string() + " is not a directory");
  if (error == EROFS) cannot_write(path, dir.string() + " is on a read-only file system");
  if (error == EACCES || error == EPERM)
    cannot_write(path, "no permission to create a file in " + dir.string() +
                           " (the output is written there under a temporary name, then renamed)");
  cannot_write(path, "cannot create a file in " + dir.string() + ": " + std::strerror(error));
}

// A FIFO opened for writing: without O_NONBLOCK the open would wait for a reader forever;
// with it, it fails (ENXIO) until there is one, which is waited for a bounded time.
int open_fifo_for_writing(const fs::path& path) {
  set_activity("waiting for a reader of the FIFO " + path.string());
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::seconds(fifo_writer_wait_seconds);
  for (;;) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd >= 0) {
      const int flags = ::fcntl(fd, F_GETFL);
      if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) < 0) {
        const int error = errno;
        ::close(fd);
        cannot_write(path, std::strerror(error));
      }
      return fd;
    }
    if (errno == EINTR) continue;
    if (errno != ENXIO) cannot_write(path, std::strerror(errno));
    if (std::chrono::steady_clock::now() >= deadline)
      cannot_write(path, "a FIFO that no program opened for reading within " +
                             std::to_string(fifo_writer_wait_seconds) +
                             " s: start its reader first (gmcc does not wait longer)");
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

// Writes all of `content`; errno on failure.
bool write_all(int fd, const std::string& content) {
  const char* p = content.data();
  for (std::size_t left = content.size(); left > 0;) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

PendingFile::PendingFile(fs::path path) : path_(std::move(path)) {
  if (const std::optional<int> fd = descriptor_named(path_.string())) {
    fd_ = ::fcntl(*fd, F_DUPFD_CLOEXEC, 3);
    if (fd_ < 0)
      cannot_write(path_, "descriptor " + std::to_string(*fd) + " is not open");
    struct stat st {};
    if (::fstat(fd_, &st) == 0 && S_ISDIR(st.st_mode))
      throw InputError(path_.string(), 0, "is a directory; give a file name");
    return;
  }
  struct stat st {};
  if (::stat(path_.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw InputError(path_.string(), 0, "is a directory; give a file name");
    if (S_ISFIFO(st.st_mode)) {
      fd_ = open_fifo_for_writing(path_);
      return;
    }
    if (S_ISCHR(st.st_mode)) {
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
      if (fd_ < 0) cannot_write(path_, std::strerror(errno));
      return;
    }
    if (S_ISBLK(st.st_mode))
      throw InputError(path_.string(), 0, "is a block device; gmcc does not write to disks");
    if (S_ISSOCK(st.st_mode)) throw InputError(path_.string(), 0, "is a socket; give a file name");
  } else if (errno != ENOENT) {
    cannot_write(path_, std::strerror(errno));  // e.g. a component is not a directory
  }
  target_ = final_target(path_);
  const fs::path dir = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  if (const char* kernel = kernel_file_system(dir); *kernel)
    cannot_write(path_, dir.string() + " is on the kernel's " + kernel +
                            " file system, where gmcc cannot create or replace files");
  if (::access(target_.c_str(), F_OK) == 0 && ::access(target_.c_str(), W_OK) != 0)
    cannot_write(path_, std::strerror(errno));  // a read-only file is not replaced
  temp_ = target_;
  temp_ += ".tmp-" + std::to_string(::getpid());
  if (is_tracked(temp_.string()))
    throw InputError(path_.string(), 0, "is written twice in this run; give each output its own path");
  // O_EXCL: never through a link someone put there. One left by a killed process of the same
  // pid (SIGKILL) is stale, and removed.
  for (int attempt = 0; fd_ < 0; ++attempt) {
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY, 0666);
    if (fd_ >= 0) break;
    if (errno == EINTR) continue;
    if (errno == EEXIST && attempt == 0 && ::unlink(temp_.c_str()) == 0) continue;
    cannot_create_in(path_, dir, errno);
  }
  try {
    tracked_ = track_temporary(temp_.string());
  } catch (...) {
    ::close(fd_);
    ::unlink(temp_.c_str());
    throw;
  }
}

PendingFile::~PendingFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_.empty()) {
    ::unlink(temp_.c_str());
    untrack_temporary(tracked_);
  }
}

void PendingFile::commit(const std::string& content) {
  set_activity("writing " + path_.string());
  if (temp_.empty()) {
    // Written directly: what went to stdout or stderr before stays before.
    std::cout.flush();
    std::cerr.flush();
  }
  const bool written = write_all(fd_, content);
  const int write_error = errno;
  const int closed = ::close(fd_);
  const int close_error = errno;
  fd_ = -1;
  if (!written) cannot_write(path_, std::strerror(write_error));
  if (closed != 0 && close_error != EINTR) cannot_write(path_, std::strerror(close_error));
  if (!temp_.empty()) {
    if (::rename(temp_.c_str(), target_.c_str()) != 0) cannot_write(path_, std::strerror(errno));
    untrack_temporary(tracked_);
  }
  committed_ = true;
}

void ensure_directory(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(dir, 0, "cannot create the directory" + (ec ? ": " + ec.message() : std::string()));
}

namespace {

std::optional<std::string> find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
  }
  return std::nullopt;
}

// Runs `gnuplot -e SETTINGS SCRIPT` in `dir` (its stdout to our stderr, so stdout keeps only the
// report); returns its exit status, 127 if it could not be started. The child is registered
// with exit_cleanup while it runs, so a signal or a limit kills it before removing its files.
int run_gnuplot(const std::string& gnuplot, const fs::path& dir, const std::string& settings,
                const std::string& script) {
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork_for_exec();
  if (pid < 0) return 127;
  if (pid == 0) {
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execl(gnuplot.c_str(), "gnuplot", "-e", settings.c_str(), script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  track_child(pid);
  // Waited for without reaping (WNOWAIT): until it is untracked its pid cannot be reused, so a
  // cleanup that kills it cannot hit another process.
  siginfo_t info{};
  while (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
  }
  if (!untrack_child(pid))
    for (;;) ::pause();  // a cleanup has taken it: the process is ending
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// gnuplot's output files, named in `dir` and registered with exit_cleanup; removed when done.
struct ScratchFile {
  fs::path path;
  int tracked;
  ScratchFile(const fs::path& dir, const std::string& name)
      : path(dir / name), tracked(track_temporary(path.string())) {}
  ~ScratchFile() {
    ::unlink(path.c_str());
    untrack_temporary(tracked);
  }
  std::optional<std::string> content() const {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    if (!(in && text << in.rdbuf())) return std::nullopt;
    return text.str();
  }
};

}  // namespace

int draw_with_gnuplot(const fs::path& dir, const std::string& stem, const std::string& who) {
  const std::optional<std::string> gnuplot = find_on_path("gnuplot");
  if (!gnuplot) {
    std::cerr << who << ": gnuplot not found on PATH: to draw the figure run\n  cd " << dir.string()
              << " && gnuplot " << stem << ".gp\n(Debian: apt-get install gnuplot-nox)\n";
    return 0;
  }
  PendingFile png_file(dir / (stem + ".png")), svg_file(dir / (stem + ".svg"));
  const std::string suffix = ".gnuplot.tmp-" + std::to_string(::getpid());
  const ScratchFile png(dir, stem + ".png" + suffix), svg(dir, stem + ".svg" + suffix);
  set_activity("drawing " + (dir / (stem + ".gp")).string() + " with gnuplot");
  const int status =
      run_gnuplot(*gnuplot, dir,
                  "png_file='" + png.path.filename().string() + "'; svg_file='" +
                      svg.path.filename().string() + "'",
                  stem + ".gp");
  const std::optional<std::string> png_data = status == 0 ? png.content() : std::nullopt;
  const std::optional<std::string> svg_data = status == 0 ? svg.content() : std::nullopt;
  if (png_data && svg_data) {
    png_file.commit(*png_data);
    svg_file.commit(*svg_data);
    return 0;
  }
  std::cerr << "gmcc: error: "
            << (status != 0 ? "gnuplot failed (exit status " + std::to_string(status) + ")"
                            : std::string("cannot read gnuplot's output"))
            << " on " << (dir / (stem + ".gp")).string() << "; the data and script are written\n";
  return 1;
}

}  // namespace gmcc::cli

namespace gmcc::cli {

StagedFiles::StagedFiles(std::filesystem::path dir) : dir_(std::move(dir)) {
  prefix_ = (dir_ / (".gmcc-staged-" + std::to_string(::getpid()) + "-")).string();
  family_ = track_temporary_family(prefix_);
}

StagedFiles::~StagedFiles() {
  if (!committed_)
    for (const auto& [temp, name] : staged_) ::unlink(temp.c_str());
  untrack_temporary(family_);
}

void StagedFiles::add(const std::string& name, const std::string& content) {
  const std::string temp = family_member(prefix_, static_cast<int>(staged_.size()));
  family_members(family_, static_cast<int>(staged_.size()) + 1);
  staged_.push_back({temp, (dir_ / name).string()});
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(staged_.back().second, 0, std::string("cannot write: ") + std::strerror(errno));
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int e = errno;
      ::close(fd);
      throw InputError(staged_.back().second, 0, std::string("cannot write: ") + std::strerror(e));
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) throw InputError(staged_.back().second, 0, std::string("cannot write: ") + std::strerror(errno));
}

void StagedFiles::commit() {
  for (const auto& [temp, name] : staged_)
    if (::rename(temp.c_str(), name.c_str()) != 0)
      throw InputError(name, 0, std::string("cannot write: ") + std::strerror(errno));
  committed_ = true;
}

}  // namespace gmcc::cli
