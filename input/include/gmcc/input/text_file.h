#pragma once
/// \file text_file.h
/// Reading an input file whole, whatever it is: a regular file, a FIFO, a pipe from process
/// substitution (`--image <(…)`), a character device. The size limit and the NUL check are
/// applied while reading, so `/dev/zero` or `/dev/urandom` is rejected in its first block
/// rather than read as empty (their size from a seek is 0) or read forever; and a FIFO that no
/// program writes is reported instead of blocking the run (docs/cli.md, "Files, special
/// paths, signals and time limits").

#include <gmcc/input/input_error.h>

#include <cstddef>
#include <string>

namespace gmcc {

/// How long a named FIFO with no writer is waited for before the read is given up.
inline constexpr int fifo_writer_wait_seconds = 10;

/// What a reader accepts, and the words its messages use.
struct TextFileRules {
  std::size_t max_bytes;  ///< larger files are rejected
  std::string noun;       ///< "colour file": "is a directory, not a colour file", "limit for colour files"
  std::string expected;   ///< "text lines r,g,b": "binary data (a NUL byte): expected text lines r,g,b"
  bool binary = false;    ///< true: NUL bytes are data (an image file), not an error
};

/// The bytes of the file at `path`. A regular file's size is checked before reading; anything
/// else is read as a stream until end of file, with the size limit applied as it grows. A named
/// FIFO that no program has opened for writing is waited for up to fifo_writer_wait_seconds;
/// once a writer is there, the read waits for it as long as it keeps the FIFO open.
/// The file's path, size and SHA-256 are recorded for provenance (file_digest.h).
/// \throws InputError naming the file (and, for a NUL byte, its 1-based line): missing or
///         unreadable, a directory or socket, larger than rules.max_bytes, holding a NUL byte,
///         a FIFO with no writer.
std::string read_text_file(const std::string& path, const TextFileRules& rules);

/// The bytes of a binary file (an image): read_text_file with rules.binary set, so that only the
/// size limit applies to the content. Recorded for provenance like every input.
/// \throws InputError as read_text_file, except for NUL bytes.
std::string read_binary_file(const std::string& path, std::size_t max_bytes, const std::string& noun);

/// Refuses, before opening it, a path that is not a regular file (or a symbolic link to one): a
/// dataset's files, found by listing its folder, are read by their names, sometimes twice
/// (libmatio opens a MATLAB 7.3 file again), so a FIFO there could block for ever.
/// \throws InputError naming the file: missing, or a FIFO, device, socket or directory.
void require_regular_file(const std::string& path, const std::string& noun);

}  // namespace gmcc
