#pragma once
/// \file enclosure.h
/// A real number enclosed in doubles as mid ± rad: midpoint–radius interval arithmetic in the
/// default rounding mode (Rump 1999, "Fast and parallel interval arithmetic", BIT 39(3), §2),
/// the certificate behind gmcc's floating-point fast paths (docs/performance.md). Every operation
/// returns an enclosure of every result of the exact operation on members of its operands.
///
/// Error analysis (u = 2^-53, round to nearest): the midpoint is the rounded result of the
/// operation on the midpoints, so it is within u·|mid| of that exact result; the radius adds this
/// to the propagated radii and is evaluated in at most seven rounded operations on non-negative
/// numbers, each of which loses at most a factor (1 − u); the final factor (1 + 2^-49) makes up
/// for all of them, and DBL_MIN for any underflow. Not for values beyond 2^1000 (overflow is not
/// guarded): gmcc's fast paths use it on inputs in [2^-300, 2^300] and fall back otherwise.

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace gmcc {

struct Enclosure {
  double mid = 0, rad = 0;

  static constexpr double u = 0x1p-53;
  /// A computed radius, made an upper bound for what its rounded evaluation lost.
  static double round_up(double r) { return r * (1 + 0x1p-49) + DBL_MIN; }

  /// The exact double x.
  static Enclosure exact(double x) { return {x, 0}; }
  /// A double known to be within a relative `rel` of the real number it stands for.
  static Enclosure relative(double x, double rel) { return {x, round_up(std::fabs(x) * rel)}; }
  /// [lo, hi]; unbounded unless lo <= hi (so a NaN end never passes for a tight enclosure).
  static Enclosure between(double lo, double hi) {
    if (!(lo <= hi)) return {0, HUGE_VAL};
    const double m = lo + (hi - lo) / 2;
    return {m, round_up(std::max(m - lo, hi - m) + u * std::fabs(m))};
  }

  /// Certain lower and upper ends: mid ∓ rad rounds by at most u·(|mid| + rad), and so does the
  /// correction's own subtraction.
  double lo() const { return (mid - rad) - round_up(2 * u * (std::fabs(mid) + rad)); }
  double hi() const { return (mid + rad) + round_up(2 * u * (std::fabs(mid) + rad)); }
  /// A finite midpoint and a finite, non-negative radius (false for anything NaN touched).
  bool finite() const { return std::isfinite(mid) && rad >= 0 && rad < HUGE_VAL; }
  bool positive() const { return lo() > 0; }
  bool negative() const { return hi() < 0; }
  /// Neither positive nor negative for certain.
  bool uncertain_sign() const { return !positive() && !negative(); }

  friend Enclosure operator-(const Enclosure& a) { return {-a.mid, a.rad}; }
  friend Enclosure operator+(const Enclosure& a, const Enclosure& b) {
    const double m = a.mid + b.mid;
    return {m, round_up(a.rad + b.rad + u * std::fabs(m))};
  }
  friend Enclosure operator-(const Enclosure& a, const Enclosure& b) {
    const double m = a.mid - b.mid;
    return {m, round_up(a.rad + b.rad + u * std::fabs(m))};
  }
  // |xy − ab| <= |a|·rb + |b|·ra + ra·rb for x ∈ a ± ra, y ∈ b ± rb.
  friend Enclosure operator*(const Enclosure& a, const Enclosure& b) {
    const double m = a.mid * b.mid;
    return {m, round_up(std::fabs(a.mid) * b.rad + std::fabs(b.mid) * a.rad + a.rad * b.rad + u * std::fabs(m))};
  }
  /// |x/y − a/b| <= (ra + |a/b|·rb) / (|b| − rb) for |b| > rb (and |a/b| <= (1 + 2u)|m|).
  /// \pre b excludes 0 (check with uncertain_sign()); otherwise the result is unbounded (inf).
  friend Enclosure operator/(const Enclosure& a, const Enclosure& b) {
    const double m = a.mid / b.mid;
    const double gap = std::fabs(b.mid) - b.rad;
    if (!(gap > 0)) return {m, HUGE_VAL};
    return {m, round_up((a.rad + std::fabs(m) * (1 + 2 * u) * b.rad) / gap + u * std::fabs(m))};
  }
};

/// √x over the non-negative part of x: |√y − √a| <= min(ra/√a, √ra).
inline Enclosure sqrt(const Enclosure& x) {
  if (!(x.mid + x.rad >= 0) || !std::isfinite(x.mid + x.rad)) return {0, HUGE_VAL};  // NaN, or no real root
  if (x.mid <= 0) {  // [0, √(mid + rad)]: half of it either side of its middle
    const double top = std::sqrt(std::max(0.0, x.mid + x.rad)) * (1 + 0x1p-50);
    return {top / 2, Enclosure::round_up(top / 2)};
  }
  const double m = std::sqrt(x.mid);
  const double spread = std::min(x.rad / m, std::sqrt(x.rad));
  return {m, Enclosure::round_up(spread + Enclosure::u * m)};
}

}  // namespace gmcc
