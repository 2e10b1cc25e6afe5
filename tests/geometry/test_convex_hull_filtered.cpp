// The filtered monotone chain of convex_hull (issue 13) against CGAL's convex_hull_2 over the lazy
// exact kernel, which it replaced: the same canonical set on seeded point sets of every kind —
// grids with repeated and collinear points, many points on convex curves (every one a vertex),
// nearly collinear slivers where the filters cannot decide, coordinates beyond the filters'
// range, vertical and horizontal lines, one point, none.
#include "../test_support.h"

#include "support/cgal_references.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>

using namespace gmcc;
using gmcc::test::Rng;

namespace {

int compared = 0;

void same_hull(std::vector<Point2> pts, Rng& rng) {
  std::shuffle(pts.begin(), pts.end(), rng);
  const ConvexSet2 h = convex_hull(pts);
  BOOST_TEST(h == test::convex_hull_cgal(pts), pts.size() << " points");
  ++compared;
}

std::vector<Point2> scaled(std::vector<Point2> pts, const Rational& s) {
  for (Point2& p : pts) p.x *= s, p.y *= s;
  return pts;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(convex_hull_filtered)

BOOST_AUTO_TEST_CASE(monotone_chain_equals_cgal) {
  Rng rng(13);
  compared = 0;
  for (int trial = 0; trial < 300; ++trial) {  // grids (repeats, collinear triples) and fine random points
    const bool grid = trial % 2;
    const auto pts = test::random_points(rng, 1 + trial % 40, 0, 5, grid ? 1 + trial % 4 : 1000);
    same_hull(pts, rng);
    if (trial % 10 == 0) {  // beyond the filters' range: exact decisions only
      same_hull(scaled(pts, Rational(mpz_class(1) << 200)), rng);
      same_hull(scaled(pts, Rational(1, mpz_class(1) << 200)), rng);
    }
  }
  for (int n : {50, 500, 3000}) {
    std::vector<Point2> parabola, circle, sliver, line, vertical;
    for (int i = 0; i < n; ++i) {
      const Rational t(i, n);
      parabola.push_back({Rational(1 + t), Rational(1 + t * t)});
      sliver.push_back({Rational(1 + t), Rational(1 + t * t / (mpz_class(1) << 80))});  // turns near 2^-80
      line.push_back({Rational(1 + t), Rational(2 + 3 * t)});
      vertical.push_back({1, Rational(1 + t)});
      const Rational s(i - n / 2, n / 8), w = 1 + s * s;  // rational points on the unit circle
      circle.push_back({Rational(2 + (1 - s * s) / w), Rational(2 + 2 * s / w)});
    }
    for (auto* pts : {&parabola, &circle, &sliver, &line, &vertical}) same_hull(*pts, rng);
    std::vector<Point2> cloud = parabola;  // with interior points
    for (int i = 0; i < n; ++i) cloud.push_back({Rational(1 + Rational(i, 2 * n)), Rational(3, 2)});
    same_hull(cloud, rng);
  }
  same_hull({}, rng);
  same_hull({{1, 2}}, rng);
  same_hull({{1, 2}, {1, 2}, {1, 2}}, rng);
  same_hull({{1, 2}, {3, 2}, {2, 2}, {3, 2}}, rng);
  BOOST_TEST(compared > 340);
}

BOOST_AUTO_TEST_SUITE_END()
