#pragma once
/// \file enclosure.h
/// gmcc's enclosure family: a real number known only to lie in a certified set, computed in
/// floating point with every rounding accounted for. Two kinds live here, shared by geometry and
/// selection; the third, MPFI intervals at any precision (selection/src/internal/interval.h),
/// links the MPFI library and is private to selection.
///
/// | kind | form | where |
/// |---|---|---|
/// | BasicEnclosure (of double or long double) | mid ± rad (Rump 1999) | every filter: cheapest per operation; the feasible polygon's vertices, hulls, rule_errors |
/// | LDInterval | [lo, hi] in x87, outward | atan2 and the 3-D mean's fast path: monotone functions evaluated at the ends |
/// | internal::Interval (MPFI) | [lo, hi] at p bits | the certified and correctly rounded results, at any precision |
///
/// They answer the same questions with the same free functions: lower(x) and upper(x) give
/// certain ends in the kind's own floating type (BasicEnclosure, LDInterval), sign(x) the one
/// decision type UncertainSign (uncertain_sign.h; MPFI's in interval.h), and
/// certainly_positive(x), certainly_negative(x) and certainly_nonzero(x) decide only when the
/// whole enclosure is on one side of zero, so that a rule written once over the family
/// (docs/architecture.md "Exactness, routes and failures") reads the same for each kind.
///
/// BasicEnclosure's error analysis (u the unit roundoff: 2^-53 for double, 2^-64 for x87; round
/// to nearest): the midpoint is the rounded result of the operation on the midpoints, so it is
/// within u·|mid| of that exact result; the radius adds this to the propagated radii and is
/// evaluated in at most seven rounded operations on non-negative numbers, each of which loses at
/// most a factor (1 − u); the final factor (1 + 16u) makes up for all of them, and the smallest
/// normal number for any underflow. Overflow is not guarded as such: an overflowing operation
/// leaves an infinite midpoint or radius (or NaN), for which finite() is false and certainly_positive(),
/// certainly_negative() are false (no sign certain), so every filter then falls back. The 2-D fast paths
/// keep their magnitudes within 2^±300; CRULE's filters reach about 2^±840 (edge discriminants)
/// and rely on that fallback beyond. LDInterval's: every operation is done in the
/// default round-to-nearest mode and its ends are pushed outward by a relative 2^-63 (the
/// rounding error is at most 2^-64 relative, and the push itself rounds back by at most 2^-64)
/// plus the smallest normal number (for underflow); atanl/atan2l on x86_64 glibc use the fpatan
/// instruction (error < 1 ulp <= 2^-63 relative), and their ends are pushed by 2^-61.

#include <gmcc/numerics/uncertain_sign.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gmcc::numerics {

/// A real number enclosed as mid ± rad in T (double, or x87 long double where its 64-bit
/// significand is available and in use; see the feasible-polygon code for that check).
template <class T>
struct BasicEnclosure {
  /// midpoint, and radius >= 0: the real number lies in [mid − rad, mid + rad]
  ///@{
  T mid = 0, rad = 0;
  ///@}

  /// The unit roundoff of T (2^-53 for double, 2^-64 for x87 long double).
  static constexpr T u = std::numeric_limits<T>::epsilon() / 2;
  /// The radius of an enclosure that decides nothing (+inf): its sign is never certain.
  static constexpr T unbounded = std::numeric_limits<T>::infinity();
  /// A computed radius, made an upper bound for what its rounded evaluation lost.
  static T round_up(T r) { return r * (1 + 16 * u) + std::numeric_limits<T>::min(); }

  /// The exact value x.
  static BasicEnclosure exact(T x) { return {x, 0}; }
  /// A value known to be within a relative `rel` of the real number it stands for.
  static BasicEnclosure relative(T x, T rel) { return {x, round_up(std::fabs(x) * rel)}; }
  /// [lo, hi]; unbounded unless lo <= hi (so a NaN end never passes for a tight enclosure).
  static BasicEnclosure between(T lo, T hi) {
    if (!(lo <= hi)) return {0, unbounded};
    const T m = lo + (hi - lo) / 2;
    return {m, round_up(std::max(m - lo, hi - m) + u * std::fabs(m))};
  }

  /// Certain lower and upper ends: mid ∓ rad rounds by at most u·(|mid| + rad), and so does the
  /// correction's own subtraction.
  T lo() const { return (mid - rad) - round_up(2 * u * (std::fabs(mid) + rad)); }
  /// The certain upper end (see lo()).
  T hi() const { return (mid + rad) + round_up(2 * u * (std::fabs(mid) + rad)); }
  /// A finite midpoint and a finite, non-negative radius (false for anything NaN touched).
  bool finite() const { return std::isfinite(mid) && rad >= 0 && rad < unbounded; }

  /// −x: exact (the midpoint's sign flips, the radius stays).
  friend BasicEnclosure operator-(const BasicEnclosure& a) { return {-a.mid, a.rad}; }
  /// x + y: radii add, plus the midpoint sum's rounding u·|m| (Rump 1999 §2).
  friend BasicEnclosure operator+(const BasicEnclosure& a, const BasicEnclosure& b) {
    const T m = a.mid + b.mid;
    return {m, round_up(a.rad + b.rad + u * std::fabs(m))};
  }
  /// x − y: radii add, plus the midpoint difference's rounding u·|m|.
  friend BasicEnclosure operator-(const BasicEnclosure& a, const BasicEnclosure& b) {
    const T m = a.mid - b.mid;
    return {m, round_up(a.rad + b.rad + u * std::fabs(m))};
  }
  /// x·y: |xy − ab| <= |a|·rb + |b|·ra + ra·rb for x ∈ a ± ra, y ∈ b ± rb, plus the rounding.
  friend BasicEnclosure operator*(const BasicEnclosure& a, const BasicEnclosure& b) {
    const T m = a.mid * b.mid;
    return {m, round_up(std::fabs(a.mid) * b.rad + std::fabs(b.mid) * a.rad + a.rad * b.rad + u * std::fabs(m))};
  }
  /// |x/y − a/b| <= (ra + |a/b|·rb) / (|b| − rb) for |b| > rb (and |a/b| <= (1 + 2u)|m|).
  /// \pre b excludes 0 (check with certainly_nonzero(b)); otherwise the result is unbounded (inf).
  friend BasicEnclosure operator/(const BasicEnclosure& a, const BasicEnclosure& b) {
    const T m = a.mid / b.mid;
    const T gap = std::fabs(b.mid) - b.rad;
    if (!(gap > 0)) return {m, unbounded};
    return {m, round_up((a.rad + std::fabs(m) * (1 + 2 * u) * b.rad) / gap + u * std::fabs(m))};
  }
};

/// √x over the non-negative part of x: |√y − √a| <= min(ra/√a, √ra).
template <class T>
BasicEnclosure<T> sqrt(const BasicEnclosure<T>& x) {
  using E = BasicEnclosure<T>;
  if (!(x.mid + x.rad >= 0) || !std::isfinite(x.mid + x.rad)) return {0, E::unbounded};  // NaN, or no real root
  if (x.mid <= 0) {  // [0, √(mid + rad)]: half of it either side of its middle
    const T top = std::sqrt(std::max(T(0), x.mid + x.rad)) * (1 + 8 * E::u);
    return {top / 2, E::round_up(top / 2)};
  }
  const T m = std::sqrt(x.mid);
  const T spread = std::min(x.rad / m, std::sqrt(x.rad));
  return {m, E::round_up(spread + E::u * m)};
}

/// An interval [lo, hi] of x87 extended-precision numbers (unit roundoff 2^-64), rounded outward
/// after each operation: the family's kind for monotone transcendental functions (atan2), whose
/// ends can be evaluated directly. Its bounds hold only where extended_precision_active()
/// (platform.h); callers check at each use and take MPFI elsewhere.
struct LDInterval {
  /// the certain ends, lo <= hi
  ///@{
  long double lo, hi;
  ///@}

  /// The relative outward push after one rounded operation (covers its 2^-64 and its own rounding).
  static constexpr long double push = 0x1p-63L;
  /// The push after atan2l (fpatan: within one ulp, four such ulps).
  static constexpr long double push_transcendental = 0x1p-61L;
  /// An absolute push for underflow: the smallest normal (a subnormal operand would cost the x87
  /// a slow microcode assist on every operation).
  static constexpr long double tiny = std::numeric_limits<long double>::min();

  /// x pushed down by a relative `rel` and tiny: below every value x was rounded from.
  static long double down(long double x, long double rel = push) { return x - std::fabs(x) * rel - tiny; }
  /// x pushed up likewise.
  static long double up(long double x, long double rel = push) { return x + std::fabs(x) * rel + tiny; }
  /// [lo, hi] pushed outward.
  static LDInterval around(long double lo, long double hi, long double rel = push) {
    return {down(lo, rel), up(hi, rel)};
  }

  /// −x: exact.
  friend LDInterval operator-(LDInterval a) { return {-a.hi, -a.lo}; }
  /// x + y.
  friend LDInterval operator+(LDInterval a, LDInterval b) { return around(a.lo + b.lo, a.hi + b.hi); }
  /// x − y.
  friend LDInterval operator-(LDInterval a, LDInterval b) { return around(a.lo - b.hi, a.hi - b.lo); }
  /// x·y: the extreme end products.
  friend LDInterval operator*(LDInterval a, LDInterval b) {
    const long double p[] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return around(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
  }
  /// x/y. If 0 ∈ b the quotient is unbounded: the whole line (the four end quotients would give a
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

/// \name The family's shared questions
/// The same names for every number type, so that generic code reads alike over them.
///@{
/// A certain lower end.
template <class T>
T lower(const BasicEnclosure<T>& x) { return x.lo(); }
/// A certain lower end.
inline long double lower(const LDInterval& x) { return x.lo; }
/// A certain upper end.
template <class T>
T upper(const BasicEnclosure<T>& x) { return x.hi(); }
/// A certain upper end.
inline long double upper(const LDInterval& x) { return x.hi; }
/// Every member is > 0 (false when a NaN touched x: no comparison with NaN holds).
template <class X>
bool certainly_positive(const X& x) { return lower(x) > 0; }
/// Every member is < 0 (false when a NaN touched x).
template <class X>
bool certainly_negative(const X& x) { return upper(x) < 0; }
/// Every member is ≠ 0: certainly positive or certainly negative (what a divisor needs).
template <class X>
bool certainly_nonzero(const X& x) { return certainly_positive(x) || certainly_negative(x); }
/// The signs x allows: certain on one side of zero, or for the point zero; indeterminate for an
/// enclosure that holds zero and more, or that a NaN touched.
template <class X>
UncertainSign sign(const X& x) {
  const auto l = lower(x), h = upper(x);
  if (l > 0) return UncertainSign::certain(1);
  if (h < 0) return UncertainSign::certain(-1);
  if (l == 0 && h == 0) return UncertainSign::certain(0);
  if (l >= 0 && h >= 0) return {0, 1};
  if (l <= 0 && h <= 0) return {-1, 0};
  return UncertainSign::indeterminate();
}
///@}

}  // namespace gmcc::numerics
