#pragma once
// The angle between 3-vectors, ∠(u, v) = atan2(|u×v|, u·v): the one implementation behind every
// angular error and worst case, for each kind of input — exact vectors rounded to double
// (angle_deg), x87 intervals (angle_deg_enclosure, for pruning), and midpoint–radius enclosures
// (enclosed_angle_deg, the certified route). Internal to gmcc::selection.

#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/constants.h>

#include "closed_form.h"
#include "ld_interval.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

namespace gmcc::internal {

/// ∠(u, v) in degrees as atan2(|u×v|, u·v) (well conditioned for small angles, unlike acos),
/// rounded to double. First in x87 extended-precision intervals from enclosures of the exact
/// inputs (cheap even when they have hundreds of digits), kept when the enclosure pins the angle
/// to 2^-56 relative; otherwise (tiny angles, where the cross product cancels) in MPFR at
/// 160 bits from the exact inputs rounded once. Either way the double is within about one ulp.
/// Equal vectors give 0 at once; between the two stages above, the cross product is enclosed
/// from its exact value (integer cross-multiplication), which settles small angles.
double angle_deg(const std::array<Rational, 3>& u, const std::array<Rational, 3>& v);

/// angle_deg(ray(u), ray(v)) for integer vectors u, v, each any positive multiple of its ray (not
/// divided by its content, so without a gcd), when a filter settles it: the double angle_deg gives
/// for the rays, or nothing (then angle_deg of the rays decides). Decides only where x87
/// extended precision is active, from an enclosure of the angle in intervals: see angle.cpp for
/// why any stage of angle_deg then returns that double.
std::optional<double> ray_angle_deg(const std::array<const mpz_class*, 3>& u, const std::array<const mpz_class*, 3>& v);

/// A rigorous enclosure of ∠(u, v) in degrees from the first stage alone, however wide (for
/// pruning: a maximum need not evaluate candidates that certainly lose). Needs the x87 fast path.
LDInterval angle_deg_enclosure(const std::array<Rational, 3>& u, const std::array<Rational, 3>& v);
/// The same from enclosures of u and v.
LDInterval angle_deg_enclosure(const std::array<LDInterval, 3>& u, const std::array<LDInterval, 3>& v);

/// 180/π rounded to T. libm's atan2 (and atan2l, the x87's fpatan) is within one ulp on x86_64
/// glibc (and every platform we know); this constant and the product by it add two roundings;
/// enclosed_angle_deg's pads cover all three.
template <class T>
constexpr T degrees_per_radian = T(180) / T(numerics::pi);

/// ∠(a, b) in degrees in midpoint–radius enclosures E (geometry/enclosure.h: doubles or x87), for
/// the certified route (certified_rule_errors.h): atan2(s, d) with s = |a×b| ∈ [s_lo, s_hi] and d = a·b.
/// One atan2 at the box's centre; over the box |∂θ/∂s| = |d|/(s² + d²) <= max|d|/R² and
/// |∂θ/∂d| = s/(s² + d²) <= s_hi/R², R² the least s² + d² on it, which bounds the rest. When the
/// box reaches the origin (R = 0: the enclosures allow a zero vector) the result is unbounded.
template <class E, class T = decltype(E::mid)>
E enclosed_angle_deg(const std::array<E, 3>& a, const std::array<E, 3>& b) {
  constexpr T u = E::u;
  std::array<E, 3> c;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    c[static_cast<std::size_t>(k)] = a[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(j)] -
                                     a[static_cast<std::size_t>(j)] * b[static_cast<std::size_t>(i)];
  }
  T s_lo, s_hi;
  internal::norm_bounds(c, s_lo, s_hi);
  const E d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  if (!std::isfinite(s_hi) || !d.finite()) return {0, E::unbounded};
  const T d_lo = d.lo(), d_hi = d.hi();
  const T d_min = d_lo > 0 ? d_lo : d_hi < 0 ? -d_hi : 0, d_max = std::max(std::fabs(d_lo), std::fabs(d_hi));
  const T r2 = (s_lo * s_lo + d_min * d_min) * (1 - 4 * u);
  if (!(r2 > 0)) return {0, E::unbounded};
  const T s_mid = s_lo + (s_hi - s_lo) / 2;
  const T ds = (s_hi - s_lo) / 2 * (1 + 4 * u) + u * s_hi, dd = d.rad + u * std::fabs(d.mid);
  const T theta = std::atan2(s_mid, d.mid);  // radians, within one ulp (2u relative)
  const T spread = (d_max * ds + s_hi * dd) / r2 * (1 + 32 * u) + std::fabs(theta) * 8 * u +
                   std::numeric_limits<T>::min();
  const T mid = theta * degrees_per_radian<T>;  // 180/π and the product: two more roundings
  return {mid, E::round_up(spread * degrees_per_radian<T> * (1 + 8 * u) + std::fabs(mid) * 4 * u)};
}

}  // namespace gmcc::internal
