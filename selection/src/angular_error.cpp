#include <gmcc/selection/angular_error.h>

#include "internal/angle.h"

#include <array>
#include <stdexcept>

namespace gmcc {
namespace {
using Vec3 = std::array<Rational, 3>;

double angle_deg(const Vec3& u, const Vec3& v) { return internal::angle_deg(u, v); }
}  // namespace

double map_angular_error_deg(const Point2& estimate, const Point2& truth) {
  return angle_deg({estimate.x, estimate.y, Rational(1)}, {truth.x, truth.y, Rational(1)});
}

double illuminant_angular_error_deg(const Point2& estimate, const Point2& truth,
                                    const Colour& c) {
  for (const Rational* x : {&estimate.x, &estimate.y, &truth.x, &truth.y, &c.r, &c.g, &c.b})
    if (sgn(*x) <= 0)
      throw std::invalid_argument("illuminant_angular_error_deg: maps and illuminant must be > 0");
  // e = c ⊘ d with d = (m1, m2, 1).
  return angle_deg({Rational(c.r / estimate.x), Rational(c.g / estimate.y), c.b},
                   {Rational(c.r / truth.x), Rational(c.g / truth.y), c.b});
}

double reproduction_angular_error_deg(const Point2& estimate, const Point2& truth) {
  for (const Rational* x : {&estimate.x, &estimate.y, &truth.x, &truth.y})
    if (sgn(*x) <= 0)
      throw std::invalid_argument("reproduction_angular_error_deg: maps must be > 0");
  return angle_deg({Rational(estimate.x / truth.x), Rational(estimate.y / truth.y), Rational(1)},
                   {Rational(1), Rational(1), Rational(1)});
}

}  // namespace gmcc
