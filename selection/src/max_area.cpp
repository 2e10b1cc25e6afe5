#include <gmcc/selection/max_area.h>

#include <stdexcept>

namespace gmcc {

Point2 max_area_point(const ConvexSet2& F) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("max_area: empty feasible set");
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
