#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/worst_case.h>

#include <stdexcept>

namespace gmcc {

double worst_case_map_deg(const ConvexSet2& F, const Point2& m) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("worst_case_map_deg: empty set");
  // The angle is largest where cos² = (m·v)² / (|m|²|v|²) is smallest; m·v >= 1 > 0 for
  // non-negative components, so compare (m·v)²·|w|² against (m·w)²·|v|² exactly.
  auto dot_m = [&](const Point2& v) { return Rational(m.x * v.x + m.y * v.y + 1); };
  auto norm2 = [](const Point2& v) { return Rational(v.x * v.x + v.y * v.y + 1); };
  const Point2* worst = &F.vertices.front();
  for (const Point2& v : F.vertices) {
    const Rational dv = dot_m(v), dw = dot_m(*worst);
    if (dv * dv * norm2(*worst) < dw * dw * norm2(v)) worst = &v;
  }
  return map_angular_error_deg(m, *worst);
}

}  // namespace gmcc
