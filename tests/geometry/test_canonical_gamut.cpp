#include "../test_support.h"

#include <gmcc/geometry/canonical_gamut.h>

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using gmcc::test::Rng;

BOOST_AUTO_TEST_SUITE(canonical_gamut_expansion)

BOOST_AUTO_TEST_CASE(no_expansion_is_the_hull) {
  const std::vector<Point2> pts{{1, 1}, {3, 1}, {2, 2}, {2, 3}};
  BOOST_TEST(canonical_gamut(pts) == convex_hull(pts));
  BOOST_TEST(canonical_gamut(pts, {ExpansionPolicy::centroid_clip, 0}) == convex_hull(pts));
}

BOOST_AUTO_TEST_CASE(policies_contain_the_measured_gamut_and_stay_positive) {
  Rng rng(10);
  for (int trial = 0; trial < 40; ++trial) {
    const auto pts = test::random_points(rng, 3 + trial % 20, 1, 3, 50);  // some near 0
    const ConvexSet2 hull = convex_hull(pts);
    for (ExpansionPolicy p : {ExpansionPolicy::centroid_clip, ExpansionPolicy::multiplicative}) {
      const ConvexSet2 g = canonical_gamut(pts, {p, Rational(1, 10)});
      for (const Point2& v : hull.vertices) BOOST_TEST(contains(g, v));
      for (const Point2& v : g.vertices) BOOST_TEST((sgn(v.x) > 0 && sgn(v.y) > 0));
      if (hull.kind == ConvexKind::polygon) BOOST_TEST(area(g) > area(hull));
    }
  }
}

BOOST_AUTO_TEST_CASE(naive_centroid_scaling_would_leave_the_quadrant_clip_prevents_it) {
  // A long thin gamut near the axis: scaling by 2 about its centroid crosses x = 0.
  const std::vector<Point2> pts{{Rational(1, 100), 1}, {10, 1}, {10, 2}};
  const ConvexSet2 g = canonical_gamut(pts, {ExpansionPolicy::centroid_clip, 1});
  for (const Point2& v : g.vertices) BOOST_TEST(v.x >= Rational(1, 200));
}

BOOST_AUTO_TEST_CASE(multiplicative_is_a_box_in_log_chromaticity) {
  const ConvexSet2 g = canonical_gamut({{2, 3}}, {ExpansionPolicy::multiplicative, 1});
  BOOST_TEST((g.vertices == std::vector<Point2>{{1, Rational(3, 2)}, {4, Rational(3, 2)}, {4, 6},
                                                {1, 6}}));
}

BOOST_AUTO_TEST_CASE(names_round_trip_and_bad_requests_throw) {
  for (ExpansionPolicy p :
       {ExpansionPolicy::none, ExpansionPolicy::centroid_clip, ExpansionPolicy::multiplicative})
    BOOST_TEST((expansion_policy_from_string(to_string(p)) == p));
  BOOST_CHECK_THROW(expansion_policy_from_string("naive"), std::invalid_argument);
  BOOST_CHECK_THROW(canonical_gamut({{1, 1}}, {ExpansionPolicy::none, 1}), std::invalid_argument);
  BOOST_CHECK_THROW(canonical_gamut({{1, 1}}, {ExpansionPolicy::multiplicative, -1}),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
