#include <gmcc/selection/max_area.h>

#include "internal/ld_interval.h"
#include "internal/max_area_candidates.h"
#include "internal/max_area_route.h"

#include <optional>
#include <stdexcept>
#include <vector>

namespace gmcc {
namespace internal {
namespace {

// F's candidates (max_area_candidates.h) from its exact vertices, in number type `Kind`: on each
// edge p → q of the north-east chain the stationary point of the concave
// f(t) = (p1 + t·Δa)(p2 + t·Δb) lies inside the edge iff f′(0) = Δa·p2 + Δb·p1 > 0 > f′(1) =
// Δa·q2 + Δb·q1, and f(t*) = p1·p2 − f′(0)²/(4·Δa·Δb). `Kind` gives N's values: x(i), y(i), dx(i, j),
// dy(i, j) (the coordinate differences, from the exact values), constant(int), and
// sign(N) → numerics::UncertainSign (the family's one decision type; Rational always decides).
template <class Kind>
struct VertexCandidates {
  using Number = typename Kind::Number;
  const std::vector<Point2>& v;
  const Kind& k;
  Number product(std::size_t i) const { return k.x(i) * k.y(i); }
  std::optional<std::optional<Number>> stationary(std::size_t i, std::size_t j) const {
    if (cmp(v[j].x, v[i].x) * cmp(v[j].y, v[i].y) >= 0) return std::optional<Number>{};  // an end
    const Number da = k.dx(i, j), db = k.dy(i, j);
    const Number d0 = da * k.y(i) + db * k.x(i), d1 = da * k.y(j) + db * k.x(j);
    const numerics::UncertainSign s0 = Kind::sign(d0), s1 = Kind::sign(d1);
    if (!s0.is_certain() || !s1.is_certain()) return std::nullopt;
    if (!(numerics::certainly_positive(s0) && numerics::certainly_negative(s1))) return std::optional<Number>{};
    return std::optional<Number>{Number(k.x(i) * k.y(i) - d0 * d0 / (Kind::constant(4) * (da * db)))};
  }
};
template <class Kind>
auto candidates(const ConvexSet2& F, const Kind& k) {
  // A segment has one edge; a polygon n edges (a segment's "second edge" is the same edge).
  const std::size_t n = F.vertices.size(), edges = F.kind == ConvexKind::polygon ? n : n - 1;
  return area_candidates(n, edges, VertexCandidates<Kind>{F.vertices, k});
}

// The point a candidate stands for, exactly: vertex, or p + t*·(Δa, Δb) with t* = −f′(0)/(2·Δa·Δb).
Point2 candidate_point(const ConvexSet2& F, std::size_t index) {
  const auto& v = F.vertices;
  const std::size_t n = v.size();
  if (index < n) return v[index];
  const Point2& p = v[index - n];
  const Point2& q = v[(index - n + 1) % n];
  const Rational da = q.x - p.x, db = q.y - p.y;
  const Rational t = -(da * p.y + db * p.x) / (2 * da * db);
  return Point2{Rational(p.x + t * da), Rational(p.y + t * db)};
}

// F's coordinates in ℚ.
struct ExactKind {
  using Number = Rational;
  const std::vector<Point2>& v;
  const Rational& x(std::size_t i) const { return v[i].x; }
  const Rational& y(std::size_t i) const { return v[i].y; }
  Rational dx(std::size_t i, std::size_t j) const { return v[j].x - v[i].x; }
  Rational dy(std::size_t i, std::size_t j) const { return v[j].y - v[i].y; }
  static Rational constant(int c) { return c; }
  static numerics::UncertainSign sign(const Rational& q) { return numerics::UncertainSign::certain(sgn(q)); }
};

// F's coordinates as x87 intervals, differences enclosed from their exact values (integer
// cross-multiplication, no gcd): no cancellation on short edges.
struct ExtendedKind {
  using Number = LDInterval;
  const std::vector<Point2>& v;
  std::vector<LDInterval> xs, ys;
  explicit ExtendedKind(const std::vector<Point2>& vertices) : v(vertices) {
    for (const Point2& p : v) xs.push_back(enclose_ld(p.x)), ys.push_back(enclose_ld(p.y));
  }
  LDInterval x(std::size_t i) const { return xs[i]; }
  LDInterval y(std::size_t i) const { return ys[i]; }
  static LDInterval difference(const Rational& p, const Rational& q) {
    const mpz_class num = p.get_num() * q.get_den() - q.get_num() * p.get_den();
    const mpz_class den = p.get_den() * q.get_den();
    return enclose_ld(num.get_mpz_t(), den.get_mpz_t());
  }
  LDInterval dx(std::size_t i, std::size_t j) const { return difference(v[j].x, v[i].x); }
  LDInterval dy(std::size_t i, std::size_t j) const { return difference(v[j].y, v[i].y); }
  static LDInterval constant(int c) { return {static_cast<long double>(c), static_cast<long double>(c)}; }
  static numerics::UncertainSign sign(const LDInterval& a) { return numerics::sign(a); }
};

StageCounts& counts() {
  static StageCounts c;
  return c;
}

}  // namespace

std::optional<Point2> max_area_filtered(const ConvexSet2& F) {
  const auto c = candidates(F, ExtendedKind(F.vertices));
  if (!c) return std::nullopt;
  const auto best = unique_maximum(*c);
  if (!best) return std::nullopt;
  return candidate_point(F, (*c)[*best].index);
}

Point2 max_area_exact(const ConvexSet2& F) {
  const auto c = *candidates(F, ExactKind{F.vertices});  // ℚ decides every sign
  std::size_t best = 0;
  Point2 best_point = candidate_point(F, c[0].index);
  for (std::size_t k = 1; k < c.size(); ++k) {
    const int order = cmp(c[k].value, c[best].value);
    if (order < 0) continue;
    Point2 p = candidate_point(F, c[k].index);
    if (order > 0 || p < best_point) best = k, best_point = std::move(p);
  }
  return best_point;
}

const StageCounts& max_area_stage_counts() { return counts(); }

}  // namespace internal

Point2 max_area_point(const ConvexSet2& F) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("max_area: empty feasible set");
  return internal::staged(
      internal::counts(),
      [&F]() -> std::optional<Point2> {
        return numerics::extended_precision_active() ? internal::max_area_filtered(F) : std::nullopt;
      },
      [&F] { return internal::max_area_exact(F); });
}

MapEstimate max_area(const ConvexSet2& F) { return exact_map_estimate("max_area", max_area_point(F)); }

}  // namespace gmcc
