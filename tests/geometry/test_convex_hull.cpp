#include "../test_support.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>

using namespace gmcc;
using gmcc::test::Rng;

BOOST_AUTO_TEST_SUITE(convex_hull_2d)

BOOST_AUTO_TEST_CASE(degenerate_inputs_give_degenerate_kinds) {
  BOOST_TEST(convex_hull({}).kind == ConvexKind::empty);
  const Point2 a{1, 2};
  const ConvexSet2 one = convex_hull({a, a, a});
  BOOST_TEST(one.kind == ConvexKind::point);
  BOOST_TEST((one.vertices == std::vector<Point2>{a}));
  const ConvexSet2 line = convex_hull({{Rational(1, 2), 1}, {2, 4}, {1, 2}, {2, 4}});
  BOOST_TEST(line.kind == ConvexKind::segment);
  BOOST_TEST((line.vertices == std::vector<Point2>{{Rational(1, 2), 1}, {2, 4}}));
}

BOOST_AUTO_TEST_CASE(square_with_interior_and_edge_points) {
  const ConvexSet2 h = convex_hull({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {1, 0}, {2, 1}});
  BOOST_TEST(h.kind == ConvexKind::polygon);
  BOOST_TEST((h.vertices == std::vector<Point2>{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  BOOST_TEST(area(h) == Rational(4));
}

BOOST_AUTO_TEST_CASE(random_hulls_are_strictly_convex_ccw_and_contain_their_input) {
  Rng rng(20261121);
  for (int trial = 0; trial < 200; ++trial) {
    const auto pts = test::random_points(rng, 3 + trial % 30, 1, 5, 7);
    const ConvexSet2 h = convex_hull(pts);
    for (const Point2& p : pts) BOOST_TEST(contains(h, p));
    if (h.kind != ConvexKind::polygon) continue;
    const auto& v = h.vertices;
    BOOST_TEST((std::min_element(v.begin(), v.end()) == v.begin()));
    for (std::size_t i = 0; i < v.size(); ++i) {
      BOOST_TEST(sgn(orientation(v[i], v[(i + 1) % v.size()], v[(i + 2) % v.size()])) > 0);
      BOOST_TEST((std::find(pts.begin(), pts.end(), v[i]) != pts.end()));
    }
  }
}

BOOST_AUTO_TEST_CASE(centroid_is_exact_and_independent_of_the_fan_apex) {
  Rng rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const ConvexSet2 h = convex_hull(test::random_points(rng, 12, 1, 4, 9));
    if (h.kind != ConvexKind::polygon) continue;
    // Green's theorem form: C = (1/6A) Σ (x_i + x_{i+1}) (x_i y_{i+1} − x_{i+1} y_i).
    const auto& v = h.vertices;
    Rational a = 0, cx = 0, cy = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Point2& p = v[i];
      const Point2& q = v[(i + 1) % v.size()];
      const Rational w = p.x * q.y - q.x * p.y;
      a += w;
      cx += (p.x + q.x) * w;
      cy += (p.y + q.y) * w;
    }
    const Point2 c = centroid(h);
    BOOST_TEST(c.x == Rational(cx / (3 * a)));
    BOOST_TEST(c.y == Rational(cy / (3 * a)));
    BOOST_TEST(area(h) == Rational(a / 2));
  }
}

BOOST_AUTO_TEST_SUITE_END()
