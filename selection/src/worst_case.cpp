#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/worst_case.h>

#include "internal/angle.h"

#include <algorithm>
#include <stdexcept>

namespace gmcc {

double worst_case_map_deg(const ConvexSet2& F, const Point2& m) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("worst_case_map_deg: empty set");
  // The angle is quasi-convex, so its maximum over F is at a vertex (MATH §1e): the largest of
  // the vertex angles, each evaluated from the exact values in MPFR.
  const std::array<Rational, 3> lifted_m{m.x, m.y, Rational(1)};
  double worst = 0;
  for (const Point2& v : F.vertices)
    worst = std::max(worst, internal::angle_deg(lifted_m, {v.x, v.y, Rational(1)}));
  return worst;
}

}  // namespace gmcc
