#pragma once
/// \file enclosure.h
/// A real number enclosed as mid ± rad in doubles (or x87 long doubles): midpoint–radius interval
/// arithmetic in the default rounding mode (Rump 1999, "Fast and parallel interval arithmetic", BIT 39(3), §2),
/// the certificate behind gmcc's floating-point fast paths (docs/performance.md). Every operation
/// returns an enclosure of every result of the exact operation on members of its operands.
///
/// Error analysis (u the unit roundoff: 2^-53 for double, 2^-64 for x87; round to nearest): the midpoint is the rounded result of the
/// operation on the midpoints, so it is within u·|mid| of that exact result; the radius adds this
/// to the propagated radii and is evaluated in at most seven rounded operations on non-negative
/// numbers, each of which loses at most a factor (1 − u); the final factor (1 + 16u) makes up
/// for all of them, and the smallest normal number for any underflow. Overflow is not guarded:
/// gmcc's fast paths use it on magnitudes within 2^±300 and fall back otherwise.

#include <gmcc/geometry/rational.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace gmcc {

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
  /// Certainly > 0: the whole enclosure lies right of zero (lo() > 0).
  bool positive() const { return lo() > 0; }
  /// Certainly < 0: the whole enclosure lies left of zero (hi() < 0).
  bool negative() const { return hi() < 0; }
  /// Neither positive nor negative for certain.
  bool uncertain_sign() const { return !positive() && !negative(); }

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
  /// \pre b excludes 0 (check with uncertain_sign()); otherwise the result is unbounded (inf).
  friend BasicEnclosure operator/(const BasicEnclosure& a, const BasicEnclosure& b) {
    const T m = a.mid / b.mid;
    const T gap = std::fabs(b.mid) - b.rad;
    if (!(gap > 0)) return {m, unbounded};
    return {m, round_up((a.rad + std::fabs(m) * (1 + 2 * u) * b.rad) / gap + u * std::fabs(m))};
  }
};

/// Doubles (u = 2^-53): the fast paths' first stage.
using Enclosure = BasicEnclosure<double>;
/// x87 extended precision (u = 2^-64): their second stage, for thin sets.
using LongEnclosure = BasicEnclosure<long double>;

/// An exact rational as a certified double enclosure: mpq_get_d truncates (relative error below
/// 2u) within [2^-138, 2^138]; outside that range an unbounded enclosure, which decides nothing.
inline Enclosure enclose_rational(const Rational& q) {
  if (sgn(q) == 0) return Enclosure::exact(0);
  const long bits = static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2)) -
                    static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 2));
  if (bits < -138 || bits > 138) return {0, Enclosure::unbounded};
  return Enclosure::relative(mpq_get_d(q.get_mpq_t()), 2 * Enclosure::u);
}

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

}  // namespace gmcc
