#pragma once
/// \file internal_check.h
/// gmcc's one way to signal a programming error (docs/conventions.md "Failures"): a condition
/// the code's own mathematics guarantees (a postcondition or invariant) found false. Always
/// checked, in every build type, because the checks are cheap next to the exact arithmetic they
/// guard and a silent wrong answer is worse than a stop; never used for bad input (that is
/// std::invalid_argument or an error type derived from it) or for degenerate geometry (a value).

#include <stdexcept>
#include <string>

namespace gmcc {

/// A broken postcondition or invariant: a bug in gmcc, never the caller's input. what() names
/// the source file and line and what failed.
class InternalError : public std::logic_error {
 public:
  /// `what` states the condition that failed; `file` and `line` where it was checked.
  InternalError(const char* file, int line, const std::string& what)
      : std::logic_error(std::string(file) + ":" + std::to_string(line) + ": check failed: " + what +
                         " (a bug in gmcc: please report it with the input)") {}
};

}  // namespace gmcc

/// Throw gmcc::InternalError naming this file and line unless `condition` holds.
#define GMCC_CHECK(condition, what)                                    \
  do {                                                                 \
    if (!(condition)) throw ::gmcc::InternalError(__FILE__, __LINE__, what); \
  } while (false)
