#include <gmcc/selection/angular_error.h>

#include <mpfr.h>

#include <array>
#include <stdexcept>

namespace gmcc {
namespace {
using Vec3 = std::array<Rational, 3>;

// The angle between two exact 3-vectors, in degrees: atan2(|u×v|, u·v), the well-conditioned
// form (acos of the normalised dot loses half the digits for small angles).
double angle_deg(const Vec3& u, const Vec3& v) {
  const Rational c0 = u[1] * v[2] - u[2] * v[1], c1 = u[2] * v[0] - u[0] * v[2],
                 c2 = u[0] * v[1] - u[1] * v[0];
  const Rational cross2 = c0 * c0 + c1 * c1 + c2 * c2;
  const Rational dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  constexpr mpfr_prec_t bits = 128;
  mpfr_t s, c, a, pi;
  mpfr_inits2(bits, s, c, a, pi, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(s, cross2.get_mpq_t(), MPFR_RNDN);
  mpfr_sqrt(s, s, MPFR_RNDN);
  mpfr_set_q(c, dot.get_mpq_t(), MPFR_RNDN);
  mpfr_atan2(a, s, c, MPFR_RNDN);
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_mul_ui(a, a, 180, MPFR_RNDN);
  mpfr_div(a, a, pi, MPFR_RNDN);
  const double deg = mpfr_get_d(a, MPFR_RNDN);
  mpfr_clears(s, c, a, pi, static_cast<mpfr_ptr>(nullptr));
  return deg;
}
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
