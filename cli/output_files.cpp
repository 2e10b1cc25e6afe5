#include "output_files.h"

#include <gmcc/validation/colour_csv.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>
#include <sstream>

namespace gmcc::cli {

namespace fs = std::filesystem;

PendingFile::PendingFile(fs::path path) : path_(std::move(path)) {
  std::error_code ec;
  if (fs::is_directory(path_, ec)) throw InputError(path_.string(), 0, "is a directory; give a file name");
  temp_ = path_;
  temp_ += ".tmp-" + std::to_string(::getpid());
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) throw InputError(path_.string(), 0, std::string("cannot write: ") + std::strerror(errno));
}

PendingFile::~PendingFile() {
  if (committed_) return;
  out_.close();
  std::error_code ec;
  fs::remove(temp_, ec);
}

void PendingFile::commit(const std::string& content) {
  out_ << content;
  out_.close();
  if (!out_) throw InputError(path_.string(), 0, "cannot write (disk full?)");
  std::error_code ec;
  fs::rename(temp_, path_, ec);
  if (ec) throw InputError(path_.string(), 0, "cannot write: " + ec.message());
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
// report); returns its exit status, 127 if it could not be started.
int run_gnuplot(const std::string& gnuplot, const fs::path& dir, const std::string& settings,
                const std::string& script) {
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    ::execl(gnuplot.c_str(), "gnuplot", "-e", settings.c_str(), script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

int draw_with_gnuplot(const fs::path& dir, const std::string& stem, const std::string& who) {
  const std::optional<std::string> gnuplot = find_on_path("gnuplot");
  if (!gnuplot) {
    std::cerr << who << ": gnuplot not found on PATH: to draw the figure run\n  cd " << dir.string()
              << " && gnuplot " << stem << ".gp\n(Debian: apt-get install gnuplot-nox)\n";
    return 0;
  }
  const std::string suffix = ".tmp-" + std::to_string(::getpid());
  const std::string png = stem + ".png" + suffix, svg = stem + ".svg" + suffix;
  const int status = run_gnuplot(*gnuplot, dir, "png_file='" + png + "'; svg_file='" + svg + "'", stem + ".gp");
  std::error_code ec;
  if (status == 0) {
    fs::rename(dir / png, dir / (stem + ".png"), ec);
    if (!ec) fs::rename(dir / svg, dir / (stem + ".svg"), ec);
    if (!ec) return 0;
  }
  std::error_code ignored;
  fs::remove(dir / png, ignored);
  fs::remove(dir / svg, ignored);
  std::cerr << "gmcc: error: "
            << (status != 0 ? "gnuplot failed (exit status " + std::to_string(status) + ")"
                            : "cannot rename gnuplot's output: " + ec.message())
            << " on " << (dir / (stem + ".gp")).string() << "; the data and script are written\n";
  return 1;
}

}  // namespace gmcc::cli
