#pragma once
// The x87 interval kind of the enclosure family (numerics/enclosure.h), and exact rationals
// enclosed in it. Internal to gmcc::selection.

#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/enclosure.h>
#include <gmcc/numerics/platform.h>

namespace gmcc::internal {

using numerics::LDInterval;

// These intervals' error analysis is for x87 extended precision (64-bit significand) at full
// precision control, and 64-bit GMP limbs: callers use them only where
// numerics::extended_precision_active() says so, asked at each use (numerics/platform.h), and
// take MPFI elsewhere.

/// An enclosure of an exact rational, from numerics::certified_extended: the top 64 bits of
/// numerator and denominator (each truncated: relative error < 2^-63; exact when they fit in 64
/// bits) and one division: relative error < 2^-61 (2^-64 when both parts fit). The whole line
/// outside the range policy of numerics/rational_to_float.h (beyond 2^±16000).
LDInterval enclose_ld(const Rational& q);

/// The same for num/den given as integers (den > 0, not necessarily coprime): an enclosure of
/// an exact quotient computed without its gcd.
LDInterval enclose_ld(mpz_srcptr num, mpz_srcptr den);

}  // namespace gmcc::internal
