#pragma once
/// \file input_error.h
/// The error every reader throws for bad input, and the command line for a bad option, caught once
/// at the program's edge (exit 2).

#include <cstddef>
#include <stdexcept>
#include <string>

namespace gmcc {

/// Bad input: a message a person can act on, naming where the input came from — a file, or on the
/// command line an option (`--shard`) — and, when the problem is on one line of a file, the
/// 1-based line number. what() reads `SOURCE:LINE: problem`, or `SOURCE: problem` for line 0.
/// A std::runtime_error (docs/conventions.md §9).
class InputError : public std::runtime_error {
 public:
  /// `problem` in `source` (a file's name, or an option's) at 1-based `line` (0: the whole input).
  InputError(std::string source, std::size_t line, const std::string& problem);
  /// Where the input came from, as given: a file's name, or an option's name such as `--shard`.
  const std::string& source() const { return source_; }
  std::size_t line() const { return line_; }  ///< 0 when the problem is not on one line of a file

 private:
  std::string source_;
  std::size_t line_;
};

}  // namespace gmcc
