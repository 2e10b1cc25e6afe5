#pragma once
// Output files of the command line: written whole under a temporary name and renamed when
// complete (never half-written), and figures drawn by gnuplot.

#include <filesystem>
#include <fstream>
#include <string>

namespace gmcc::cli {

/// A file that appears only when commit() succeeds. The temporary file is opened at
/// construction, so an unusable path is reported (InputError, exit 2) before any work is done.
class PendingFile {
 public:
  explicit PendingFile(std::filesystem::path path);
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;
  ~PendingFile();
  /// Write `content` and rename into place. \throws InputError on failure.
  void commit(const std::string& content);

 private:
  std::filesystem::path path_, temp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Create `dir` if needed. \throws InputError if it cannot be made.
void ensure_directory(const std::string& dir);

/// Run gnuplot on `dir/<stem>.gp` (which reads variables png_file and svg_file) to make
/// `dir/<stem>.png` and `.svg`, renamed into place only when gnuplot succeeds. Without gnuplot
/// on the PATH, tells how to draw it later. Returns the exit status for the command (0, or 1
/// when gnuplot failed). `who` prefixes messages.
int draw_with_gnuplot(const std::filesystem::path& dir, const std::string& stem,
                      const std::string& who);

}  // namespace gmcc::cli
