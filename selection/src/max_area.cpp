#include <gmcc/selection/max_area.h>

#include "internal/ld_interval.h"

#include <optional>
#include <stdexcept>
#include <vector>

namespace gmcc {
namespace {
using internal::LDInterval;

// p − q enclosed from its exact value (integer cross-multiplication, no gcd).
LDInterval enclose_difference(const Rational& p, const Rational& q) {
  const mpz_class num = p.get_num() * q.get_den() - q.get_num() * p.get_den();
  const mpz_class den = p.get_den() * q.get_den();
  return internal::enclose_ld(num.get_mpz_t(), den.get_mpz_t());
}

bool positive(const LDInterval& x) { return x.lo > 0; }
bool negative(const LDInterval& x) { return x.hi < 0; }

// The filter: every candidate's m1·m2 enclosed in extended-precision intervals. When one
// candidate's enclosure lies strictly above all others', it is the unique maximum and only it is
// constructed exactly (the same formula as below, so the same rational). Nothing when any
// decision is uncertain (near-ties, stationary points at an edge's end).
std::optional<Point2> max_area_filtered(const ConvexSet2& F) {
  const auto& v = F.vertices;
  const std::size_t n = v.size();
  std::vector<LDInterval> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = internal::enclose_ld(v[i].x), y[i] = internal::enclose_ld(v[i].y);
  struct Candidate {
    LDInterval value;
    std::size_t index;  // a vertex, or the edge from vertex index − n
  };
  std::vector<Candidate> candidates;
  candidates.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) candidates.push_back({x[i] * y[i], i});
  const std::size_t edges = F.kind == ConvexKind::polygon ? n : n - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const std::size_t j = (i + 1) % n;
    const int sa = cmp(v[j].x, v[i].x), sb = cmp(v[j].y, v[i].y);
    if (sa * sb >= 0) continue;  // not on the north-east chain: the maximum is at an end
    const LDInterval da = enclose_difference(v[j].x, v[i].x), db = enclose_difference(v[j].y, v[i].y);
    // f(t) = (p1 + t·Δa)(p2 + t·Δb) is concave: t* ∈ (0, 1) iff f′(0) > 0 > f′(1).
    const LDInterval d0 = da * y[i] + db * x[i], d1 = da * y[j] + db * x[j];
    if (!(positive(d0) || negative(d0)) || !(positive(d1) || negative(d1))) return std::nullopt;
    if (!(positive(d0) && negative(d1))) continue;
    // f(t*) = f(0) − f′(0)² / (4·Δa·Δb)
    const LDInterval four_dd = LDInterval{4, 4} * (da * db);
    candidates.push_back({x[i] * y[i] - d0 * d0 / four_dd, n + i});
  }
  std::size_t best = 0;
  for (std::size_t k = 1; k < candidates.size(); ++k)
    if (candidates[k].value.lo > candidates[best].value.lo) best = k;
  for (std::size_t k = 0; k < candidates.size(); ++k)
    if (k != best && candidates[k].value.hi >= candidates[best].value.lo) return std::nullopt;
  const std::size_t w = candidates[best].index;
  if (w < n) return v[w];
  const Point2& p = v[w - n];
  const Point2& q = v[(w - n + 1) % n];
  const Rational da = q.x - p.x, db = q.y - p.y;
  const Rational t = -(da * p.y + db * p.x) / (2 * da * db);
  return Point2{Rational(p.x + t * da), Rational(p.y + t * db)};
}
}  // namespace

Point2 max_area_point(const ConvexSet2& F) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("max_area: empty feasible set");
  if (internal::fast_path_available())
    if (auto p = max_area_filtered(F)) return std::move(*p);
  const auto& v = F.vertices;
  Point2 best = v[0];
  Rational best_value = best.x * best.y;
  auto consider = [&](Point2 p) {
    const Rational value = p.x * p.y;
    if (value > best_value || (value == best_value && p < best)) {
      best_value = value;
      best = std::move(p);
    }
  };
  for (const Point2& p : v) consider(p);
  // A segment has one edge; a polygon n edges (a segment's "second edge" is the same edge).
  const std::size_t edges = F.kind == ConvexKind::polygon ? v.size() : v.size() - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const Point2& p = v[i];
    const Point2& q = v[(i + 1) % v.size()];
    const Rational da = q.x - p.x, db = q.y - p.y;
    const Rational dd = da * db;
    if (sgn(dd) >= 0) continue;  // not on the north-east chain: the maximum is at an end
    const Rational t = -(da * p.y + db * p.x) / (2 * dd);
    if (sgn(t) > 0 && t < 1) consider({Rational(p.x + t * da), Rational(p.y + t * db)});
  }
  return best;
}

MapEstimate max_area(const ConvexSet2& F) { return exact_map_estimate("max_area", max_area_point(F)); }

}  // namespace gmcc
