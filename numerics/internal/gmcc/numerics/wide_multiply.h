#pragma once
/// \file wide_multiply.h
/// The full 128-bit product of two 64-bit integers, as two halves, and its quotient by a 64-bit
/// integer: what Lemire's unbiased bounded integer sampler needs (Lemire 2019, "Fast random integer
/// generation in an interval", ACM TOMACS 29(1), §4) and what splitting scenes into shards needs.
/// A 128-bit integer type where the compiler has one, 32-bit halves and long division elsewhere
/// (and under GMCC_PORTABLE_NUMERICS); the same bits either way.

#include <cstdint>

namespace gmcc::numerics {

/// a·b = high·2^64 + low, exactly.
struct WideProduct {
  std::uint64_t high;  ///< the upper 64 bits
  std::uint64_t low;   ///< the lower 64 bits
};

/// a·b as WideProduct by schoolbook multiplication on 32-bit halves (a = a1·2^32 + a0, likewise
/// b): portable C++, no partial sum overflows. What multiply_wide uses without a 128-bit type.
inline WideProduct multiply_wide_halves(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
  const std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const std::uint64_t middle = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
  return {p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32), (middle << 32) | (p00 & 0xffffffffu)};
}

/// a·b as WideProduct, exactly: the compiler's 128-bit integers where it has them, else
/// multiply_wide_halves.
inline WideProduct multiply_wide(std::uint64_t a, std::uint64_t b) {
#if defined(__SIZEOF_INT128__) && !defined(GMCC_PORTABLE_NUMERICS)
  __extension__ using Wide = unsigned __int128;
  const Wide m = static_cast<Wide>(a) * b;
  return {static_cast<std::uint64_t>(m >> 64), static_cast<std::uint64_t>(m)};
#else
  return multiply_wide_halves(a, b);
#endif
}

/// ⌊(high·2^64 + low)/n⌋ by binary long division: portable C++, 64 steps.
/// \pre n > 0 and p.high < n (the quotient fits in 64 bits).
inline std::uint64_t divide_wide_halves(WideProduct p, std::uint64_t n) {
  std::uint64_t remainder = p.high, quotient = 0;
  for (int bit = 63; bit >= 0; --bit) {
    const bool carry = remainder >> 63;  // remainder·2 + next bit may need 65 bits
    remainder = (remainder << 1) | ((p.low >> bit) & 1);
    if (carry || remainder >= n) remainder -= n, quotient |= std::uint64_t{1} << bit;
  }
  return quotient;
}

/// ⌊(high·2^64 + low)/n⌋: the compiler's 128-bit division where it has one, else
/// divide_wide_halves. \pre n > 0 and p.high < n.
inline std::uint64_t divide_wide(WideProduct p, std::uint64_t n) {
#if defined(__SIZEOF_INT128__) && !defined(GMCC_PORTABLE_NUMERICS)
  __extension__ using Wide = unsigned __int128;
  return static_cast<std::uint64_t>(((static_cast<Wide>(p.high) << 64) | p.low) / n);
#else
  return divide_wide_halves(p, n);
#endif
}

}  // namespace gmcc::numerics
