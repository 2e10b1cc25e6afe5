#pragma once
// Output files of the command line: written whole under a temporary name and renamed when
// complete (never half-written), and figures drawn by gnuplot. What an output path may be is
// a policy, documented in docs/cli.md, "Files, special paths, signals and time limits":
//   - a regular file or a new name: a temporary file beside it, renamed onto it;
//   - a symbolic link: followed; its final target is replaced that way, the link is kept;
//   - /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N: that open descriptor, written
//     directly (as the shell treats these names), so the output lands where the descriptor
//     points, after what was written there before;
//   - a FIFO or a character device (/dev/null, a terminal): written directly, since renaming
//     onto it would replace it by a regular file; a FIFO with no reader is waited for up to
//     fifo_writer_wait_seconds, then reported;
//   - a directory, a block device, a socket, or a place where the temporary file cannot be
//     made (a read-only or kernel file system such as /proc): an InputError saying which.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace gmcc::cli {

/// A file that appears only when commit() succeeds. The output is opened at construction
/// (its temporary file made, or the FIFO or device opened), so an unusable path is reported
/// (InputError, exit 2) before any work is done. The temporary file is registered with
/// exit_cleanup, so a signal or a limit removes it too.
class PendingFile {
 public:
  explicit PendingFile(std::filesystem::path path);
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;
  ~PendingFile();
  /// Write `content` and rename into place (or write it through, for a descriptor, a FIFO or
  /// a device). \throws InputError on failure.
  void commit(const std::string& content);

 private:
  std::filesystem::path path_;    // as given: messages name it
  std::filesystem::path target_;  // the file replaced: path_, or where its links lead
  std::filesystem::path temp_;    // empty when written directly
  int fd_ = -1;
  int tracked_ = -1;  // exit_cleanup handle of temp_
  bool committed_ = false;
};

/// Files written into one folder as they are made, and put in place together or not at all:
/// each goes to a temporary member of one registered family (exit_cleanup.h) in that folder,
/// so memory holds none of them and a signal or limit removes them; commit() renames every one
/// onto its name; destruction before commit() removes them (docs/cli.md "gmcc estimate").
class StagedFiles {
 public:
  /// Stage into `dir` (an existing folder). \throws InputError if it cannot be written.
  explicit StagedFiles(std::filesystem::path dir);
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();
  /// Write `content` now, to appear as dir/name at commit(). \throws InputError on failure.
  void add(const std::string& name, const std::string& content);
  /// Rename every staged file into place. \throws InputError on failure.
  void commit();

 private:
  std::filesystem::path dir_;
  std::string prefix_;
  int family_ = -1;
  std::vector<std::pair<std::string, std::string>> staged_;  // temporary, final
  bool committed_ = false;
};

/// Create `dir` if needed. \throws InputError if it cannot be made.
void ensure_directory(const std::string& dir);

/// Run gnuplot on `dir/<stem>.gp` (which reads variables png_file and svg_file) to make
/// `dir/<stem>.png` and `.svg`, each delivered as a PendingFile only when gnuplot succeeds.
/// Without gnuplot on the PATH, tells how to draw it later. Returns the exit status for the
/// command (0, or 1 when gnuplot failed). `who` prefixes messages.
/// \throws InputError if `dir/<stem>.png` or `.svg` cannot be written.
int draw_with_gnuplot(const std::filesystem::path& dir, const std::string& stem,
                      const std::string& who);

}  // namespace gmcc::cli
