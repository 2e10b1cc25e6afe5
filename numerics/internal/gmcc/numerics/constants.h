#pragma once
/// \file constants.h
/// Mathematical constants gmcc needs, written once (`M_PI` is not standard C++).

namespace gmcc::numerics {

/// π rounded to the nearest `long double` (to the nearest double when converted: `double(pi)`
/// equals the POSIX `M_PI`).
inline constexpr long double pi = 3.141592653589793238462643383279502884L;

}  // namespace gmcc::numerics
