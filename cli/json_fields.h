#pragma once
// Reading JSON Lines written by gmcc itself (`gmcc merge` of reproduce's scene files and of
// benchmark records): where a value was read, and its members by name with a message naming the
// file and line when one is missing or of the wrong type.

#include <gmcc/input/input_error.h>

#include <cstddef>
#include <string>

namespace gmcc::cli {

/// The file and line a JSON value came from.
struct Place {
  std::string file;
  std::size_t line;
};

/// \throws InputError at `at`.
[[noreturn]] inline void bad(const Place& at, const std::string& problem) { throw InputError(at.file, at.line, problem); }

/// The member `name` of `object`. \throws InputError at `at` when there is none.
template <class Json>
const Json& member(const Json& object, const char* name, const Place& at) {
  if (!object.is_object() || !object.contains(name)) bad(at, std::string("no member \"") + name + "\"");
  return object.at(name);
}

/// The member `name` of `object` as a T. \throws InputError at `at` when missing or of another type.
template <class T, class Json>
T get(const Json& object, const char* name, const Place& at) {
  try {
    return member(object, name, at).template get<T>();
  } catch (const typename Json::exception&) {
    bad(at, std::string("member \"") + name + "\" has the wrong type");
  }
}

}  // namespace gmcc::cli
