#pragma once
// A name as written on the command line or in Python: the library's own (`max_volume`) or with
// dashes for underscores (`max-volume`). Internal to gmcc::photo.

#include <string>

namespace gmcc::internal {

inline bool names_match(const std::string& text, std::string name) {
  if (text == name) return true;
  for (char& c : name)
    if (c == '_') c = '-';
  return text == name;
}

}  // namespace gmcc::internal
