#pragma once
// One rule's certified values from F's vertex enclosures (Finlayson & Hordley 1999 §3, §4): its
// map, the map-space worst case and, given the true map, the map, illuminant and reproduction
// errors, in midpoint–radius enclosures E (doubles, or x87 extended precision for thin sets).
// Written once for certified_rule_errors.cpp (the experiments' angles) and scene_record.cpp
// (the batch record). Internal to gmcc::selection.

#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/selection/certified_rule_errors.h>
#include <gmcc/selection/rule.h>
#include <gmcc/numerics/filtered_sign.h>

#include "angle.h"
#include "closed_form.h"
#include "ld_interval.h"
#include "max_area_candidates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace gmcc::internal {
// Everything below is generic in the enclosure type E: doubles first, x87 extended precision as
// a second stage for thin feasible sets. T is its number type, u its unit roundoff; every pad is
// a multiple of u.

// An exact rational as an enclosure, under the range policy of numerics/rational_to_float.h.
// Doubles: enclose_rational (enclosure.h; an unbounded enclosure outside the policy, which no
// result accepts). Extended: numerator and denominator's top 64 bits and a division
// (enclose_ld, from numerics::certified_extended).
template <class E>
E enclose(const Rational& q);
template <>
inline Enclosure enclose<Enclosure>(const Rational& q) {
  return enclose_rational(q);
}
template <>
inline LongEnclosure enclose<LongEnclosure>(const Rational& q) {
  if (sgn(q) == 0) return LongEnclosure::exact(0);
  const LDInterval i = enclose_ld(q);
  return LongEnclosure::between(i.lo, i.hi);
}

// The edges' lines are double approximations (each coefficient within 6·2^-53 of the same
// positive multiple of the exact line), whatever E is.
inline constexpr double line_error = 6 * numerics::unit_roundoff;

// Max-area's candidates (max_area_candidates.h) from F's vertex enclosures v and edge lines: the
// edge a·x + b·y = c has Δx·Δy < 0 iff a·b > 0, and there m1·m2 is concave along it with its
// stationary point at (c/2a, c/2b), value c²/4ab — formed from the line, so that a short edge
// costs no cancellation. Inside the edge iff x − p.x and x − q.x have opposite signs.
template <class E, class V>
struct EdgeLineCandidates {
  using Number = E;
  const std::vector<V>& v;
  const std::vector<ApproximateLine>& edges;

  E product(std::size_t i) const { return v[i].x * v[i].y; }
  // The stationary point (x, y) of edge i, when its line is on the north-east chain.
  std::optional<std::array<E, 3>> point(std::size_t i) const {
    const ApproximateLine& l = edges[i];
    if (!((l.a > 0 && l.b > 0) || (l.a < 0 && l.b < 0))) return std::nullopt;
    const E a = E::relative(l.a, line_error), b = E::relative(l.b, line_error), k = E::relative(l.c, line_error);
    return std::array<E, 3>{k / (E::exact(2) * a), k / (E::exact(2) * b), k * k / (E::exact(4) * a * b)};
  }
  std::optional<std::optional<E>> stationary(std::size_t i, std::size_t j) const {
    const auto s = point(i);
    if (!s) return std::optional<E>{};
    const E to_p = (*s)[0] - v[i].x, to_q = (*s)[0] - v[j].x;  // strictly inside iff opposite signs
    if (!certainly_nonzero(to_p) || !certainly_nonzero(to_q)) return std::nullopt;
    if (certainly_positive(to_p) == certainly_positive(to_q)) return std::optional<E>{};
    return std::optional<E>{(*s)[2]};
  }
};

template <class E, class V>
std::optional<std::array<E, 2>> max_area_map(const std::vector<V>& v, const std::vector<ApproximateLine>& edges) {
  const EdgeLineCandidates<E, V> kind{v, edges};
  const auto c = area_candidates(v.size(), v.size(), kind);
  if (!c) return std::nullopt;
  for (const auto& k : *c)
    if (!k.value.finite()) return std::nullopt;
  const auto best = unique_maximum(*c);
  if (!best) return std::nullopt;
  const std::size_t index = (*c)[*best].index;
  if (index < v.size()) return std::array<E, 2>{v[index].x, v[index].y};
  const auto s = *kind.point(index - v.size());
  return std::array<E, 2>{s[0], s[1]};
}

template <class E, class V>
std::optional<std::array<E, 2>> centroid(const std::vector<V>& v) {
  // The fan from vertex 0, in offsets from it: Σ w_i (d_i + d_{i+1})/3 / Σ w_i.
  E w_sum{}, x_sum{}, y_sum{};
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const E ax = v[i].x - v[0].x, ay = v[i].y - v[0].y, bx = v[i + 1].x - v[0].x, by = v[i + 1].y - v[0].y;
    const E w = ax * by - ay * bx;
    w_sum = w_sum + w, x_sum = x_sum + w * (ax + bx), y_sum = y_sum + w * (ay + by);
  }
  if (!certainly_positive(w_sum)) return std::nullopt;
  const E den = E::exact(3) * w_sum;
  return std::array<E, 2>{v[0].x + x_sum / den, v[0].y + y_sum / den};
}

// Within the stated accuracy, counting the final rounding of the midpoint to double (2^-53).
template <class E>
bool accurate(const E& angle) {
  const auto a = std::fabs(angle.mid);
  return angle.finite() && angle.rad + a * 0x1p-52 <= rule_errors_accuracy * (1 + a);
}

// The range the double analysis is made for: magnitudes within [2^-100, 2^100] (or 0), far from
// overflow in products of four and from underflow; anything else goes to the exact route.
template <class E>
bool in_range(const E& x) {
  const auto a = std::fabs(x.mid);
  return x.finite() && (a == 0 || (a >= 0x1p-100 && a <= 0x1p100)) && x.rad <= 0x1p100;
}

// Each rule's map in enclosures of type E from F's vertex enclosures v and edge lines: nothing
// when it is not certain, or the rule has no certified form.
template <class E, class V>
std::optional<std::array<E, 2>> certified_map(Rule rule, const std::vector<V>& v, const std::vector<ApproximateLine>& edges) {
  switch (rule) {
    case Rule::max_area: return max_area_map<E>(v, edges);
    case Rule::mean_2d: return centroid<E>(v);
    case Rule::mean_3d: return mean_3d_direction<E>(v);
  }
  return std::nullopt;  // a rule with no certified form: the caller takes the exact route
}

/// One rule's values (docs: certified_rule_errors.h), each an enclosure of the exact value at
/// the rule's exact map; error, illuminant and reproduction only with a truth, the last two only
/// for a certainly positive map.
template <class E>
struct CertifiedRule {
  std::array<E, 2> map;
  E worst;  // the map-space worst case, degrees
  bool positive_map = false;
  std::optional<E> error, illuminant, reproduction;
};

/// `rule`'s values from F's vertex enclosures v and edge lines, the true map t (when scored) and
/// the canonical illuminant c, all enclosed: nothing when a decision is uncertain or an angle is
/// wider than rule_errors_accuracy. `keys` is scratch space.
template <class E, class V>
std::optional<CertifiedRule<E>> certified_rule(Rule rule, const std::vector<V>& v, const std::vector<ApproximateLine>& edges,
                                               const std::optional<std::array<E, 2>>& t, const std::array<E, 3>& c,
                                               std::vector<E>& keys) {
  using T = decltype(E::mid);
  const std::optional<std::array<E, 2>> map = certified_map<E>(rule, v, edges);
  if (!map) return std::nullopt;
  const E m1 = (*map)[0], m2 = (*map)[1], one = E::exact(1);
  if (!in_range(m1) || !in_range(m2) || !certainly_nonzero(m1) || !certainly_nonzero(m2)) return std::nullopt;
  CertifiedRule<E> out;
  out.map = *map;
  const std::array<E, 3> lifted{m1, m2, one};
  if (t) out.error = enclosed_angle_deg<E>(lifted, {(*t)[0], (*t)[1], one});
  // Worst case: every vertex at an acute angle to the map (u·v > 0), so the maximum is at a
  // vertex (docs/derivations.md §3.1). There the angle falls as (u·v)²/|v|² rises (|u| is
  // common): only vertices whose key may be the least need their angle; the enclosure of a
  // maximum is the maximum of the ends.
  keys.clear();
  T least_hi = E::unbounded;
  for (const V& p : v) {
    const E dot = m1 * p.x + m2 * p.y + one;
    if (!certainly_positive(dot)) return std::nullopt;
    keys.push_back(dot * dot / (p.x * p.x + p.y * p.y + one));
    least_hi = std::min(least_hi, keys.back().hi());
  }
  T worst_lo = 0, worst_hi = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (keys[i].lo() > least_hi) continue;  // certainly a smaller angle than another vertex's
    const E a = enclosed_angle_deg<E>(lifted, {v[i].x, v[i].y, one});
    worst_lo = std::max(worst_lo, a.lo()), worst_hi = std::max(worst_hi, a.hi());
  }
  out.worst = E::between(worst_lo, worst_hi);
  if ((out.error && !accurate(*out.error)) || !accurate(out.worst)) return std::nullopt;
  out.positive_map = certainly_positive(m1) && certainly_positive(m2);
  if (out.positive_map && t) {  // e = c ⊘ (m, 1); the reproduction error compares d_est ⊘ d_true with white
    const E t1 = (*t)[0], t2 = (*t)[1];
    out.illuminant = enclosed_angle_deg<E>({c[0] / m1, c[1] / m2, c[2]}, {c[0] / t1, c[1] / t2, c[2]});
    out.reproduction = enclosed_angle_deg<E>({m1 / t1, m2 / t2, one}, {one, one, one});
    if (!accurate(*out.illuminant) || !accurate(*out.reproduction)) return std::nullopt;
  }
  return out;
}

}  // namespace gmcc::internal
