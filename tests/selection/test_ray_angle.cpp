// ray_angle_deg (selection/src/internal/angle.h; issue 46 item 3, fourth round): the angle between
// two rays from any positive integer multiples of them, without a gcd, is angle_deg of the rays
// (their primitive integer vectors) bit for bit whenever it decides; and it declines whenever the
// exact angle θ is so near a rounding boundary of double that some value within 2^-56·θ of it,
// which angle_deg's stages may return, rounds to another double (the test's own oracle: θ in
// MPFR at 400 bits from exact integer cross and dot products). Fails if the filter's widening
// by 2^-56 is dropped or narrowed.
#include "../test_support.h"

#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/numerics/platform.h>

#include "internal/angle.h"

#include <boost/test/unit_test.hpp>

#include <mpfr.h>

#include <array>
#include <optional>

using namespace gmcc;
using gmcc::test::Rng;

namespace {

mpz_class random_integer(Rng& rng, int bits, bool signed_) {
  mpz_class z = 0;
  for (int b = 0; b < bits; b += 32) z = (z << 32) + static_cast<unsigned long>(rng() & 0xffffffffu);
  z >>= (bits + 31) / 32 * 32 - bits;
  return signed_ && (rng() & 1) ? mpz_class(-z) : z;
}

std::array<Rational, 3> ray(std::array<mpz_class, 3> z) {
  divide_by_content_of(z[0], z[1], z[2]);
  return {Rational(z[0]), Rational(z[1]), Rational(z[2])};
}

std::optional<double> filtered(const std::array<mpz_class, 3>& u, const std::array<mpz_class, 3>& v) {
  return internal::ray_angle_deg({&u[0], &u[1], &u[2]}, {&v[0], &v[1], &v[2]});
}

// Whether θ(1 − 2^-56) and θ(1 + 2^-56) round to different doubles (θ, the exact angle in degrees
// between u and v, in MPFR at 400 bits: relative error far below 2^-300).
bool near_a_boundary(const std::array<mpz_class, 3>& u, const std::array<mpz_class, 3>& v) {
  mpz_class c2 = 0, d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  for (int k = 0; k < 3; ++k) {
    const mpz_class c = u[(k + 1) % 3] * v[(k + 2) % 3] - u[(k + 2) % 3] * v[(k + 1) % 3];
    c2 += c * c;
  }
  mpfr_t s, t, a, pi;
  mpfr_inits2(400, s, t, a, pi, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_z(s, c2.get_mpz_t(), MPFR_RNDN);
  mpfr_sqrt(s, s, MPFR_RNDN);
  mpfr_set_z(t, d.get_mpz_t(), MPFR_RNDN);
  mpfr_atan2(a, s, t, MPFR_RNDN);
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_mul_ui(a, a, 180, MPFR_RNDN);
  mpfr_div(a, a, pi, MPFR_RNDN);
  mpfr_mul_2si(t, a, -56, MPFR_RNDN);
  mpfr_sub(s, a, t, MPFR_RNDN);
  mpfr_add(t, a, t, MPFR_RNDN);
  const bool near = mpfr_get_d(s, MPFR_RNDN) != mpfr_get_d(t, MPFR_RNDN);
  mpfr_clears(s, t, a, pi, static_cast<mpfr_ptr>(nullptr));
  return near;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(ray_angle)

BOOST_AUTO_TEST_CASE(multiples_give_the_rays_double_or_decline_near_a_boundary) {
  if (!numerics::extended_precision_active()) {
    const std::array<mpz_class, 3> u{1, 2, 3}, v{3, 2, 1};
    BOOST_TEST(!filtered(u, v).has_value());  // no x87: angle_deg decides
    return;
  }
  Rng rng(4646);
  int decided = 0, near = 0, trials = 0;
  for (int trial = 0; trial < 6000; ++trial) {
    const int bits = 1 + static_cast<int>(rng() % 300);
    const bool signed_ = trial % 4 == 3;
    std::array<mpz_class, 3> u, v, U, V;
    for (int k = 0; k < 3; ++k) u[k] = random_integer(rng, bits, signed_), v[k] = random_integer(rng, 1 + static_cast<int>(rng() % 300), signed_);
    if (trial % 5 == 1)  // nearly parallel: a small angle
      for (int k = 0; k < 3; ++k) v[k] = (u[k] << 40) + random_integer(rng, 20, true);
    if (trial % 50 == 7) v = u;  // equal rays: 0
    if (trial % 50 == 9)         // opposite rays: 180
      for (int k = 0; k < 3; ++k) v[k] = -u[k];
    if (sgn(u[0]) == 0 && sgn(u[1]) == 0 && sgn(u[2]) == 0) continue;
    if (sgn(v[0]) == 0 && sgn(v[1]) == 0 && sgn(v[2]) == 0) continue;
    const mpz_class k = random_integer(rng, 1 + static_cast<int>(rng() % 200), false) + 1,
                    l = random_integer(rng, 1 + static_cast<int>(rng() % 200), false) + 1;
    for (int j = 0; j < 3; ++j) U[j] = k * u[j], V[j] = l * v[j];
    ++trials;
    const std::optional<double> got = filtered(U, V);
    const bool boundary = near_a_boundary(u, v);
    near += boundary;
    if (boundary) BOOST_TEST(!got.has_value(), "trial " << trial);
    if (!got) continue;
    ++decided;
    const double want = internal::angle_deg(ray(u), ray(v));
    BOOST_TEST(*got == want, "trial " << trial);
  }
  BOOST_TEST_MESSAGE("ray_angle: " << trials << " trials, " << near << " near a boundary, " << decided << " decided");
  BOOST_TEST(near > trials / 20);     // cases near a boundary were met (about one in six)
  BOOST_TEST(decided > trials / 2);   // and most were decided
}

BOOST_AUTO_TEST_SUITE_END()
