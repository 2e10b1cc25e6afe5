#include <gmcc/selection/certified_rule_errors.h>

#include "internal/angle.h"
#include "internal/closed_form.h"
#include "internal/max_area_candidates.h"
#include "internal/ld_interval.h"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace gmcc {
namespace {
// Everything below is generic in the enclosure type E: doubles first, x87 extended precision as
// a second stage for thin feasible sets. T is its number type, u its unit roundoff; every pad is
// a multiple of u.

// An exact rational as an enclosure, under the range policy of numerics/rational_to_float.h.
// Doubles: enclose_rational (enclosure.h; an unbounded enclosure outside the policy, which no
// result accepts). Extended: numerator and denominator's top 64 bits and a division
// (internal::enclose_ld, from numerics::certified_extended).
template <class E>
E enclose(const Rational& q);
template <>
Enclosure enclose<Enclosure>(const Rational& q) {
  return enclose_rational(q);
}
template <>
LongEnclosure enclose<LongEnclosure>(const Rational& q) {
  if (sgn(q) == 0) return LongEnclosure::exact(0);
  const internal::LDInterval i = internal::enclose_ld(q);
  return LongEnclosure::between(i.lo, i.hi);
}

// The edges' lines are double approximations (each coefficient within 6·2^-53 of the same
// positive multiple of the exact line), whatever E is.
constexpr double line_error = 6 * 0x1p-53;

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
  const auto c = internal::area_candidates(v.size(), v.size(), kind);
  if (!c) return std::nullopt;
  for (const auto& k : *c)
    if (!k.value.finite()) return std::nullopt;
  const auto best = internal::unique_maximum(*c);
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
    case Rule::mean_3d: break;
  }
  return internal::mean_3d_direction<E>(v);
}

// One stage: every value in enclosures of type E, from F's vertex enclosures v.
template <class E, class V>
std::optional<PerRule<RuleErrors>> stage(const std::vector<V>& v, const std::vector<ApproximateLine>& edges,
                                               const Point2& truth, const Colour& canonical_illuminant) {
  using T = decltype(E::mid);
  for (const V& p : v)
    if (!in_range(p.x) || !in_range(p.y)) return std::nullopt;
  const E t1 = enclose<E>(truth.x), t2 = enclose<E>(truth.y), one = E::exact(1);
  const E cr = enclose<E>(canonical_illuminant.r), cg = enclose<E>(canonical_illuminant.g),
          cb = enclose<E>(canonical_illuminant.b);
  for (const E* x : {&t1, &t2, &cr, &cg, &cb})
    if (!in_range(*x)) return std::nullopt;
  PerRule<RuleErrors> out{};
  std::vector<E> keys;
  keys.reserve(v.size());
  for (Rule r : all_rules) {
    const std::optional<std::array<E, 2>> map = certified_map<E>(r, v, edges);
    if (!map) return std::nullopt;
    const E m1 = (*map)[0], m2 = (*map)[1];
    if (!in_range(m1) || !in_range(m2) || !certainly_nonzero(m1) || !certainly_nonzero(m2)) return std::nullopt;
    const std::array<E, 3> lifted{m1, m2, one};
    const E error = internal::enclosed_angle_deg<E>(lifted, {t1, t2, one});
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
      const E a = internal::enclosed_angle_deg<E>(lifted, {v[i].x, v[i].y, one});
      worst_lo = std::max(worst_lo, a.lo()), worst_hi = std::max(worst_hi, a.hi());
    }
    const E worst = E::between(worst_lo, worst_hi);
    if (!accurate(error) || !accurate(worst)) return std::nullopt;
    RuleErrors& e = out[r];
    e.map_error_deg = static_cast<double>(error.mid);
    e.worst_case_deg = static_cast<double>(worst.mid);
    e.map = {static_cast<double>(m1.mid), static_cast<double>(m2.mid)};
    e.positive_map = certainly_positive(m1) && certainly_positive(m2);
    if (e.positive_map) {  // e = c ⊘ (m, 1); the reproduction error compares d_est ⊘ d_true with white
      const E illuminant = internal::enclosed_angle_deg<E>({cr / m1, cg / m2, cb}, {cr / t1, cg / t2, cb});
      const E reproduction = internal::enclosed_angle_deg<E>({m1 / t1, m2 / t2, one}, {one, one, one});
      if (!accurate(illuminant) || !accurate(reproduction)) return std::nullopt;
      e.illuminant_error_deg = static_cast<double>(illuminant.mid);
      e.reproduction_error_deg = static_cast<double>(reproduction.mid);
    }
  }
  return out;
}

}  // namespace

std::optional<PerRule<RuleErrors>> certified_rule_errors(const FeasiblePolygon& F, const Point2& truth,
                                                        const Colour& canonical_illuminant) {
  for (const Rational* x : {&truth.x, &truth.y, &canonical_illuminant.r, &canonical_illuminant.g, &canonical_illuminant.b})
    if (sgn(*x) <= 0) throw std::invalid_argument("certified_rule_errors: the true map and the illuminant must be > 0");
  if (!F.enclosed()) return std::nullopt;
  if (auto out = stage<Enclosure>(F.vertices(), F.edges(), truth, canonical_illuminant)) return out;
  // Thin sets (F ∩ C along the daylight locus, small cones): the same in extended precision,
  // from vertex enclosures about 2^11 times tighter.
  if (numerics::extended_precision_active() && !F.extended_vertices().empty())
    return stage<LongEnclosure>(F.extended_vertices(), F.edges(), truth, canonical_illuminant);
  return std::nullopt;
}

}  // namespace gmcc
