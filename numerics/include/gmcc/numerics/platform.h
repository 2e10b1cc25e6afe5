#pragma once
/// \file platform.h
/// Which floating-point fast paths this build and this thread may use: the one place gmcc asks.
/// gmcc's extended-precision filters (the feasible polygon's vertex enclosures, the angle, worst
/// case and 3-D mean fast paths) carry error bounds derived for x87 extended precision (a 64-bit
/// significand, unit roundoff 2^-64) and for 64-bit GMP limbs (docs/math.md §1a′ and §2). Where
/// either is missing, or where the thread's precision control has been lowered, every caller takes
/// its portable route (exact arithmetic, MPFR or MPFI), which gives the same results more slowly.

#include <gmp.h>

#include <limits>

namespace gmcc::numerics {

/// True when the extended-precision fast paths are compiled in: `long double` has a 64-bit
/// significand (x86's x87), GMP limbs hold 64 bits with no nail bits, and the build did not force
/// the portable path (CMake option GMCC_PORTABLE_NUMERICS, which defines the macro of that name).
/// False on, e.g., aarch64 (113-bit `long double`) or MSVC (53-bit).
inline constexpr bool extended_precision_compiled =
#ifdef GMCC_PORTABLE_NUMERICS
    false;
#else
    std::numeric_limits<long double>::digits == 64 && GMP_NUMB_BITS == 64 && GMP_NAIL_BITS == 0;
#endif

/// True when extended_precision_compiled and this thread's x87 precision control is at its full
/// 64 bits. Some systems and libraries set it to 53 bits, which would void the fast paths' bounds
/// silently; it is per thread and can change at run time, so callers ask where they use a fast
/// path, not once. Cost: one addition through a volatile.
inline bool extended_precision_active() {
  if constexpr (!extended_precision_compiled) {
    return false;
  } else {
    volatile long double one = 1, tiny = 0x1p-63L;
    return one + tiny != one;
  }
}

}  // namespace gmcc::numerics
