#pragma once
// Writing a command's whole output to stdout, with the failure reported: a full disk or a closed
// pipe must not pass for success with the output cut short.

#include <gmcc/input/colour_csv.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>

namespace gmcc::cli {

/// Write `text` to stdout and flush. \throws InputError (exit 2 at the edge) if it fails.
inline void write_stdout(const std::string& text) {
  errno = 0;
  std::cout << text << std::flush;
  if (!std::cout)
    throw InputError("standard output", 0,
                     std::string("cannot write the output") +
                         (errno ? std::string(": ") + std::strerror(errno) : std::string()));
}

}  // namespace gmcc::cli
