#pragma once
// Integer options read exactly, like every number gmcc reads (`1e7` is 10000000), range-checked:
// CLI11 would silently wrap `-1` into an unsigned option.

#include <gmcc/selection/option_error.h>

#include <cstdint>
#include <string>

namespace gmcc::cli {

/// The integer written in `text`, within [lo, hi].
/// \throws InputError naming the option (exit 2 at the edge) otherwise.
std::uint64_t integer_option(const std::string& name, const std::string& text, std::uint64_t lo,
                             std::uint64_t hi);
/// The same within a library range (e.g. mean_3d.h's).
inline std::uint64_t integer_option(const std::string& name, const std::string& text, IntegerRange range) {
  return integer_option(name, text, range.lo, range.hi);
}

}  // namespace gmcc::cli
