#pragma once
// The 3-D mean's closed form τ = ½ Σ θ_i c_i/|c_i| (docs/derivations.md §1.2), written once for
// every number type it is evaluated in: the sum over the edges and the final ratio are
// tau_direction(); what differs by kind is only how an edge's c_i and its weight θ_i/|c_i| are
// enclosed (TauTerm). mean_3d_analytic uses x87 intervals (LDInterval) and MPFI, from vertex
// enclosures, from exactly formed edges or from exact products; certified_rule_errors uses midpoint–radius
// enclosures (geometry/enclosure.h) in doubles and x87 extended precision. Internal to
// gmcc::selection.

#include <gmcc/geometry/rational_enclosure.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace gmcc::internal {

/// One edge's share of τ in number type K: c_i = p_i × p_{i+1} for the lifted vertices
/// p = (x, y, 1), and its weight θ_i/|c_i| = atan2(|c_i|, p_i·p_{i+1})/|c_i|.
template <class K>
struct TauTerm {
  std::array<K, 3> c;
  K weight;
};

/// c_i from the edge e = p_{i+1} − p_i: (−e_y, e_x, x_i·e_y − y_i·e_x), exact in direction
/// however short the edge (no cancellation between two close vertices).
template <class K>
std::array<K, 3> cross_from_edge(const K& x, const K& y, const K& ex, const K& ey) {
  return {-ey, ex, x * ey - y * ex};
}

/// c_i from both vertices: (y_i − y_j, x_j − x_i, x_i·y_j − y_i·x_j).
template <class K>
std::array<K, 3> cross_from_vertices(const K& xi, const K& yi, const K& xj, const K& yj) {
  return {yi - yj, xj - xi, xi * yj - yi * xj};
}

/// θ/|c| = atan2(|c|, d)/|c| in an interval kind (LDInterval, MPFI) from |c|'s enclosure.
template <class K>
K theta_over_norm(const K& norm, const K& d) {
  return atan2(norm, d) / norm;
}

/// The same from c's components: |c| = √(c0² + c1² + c2²).
template <class K>
K theta_over_norm(const std::array<K, 3>& c, const K& d) {
  return theta_over_norm(sqrt(sqr(c[0]) + sqr(c[1]) + sqr(c[2])), d);
}

namespace detail {
template <class K>
const TauTerm<K>* engaged(const TauTerm<K>& t) { return &t; }
template <class K>
const TauTerm<K>* engaged(const std::optional<TauTerm<K>>& t) { return t ? &*t : nullptr; }
}  // namespace detail

/// τ = Σ w_i c_i of an n-gon, summed in K from zero (the ½ dropped: it cancels in the
/// direction, as does the orientation's sign). `term(i)` gives edge i's TauTerm, or nothing (an
/// empty std::optional) when K cannot enclose it, and then so is the sum.
template <class K, class Term>
std::optional<std::array<K, 3>> tau_sum(std::size_t n, const K& zero, Term&& term) {
  std::optional<std::array<K, 3>> tau{std::array<K, 3>{zero, zero, zero}};
  for (std::size_t i = 0; i < n; ++i) {
    const auto t = term(i);
    const TauTerm<K>* e = detail::engaged<K>(t);
    if (!e) return std::nullopt;
    for (std::size_t k = 0; k < 3; ++k) (*tau)[k] = (*tau)[k] + e->weight * e->c[k];
  }
  return tau;
}

/// The 3-D mean's perspective map (τ1/τ3, τ2/τ3).
template <class K>
std::array<K, 2> tau_direction(const std::array<K, 3>& tau) {
  return {tau[0] / tau[2], tau[1] / tau[2]};
}

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

/// The 3-D mean's map (τ1/τ3, τ2/τ3) in midpoint–radius enclosures E from vertex enclosures v
/// (each with members x, y of type E), c_i from the edges; nothing when an edge's p_i·p_{i+1} or
/// τ3 is not certainly positive, or anything overflows.
template <class E, class V>
std::optional<std::array<E, 2>> mean_3d_direction(const std::vector<V>& v) {
  using T = decltype(E::mid);
  const std::size_t n = v.size();
  const auto tau = tau_sum<E>(n, E{}, [&](std::size_t i) -> std::optional<TauTerm<E>> {
    const V& p = v[i];
    const V& q = v[(i + 1) % n];
    const std::array<E, 3> c = cross_from_edge<E>(p.x, p.y, q.x - p.x, q.y - p.y);
    T s_lo, s_hi;
    norm_bounds(c, s_lo, s_hi);
    const E d = p.x * q.x + p.y * q.y + E::exact(1);
    if (!d.finite() || !certainly_positive(d) || !std::isfinite(s_hi)) return std::nullopt;
    return TauTerm<E>{c, theta_over_s(s_lo, s_hi, d)};
  });
  if (!tau) return std::nullopt;
  const std::array<E, 3>& t = *tau;
  if (!t[0].finite() || !t[1].finite() || !t[2].finite() || !certainly_nonzero(t[2])) return std::nullopt;
  return tau_direction(t);
}

}  // namespace gmcc::internal
