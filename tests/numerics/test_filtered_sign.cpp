// The filters' shared vocabulary (numerics/filtered_sign.h): γ_n as a double never below its exact
// value n·u/(1 − n·u), computed in ℚ; and sign_within never excluding the sign of a real number
// within the stated bound of the computed value, decided exactly.
#include <gmcc/numerics/filtered_sign.h>

#include <boost/test/unit_test.hpp>
#include <gmpxx.h>

#include <cmath>
#include <limits>
#include <random>

using namespace gmcc::numerics;

BOOST_AUTO_TEST_SUITE(filtered_sign)

BOOST_AUTO_TEST_CASE(gamma_n_is_never_below_its_value) {
  const mpq_class u(1, mpz_class(1) << 53);
  int plain_below = 0;
  for (int n = 1; n <= 4096; ++n) {
    const mpq_class exact = n * u / (1 - n * u);
    BOOST_TEST(mpq_class(gamma_n(n)) >= exact, "gamma_n(" << n << ")");
    BOOST_TEST(mpq_class(gamma_n(n)) <= exact * (1 + 8 * u));  // and no looser than a few ulps
    plain_below += mpq_class(n * unit_roundoff / (1 - n * unit_roundoff)) < exact;
  }
  BOOST_TEST(plain_below > 0);  // why the factor is there: the plain quotient rounds below
  BOOST_TEST(mpq_class(unit_roundoff) == u);
}

BOOST_AUTO_TEST_CASE(sign_within_never_excludes_the_truth) {
  std::mt19937_64 rng(46);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < 50000; ++i) {
    const double v = i % 11 == 0 ? 0.0 : std::ldexp(unit(rng), static_cast<int>(rng() % 200) - 100);
    const double b = i % 13 == 0 ? 0.0 : std::fabs(v) * std::ldexp(std::fabs(unit(rng)), static_cast<int>(rng() % 8) - 4);
    const UncertainSign s = sign_within(v, b);
    for (int k = -4; k <= 4; ++k) {  // points x with |x − v| <= b
      const mpq_class x = mpq_class(v) + mpq_class(b) * mpq_class(k, 4);
      const int t = sgn(x);
      BOOST_TEST((s.lo <= t && t <= s.hi), "v " << v << " b " << b << " x " << x.get_d());
    }
  }
  BOOST_TEST(sign_within(1.0, 0.5).is_certain());
  BOOST_TEST(!sign_within(0.0, 0.0).is_certain());  // a computed 0 may hide an underflow
  BOOST_TEST(!sign_within(std::nan(""), 1.0).is_certain());
  BOOST_TEST(!sign_within(1.0, std::nan("")).is_certain());
}

BOOST_AUTO_TEST_SUITE_END()
