#pragma once
// The 3-D mean's closed form τ = ½ Σ θ_i c_i/|c_i| (docs/derivations.md §1.2) in midpoint–radius
// enclosures (geometry/enclosure.h), generic in their precision: doubles for rule_errors' first
// stage, x87 extended precision for its second stage and for mean_3d_analytic's fast path. Internal
// to gmcc::selection.

#include <gmcc/geometry/enclosure.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace gmcc::internal {

// |x| for x in the enclosure: [max(0, |mid| − rad), |mid| + rad], made certain.
template <class E, class T = decltype(E::mid)>
T abs_lo(const E& x) { return std::max(T(0), std::fabs(x.mid) - x.rad) * (1 - 4 * E::u); }
template <class E, class T = decltype(E::mid)>
T abs_hi(const E& x) { return (std::fabs(x.mid) + x.rad) * (1 + 4 * E::u) + std::numeric_limits<T>::min(); }

// |u×v| ∈ [s_lo, s_hi] from the components' enclosures: three products and two sums of
// non-negatives (a relative 6u, covered by 8u), a square root and a product (2u more).
template <class E, class T = decltype(E::mid)>
void norm_bounds(const std::array<E, 3>& c, T& s_lo, T& s_hi) {
  T s2_lo = 0, s2_hi = 0;
  for (const E& ck : c) {
    const T lo = abs_lo(ck), hi = abs_hi(ck);
    s2_lo += lo * lo, s2_hi += hi * hi;
  }
  s_lo = std::sqrt(s2_lo * (1 - 8 * E::u)) * (1 - 2 * E::u);
  s_hi = std::isfinite(s2_hi) ? std::sqrt(s2_hi * (1 + 8 * E::u)) * (1 + 2 * E::u) + std::numeric_limits<T>::min()
                              : E::unbounded;
}

// g(s, d) = θ/s = atan2(s, d)/s for d > 0 (1/d at s = 0), enclosed from one evaluation at the
// box's centre. With t = s/d, g = h(t)/d for h(t) = atan(t)/t: |h′| < 0.2923 on t >= 0 (its
// maximum, checked numerically on a fine grid), so |∂g/∂s| = |h′|/d² < 0.3/d², and
// ∂g/∂d = −(t·h)′/d² = −1/((1 + t²)·d²), at most 1/d² in size. libm's atan2 (one ulp) and the
// division: a relative 8u covers them.
template <class E, class T = decltype(E::mid)>
E theta_over_s(T s_lo, T s_hi, const E& d) {
  constexpr T u = E::u;
  const T d_lo = d.lo();
  const T s_mid = s_lo + (s_hi - s_lo) / 2;
  const T ds = (s_hi - s_lo) / 2 * (1 + 4 * u) + u * s_hi, dd = d.rad + u * std::fabs(d.mid);
  const T g = s_mid > 0 ? std::atan2(s_mid, d.mid) / s_mid : 1 / d.mid;
  return {g, E::round_up((T(0.3) * ds + dd) / (d_lo * d_lo) * (1 + 32 * u) + g * 8 * u)};
}

template <class E, class V>
std::optional<std::array<E, 2>> mean_3d_direction(const std::vector<V>& v) {
  using T = decltype(E::mid);
  // τ = ½ Σ θ_i c_i/|c_i| with c_i = p_i × p_{i+1}, p = (x, y, 1) (docs/derivations.md §1.2); the ½
  // and the orientation cancel in (τ1/τ3, τ2/τ3). c_i from the edge e = p_{i+1} − p_i:
  // (−e_y, e_x, x_i·e_y − y_i·e_x), exact in direction however short the edge.
  std::array<E, 3> tau{};
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const V& p = v[i];
    const V& q = v[(i + 1) % n];
    const E ex = q.x - p.x, ey = q.y - p.y;
    const std::array<E, 3> c{-ey, ex, p.x * ey - p.y * ex};
    T s_lo, s_hi;
    norm_bounds(c, s_lo, s_hi);
    const E d = p.x * q.x + p.y * q.y + E::exact(1);
    if (!d.finite() || !d.positive() || !std::isfinite(s_hi)) return std::nullopt;
    const E g = theta_over_s(s_lo, s_hi, d);
    for (int k = 0; k < 3; ++k) tau[k] = tau[k] + g * c[k];
  }
  if (!tau[0].finite() || !tau[1].finite() || !tau[2].finite() || tau[2].uncertain_sign()) return std::nullopt;
  return std::array<E, 2>{tau[0] / tau[2], tau[1] / tau[2]};
}

}  // namespace gmcc::internal
