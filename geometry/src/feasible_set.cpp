#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>

#include "internal/half_plane.h"

#include <algorithm>

namespace gmcc {

ConvexSet2 feasible_set(const ConvexSet2& canonical, const std::vector<Point2>& image) {
  if (canonical.kind == ConvexKind::empty)
    throw std::invalid_argument("feasible_set: the canonical gamut is empty");
  if (image.empty()) throw std::invalid_argument("feasible_set: no image chromaticities");
  for (const Point2& q : image)
    if (sgn(q.x) < 0 || sgn(q.y) < 0)
      throw std::invalid_argument("feasible_set: an image chromaticity is negative");

  // Only the image hull's vertices constrain F (interior colours add implied constraints).
  const ConvexSet2 image_hull = convex_hull(image);
  const auto& qs = image_hull.vertices;

  auto max_of = [](const std::vector<Point2>& ps, Rational Point2::*c) {
    Rational m = ps.front().*c;
    for (const Point2& p : ps) m = std::max(m, p.*c);
    return m;
  };
  const Rational q1 = max_of(qs, &Point2::x), q2 = max_of(qs, &Point2::y);
  if (sgn(q1) == 0)
    throw UnboundedFeasibleSet("every image colour has r = 0: the map's red component is "
                               "unconstrained and the feasible set is unbounded");
  if (sgn(q2) == 0)
    throw UnboundedFeasibleSet("every image colour has g = 0: the map's green component is "
                               "unconstrained and the feasible set is unbounded");

  // The box [0, X/Q1] × [0, Y/Q2] contains F: for q with q1 = Q1 > 0, m1·Q1 is the first
  // coordinate of a point of G_c, so 0 <= m1·Q1 <= X (likewise m2). Clip it to F.
  const Rational x_max = max_of(canonical.vertices, &Point2::x) / q1;
  const Rational y_max = max_of(canonical.vertices, &Point2::y) / q2;
  std::vector<Point2> cycle{{0, 0}, {x_max, 0}, {x_max, y_max}, {0, y_max}};

  const std::vector<internal::HalfPlane> gamut = internal::half_planes(canonical);
  for (const Point2& q : qs) {
    for (const internal::HalfPlane& h : gamut) {
      // m ⊙ q ∈ {a·x + b·y <= c}  ⟺  (a·q1)·m1 + (b·q2)·m2 <= c
      cycle = internal::clip(cycle, {Rational(h.a * q.x), Rational(h.b * q.y), h.c});
      if (cycle.empty()) return {};
    }
  }
  return canonical_convex_set(std::move(cycle));
}

}  // namespace gmcc
