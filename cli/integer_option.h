#pragma once
// Integer options read exactly, like every number gmcc reads (`1e7` is 10000000), range-checked:
// CLI11 would silently wrap `-1` into an unsigned option.

#include <cstdint>
#include <string>

namespace gmcc::cli {

/// The integer written in `text`, within [lo, hi].
/// \throws InputError naming the option (exit 2 at the edge) otherwise.
std::uint64_t integer_option(const std::string& name, const std::string& text, std::uint64_t lo,
                             std::uint64_t hi);

}  // namespace gmcc::cli
