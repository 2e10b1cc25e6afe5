#pragma once
/// \file uncertain_sign.h
/// The one decision type of gmcc's number types, in the manner of CGAL's Uncertain<Sign>: what an
/// enclosure (numerics/enclosure.h, selection's MPFI intervals) says about the sign of the real
/// number it holds. An exact rational's sign is always certain; an enclosure's is certain only
/// when the whole enclosure lies on one side of zero, or is the point zero (docs/architecture.md
/// "Exactness, routes and failures": a filter decides only what is certain, and the exact stage
/// the rest).

namespace gmcc::numerics {

/// The signs (−1, 0, 1) the number may have: every one in [lo, hi]. Certain when lo == hi.
struct UncertainSign {
  /// the least and greatest possible sign, −1 <= lo <= hi <= 1
  ///@{
  int lo = -1, hi = 1;
  ///@}
  /// The sign s (−1, 0 or 1), certain.
  static constexpr UncertainSign certain(int s) { return {s, s}; }
  /// Any sign: nothing decided (an unbounded or NaN enclosure, one that holds 0 and more).
  static constexpr UncertainSign indeterminate() { return {-1, 1}; }
  /// Only one sign is possible.
  constexpr bool is_certain() const { return lo == hi; }
};

/// The number is certainly > 0.
constexpr bool certainly_positive(UncertainSign s) { return s.lo > 0; }
/// The number is certainly < 0.
constexpr bool certainly_negative(UncertainSign s) { return s.hi < 0; }
/// The number is certainly 0.
constexpr bool certainly_zero(UncertainSign s) { return s.lo == 0 && s.hi == 0; }
/// The number is certainly ≠ 0 (positive or negative, certainly): what a divisor needs.
constexpr bool certainly_nonzero(UncertainSign s) { return s.lo > 0 || s.hi < 0; }
/// The sign of −x.
constexpr UncertainSign operator-(UncertainSign s) { return {-s.hi, -s.lo}; }

}  // namespace gmcc::numerics
