#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/worst_case.h>

#include "internal/angle.h"
#include "internal/ld_interval.h"

#include <algorithm>
#include <stdexcept>

namespace gmcc {

double worst_case_map_deg(const ConvexSet2& F, const Point2& m) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("worst_case_map_deg: empty set");
  // The angle is quasi-convex, so its maximum over F is at a vertex (MATH §1e): the largest of
  // the vertex angles, each evaluated from the exact values in MPFR.
  const std::array<Rational, 3> lifted_m{m.x, m.y, Rational(1)};
  auto lifted = [](const Point2& v) { return std::array<Rational, 3>{v.x, v.y, Rational(1)}; };
  double worst = 0;
  if (!internal::fast_path_available) {
    for (const Point2& v : F.vertices) worst = std::max(worst, internal::angle_deg(lifted_m, lifted(v)));
    return worst;
  }
  // Cheap enclosures first; a vertex whose angle is certainly below another's by a relative
  // 2^-40 cannot be the maximum, and its rounded angle (within a relative 2^-50 of the true one,
  // like every angle_deg result) cannot exceed the winner's either, so it is not evaluated.
  std::vector<internal::LDInterval> enclosures;
  enclosures.reserve(F.vertices.size());
  const internal::LDInterval mx = internal::enclose_ld(m.x), my = internal::enclose_ld(m.y);
  long double best_lo = 0;
  for (const Point2& v : F.vertices) {
    enclosures.push_back(internal::angle_deg_enclosure({mx, my, {1, 1}}, {internal::enclose_ld(v.x), internal::enclose_ld(v.y), {1, 1}}));
    best_lo = std::max(best_lo, enclosures.back().lo);
  }
  const long double threshold = best_lo * (1 - 0x1p-40L);
  for (std::size_t i = 0; i < F.vertices.size(); ++i)
    if (enclosures[i].hi >= threshold)
      worst = std::max(worst, internal::angle_deg(lifted_m, lifted(F.vertices[i])));
  return worst;
}

}  // namespace gmcc
