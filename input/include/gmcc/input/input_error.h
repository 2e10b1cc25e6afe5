#pragma once
/// \file input_error.h
/// The error every reader throws for bad input, caught once at the program's edge (exit 2).

#include <cstddef>
#include <stdexcept>
#include <string>

namespace gmcc {

/// Bad input in a file: a message a person can act on, with the file and (when the problem is
/// on one line) the 1-based line number. what() reads `FILE:LINE: problem`.
class InputError : public std::runtime_error {
 public:
  /// `problem` in `file` at 1-based `line` (0: the whole file).
  InputError(std::string file, std::size_t line, const std::string& problem);
  /// The file's name as given.
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }  ///< 0 when the problem is the whole file

 private:
  std::string file_;
  std::size_t line_;
};

}  // namespace gmcc
