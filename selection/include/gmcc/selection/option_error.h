#pragma once
/// \file option_error.h
/// The one error the library throws for an option outside its documented range or meaning
/// (docs/conventions.md §9): it names the option by the library's name for it (the Python
/// argument's name), so that each front end only translates the name into its own (`--order` on
/// the command line) and keeps the library's words.

#include <stdexcept>
#include <string>

namespace gmcc {

/// An option the library cannot use. what() is the problem in words, without the option's name.
struct OptionError : std::invalid_argument {
  std::string option;  ///< the option's library name: `precision`, `order`, `samples`, …
  /// The problem `what` with option `name`.
  OptionError(std::string name, const std::string& what) : std::invalid_argument(what), option(std::move(name)) {}
};

/// An integer option's accepted values, lo to hi inclusive.
struct IntegerRange {
  unsigned long long lo;  ///< the least accepted value
  unsigned long long hi;  ///< the greatest accepted value
};

}  // namespace gmcc
