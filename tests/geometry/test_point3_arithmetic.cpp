// Exact Point3 arithmetic (geometry/point3_arithmetic.h): the identities of vector algebra, which
// hold exactly in ℚ, on random rational points.
#include "../test_support.h"

#include <gmcc/geometry/point3_arithmetic.h>

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using gmcc::test::Rng;
using gmcc::test::random_rational;

namespace {
Point3 random_point3(Rng& rng) {
  Rational x = random_rational(rng, -40, 40, 9), y = random_rational(rng, -40, 40, 9);
  return {x, y, random_rational(rng, -40, 40, 9)};
}
}  // namespace

BOOST_AUTO_TEST_SUITE(point3_arithmetic)

BOOST_AUTO_TEST_CASE(vector_identities_hold_exactly) {
  Rng rng(31);
  for (int trial = 0; trial < 300; ++trial) {
    const Point3 a = random_point3(rng), b = random_point3(rng), c = random_point3(rng);
    const Rational s = random_rational(rng, -9, 9, 5);
    BOOST_TEST((add(sub(a, b), b) == a));
    BOOST_TEST((add(a, b) == add(b, a)));
    BOOST_TEST((scale(add(a, b), s) == add(scale(a, s), scale(b, s))));
    BOOST_TEST((hadamard(a, b) == hadamard(b, a)));
    BOOST_TEST(dot(hadamard(a, b), Point3{1, 1, 1}) == dot(a, b));
    BOOST_TEST((cross(a, b) == scale(cross(b, a), -1)));
    BOOST_TEST(dot(cross(a, b), a) == 0);
    BOOST_TEST(dot(cross(a, b), b) == 0);
    // Lagrange's identity and the scalar triple product's cyclic symmetry.
    const Point3 n = cross(a, b);
    BOOST_TEST(dot(n, n) == dot(a, a) * dot(b, b) - dot(a, b) * dot(a, b));
    BOOST_TEST(dot(cross(a, b), c) == dot(cross(b, c), a));
    BOOST_TEST(is_zero(cross(a, scale(a, s))));
    BOOST_TEST(is_zero(sub(a, a)));
    BOOST_TEST(is_zero(a) == (sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0));
    const int k = largest_coordinate(a);
    for (int j = 0; j < 3; ++j) {
      BOOST_TEST(abs(coord(a, k)) >= abs(coord(a, j)));
      if (j < k) BOOST_TEST(abs(coord(a, k)) > abs(coord(a, j)));  // the first on ties
    }
  }
  Point3 p{1, 2, 3};
  coord(p, 1) = 7;
  BOOST_TEST((p == Point3{1, 7, 3}));
  BOOST_TEST(largest_coordinate(Point3{-5, 5, 5}) == 0);
}

BOOST_AUTO_TEST_SUITE_END()
