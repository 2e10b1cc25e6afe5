// Rationals over one common denominator and integers over their content
// (geometry/integers_over_lcm.h), against the definitions computed another way.
#include "../test_support.h"

#include <gmcc/geometry/integers_over_lcm.h>

#include <boost/test/unit_test.hpp>

#include <vector>

using namespace gmcc;
using gmcc::test::Rng;
using gmcc::test::random_rational;

namespace {
// lcm(a, b) = a·b / gcd(a, b), by Euclid's algorithm written out here.
mpz_class lcm_by_euclid(mpz_class a, mpz_class b) {
  const mpz_class product = a * b;
  while (b != 0) {
    const mpz_class r = a % b;
    a = b;
    b = r;
  }
  return product / a;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(integers_over_lcm_suite)

BOOST_AUTO_TEST_CASE(integers_over_the_least_common_denominator) {
  Rng rng(3);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Rational> xs;
    for (int k = 0; k < trial % 6; ++k) xs.push_back(random_rational(rng, -1000, 1000, trial % 2 ? 360 : 1L << 40));
    mpz_class l;
    const std::vector<mpz_class> zs = integers_over_lcm(xs, &l);
    mpz_class expected = 1;
    for (const Rational& x : xs) expected = lcm_by_euclid(expected, x.get_den());
    BOOST_TEST(l == expected);
    BOOST_TEST(l == lcm_of_denominators(xs));
    BOOST_TEST(zs.size() == xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
      Rational back(zs[i], l);
      back.canonicalize();
      BOOST_TEST(back == xs[i]);  // the same numbers, over L
      BOOST_TEST(times_lcm(xs[i], l) == zs[i]);
    }
    if (xs.size() >= 3)
      BOOST_TEST(lcm_of_denominators_of(xs[0], xs[1], xs[2]) == lcm_of_denominators(std::vector<Rational>(xs.begin(), xs.begin() + 3)));
  }
}

BOOST_AUTO_TEST_CASE(division_by_content_keeps_proportions) {
  Rng rng(5);
  std::uniform_int_distribution<long> n(-60, 60), factor(1, 36);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<mpz_class> zs;
    const long f = factor(rng);
    for (int k = 0; k < 1 + trial % 4; ++k) zs.push_back(mpz_class(n(rng)) * f);
    const std::vector<mpz_class> before = zs;
    divide_by_content(zs);
    mpz_class g = 0;  // the content after: 1, or 0 when every integer is 0
    for (const mpz_class& z : zs) g = gcd(g, z);
    BOOST_TEST((g == 1 || (g == 0 && zs == before)));
    for (std::size_t i = 0; i < zs.size(); ++i) {
      BOOST_TEST(sgn(zs[i]) == sgn(before[i]));
      BOOST_TEST(zs[i] * before[0] == before[i] * zs[0]);  // the same proportions
    }
    mpz_class a = before[0], b = before.back();
    divide_by_content_of(a, b);
    BOOST_TEST((gcd(a, b) == 1 || (sgn(a) == 0 && sgn(b) == 0)));
  }
}

BOOST_AUTO_TEST_SUITE_END()
