#pragma once
// Rigorous intervals in x87 extended precision (64-bit significand, unit roundoff u = 2^-64)
// for the closed form's fast path. Every operation is done in the default round-to-nearest mode
// and its ends are pushed outward by a relative 2^-63 (the rounding error is at most 2^-64
// relative, and the push itself rounds back by at most 2^-64) plus the smallest
// normal number (for underflow). atanl/
// atan2l on x86_64 glibc use the fpatan instruction (error < 1 ulp <= 2^-63 relative); their
// ends are pushed by 2^-61 (4 such ulps). Internal to gmcc::selection.

#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/platform.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gmcc::internal {

struct LDInterval {
  long double lo, hi;

  static constexpr long double push = 0x1p-63L;
  static constexpr long double push_transcendental = 0x1p-61L;
  // An absolute push for underflow: the smallest normal (a subnormal operand would cost the x87
  // a slow microcode assist on every operation).
  static constexpr long double tiny = std::numeric_limits<long double>::min();

  static long double down(long double x, long double rel = push) { return x - std::fabs(x) * rel - tiny; }
  static long double up(long double x, long double rel = push) { return x + std::fabs(x) * rel + tiny; }
  static LDInterval around(long double lo, long double hi, long double rel = push) {
    return {down(lo, rel), up(hi, rel)};
  }

  /// −x: exact.
  friend LDInterval operator-(LDInterval a) { return {-a.hi, -a.lo}; }
  friend LDInterval operator+(LDInterval a, LDInterval b) { return around(a.lo + b.lo, a.hi + b.hi); }
  friend LDInterval operator-(LDInterval a, LDInterval b) { return around(a.lo - b.hi, a.hi - b.lo); }
  friend LDInterval operator*(LDInterval a, LDInterval b) {
    const long double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return around(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
  }
  /// If 0 ∈ b the quotient is unbounded: the whole line (the four end quotients would give a
  /// bounded, wrong interval — [−7e-385, 7e-385] for a map near 1e400 — which rounds to ±0).
  friend LDInterval operator/(LDInterval a, LDInterval b) {
    if (!(b.lo > 0 || b.hi < 0))
      return {-std::numeric_limits<long double>::infinity(), std::numeric_limits<long double>::infinity()};
    const long double p[] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    return around(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
  }
};

/// x², as x·x (its enclosure may reach below 0 when x holds 0: sqrt clamps it).
inline LDInterval sqr(LDInterval x) { return x * x; }

/// √x (a negative lower end, from outward rounding of a non-negative quantity, is clamped).
inline LDInterval sqrt(LDInterval x) {
  return LDInterval::around(std::sqrt(std::max(x.lo, 0.0L)), std::sqrt(std::max(x.hi, 0.0L)));
}

/// atan2(y, x) for y > 0: decreasing in x; increasing in y where x > 0, decreasing where x < 0.
inline LDInterval atan2(LDInterval y, LDInterval x) {
  long double lo, hi;
  if (x.lo > 0) {
    lo = std::atan2(y.lo, x.hi), hi = std::atan2(y.hi, x.lo);
  } else if (x.hi < 0) {
    lo = std::atan2(y.hi, x.hi), hi = std::atan2(y.lo, x.lo);
  } else {
    const long double p[] = {std::atan2(y.lo, x.lo), std::atan2(y.lo, x.hi),
                             std::atan2(y.hi, x.lo), std::atan2(y.hi, x.hi)};
    lo = *std::min_element(p, p + 4), hi = *std::max_element(p, p + 4);
  }
  return LDInterval::around(lo, hi, LDInterval::push_transcendental);
}

// These intervals' error analysis is for x87 extended precision (64-bit significand) at full
// precision control, and 64-bit GMP limbs: callers use them only where
// numerics::extended_precision_active() says so, asked at each use (numerics/platform.h), and
// take MPFI elsewhere.

/// An enclosure of an exact rational, from the top 64 bits of numerator and denominator
/// (each truncated: relative error < 2^-63; exact when they fit in 64 bits) and one division:
/// relative error < 2^-61 (2^-64 when both parts fit).
LDInterval enclose_ld(const Rational& q);

/// The same for num/den given as integers (den > 0, not necessarily coprime): an enclosure of
/// an exact quotient computed without its gcd.
LDInterval enclose_ld(mpz_srcptr num, mpz_srcptr den);

}  // namespace gmcc::internal
