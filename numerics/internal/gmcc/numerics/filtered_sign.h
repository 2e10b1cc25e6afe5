#pragma once
/// \file filtered_sign.h
/// The floating-point filters' shared vocabulary (Shewchuk 1997; Higham 2002 §3.1): the unit
/// roundoff u of IEEE double, γ_n, and the sign of a real number x known only through a computed
/// double v and a proven bound |x − v| <= b, as the one decision type UncertainSign
/// (uncertain_sign.h). Every filter that derives such a bound by hand (docs/derivations.md §4)
/// decides with sign_within, and goes to its exact stage when the sign is not certain.

#include <gmcc/numerics/uncertain_sign.h>

namespace gmcc::numerics {

/// u = 2^-53, the unit roundoff of IEEE double in round-to-nearest: a rounded operation's
/// relative error is at most u.
inline constexpr double unit_roundoff = 0x1p-53;

/// γ_n = n·u / (1 − n·u) (Higham 2002 §3.1), the bound on the relative error of n rounded
/// operations in sequence, as a double at least γ_n: the quotient (n·u and 1 − n·u are exact for
/// n <= 2^20) is within a factor 1 − u of γ_n, so times 1 + 4u (exact), rounded, it is above
/// γ_n(1 − u)²(1 + 4u) > γ_n. A bound a filter uses must not be rounded below its value: the
/// plain quotient is, for 117 of n = 1…199 (tests/numerics/test_filtered_sign.cpp). For
/// 1 <= n <= 2^20.
constexpr double gamma_n(int n) {
  return n * unit_roundoff / (1 - n * unit_roundoff) * (1 + 4 * unit_roundoff);
}

/// The signs x may have, given |x − value| <= bound: certain when value lies beyond ±bound; the
/// signs [value − bound, value + bound] allows otherwise (indeterminate when it holds 0 inside,
/// and for a NaN value or bound). A zero bound is not taken to make value exact: a computed
/// magnitude of 0 may hide an underflow, so a filter that knows better says so itself.
constexpr UncertainSign sign_within(double value, double bound) {
  if (value > bound) return UncertainSign::certain(1);
  if (value < -bound) return UncertainSign::certain(-1);
  if (value == bound && value > 0) return {0, 1};
  if (value == -bound && value < 0) return {-1, 0};
  return UncertainSign::indeterminate();
}

}  // namespace gmcc::numerics
