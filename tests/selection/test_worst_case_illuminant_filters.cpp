// worst_case_illuminant's double-precision filters (issue 13: many-vertex feasible sets) against
// the unfiltered exact route: the same angle, location and kind of location, bit for bit, on
// random polygons, segments and points, many-vertex polygons (feasible sets of a parabola gamut,
// rational points on a circle), with maps inside, on and outside F, short and long.
#include "../test_support.h"

#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/mean_2d.h>

#include "internal/worst_case_illuminant_route.h"

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using gmcc::test::Rng;

namespace {

struct Tally {
  int cases = 0, at_edge = 0, many_vertices = 0;
};

void compare(const ConvexSet2& F, const Point2& m, const Colour& c, Tally& t) {
  const IlluminantWorstCase fast = internal::worst_case_illuminant(F, m, c, true);
  const IlluminantWorstCase slow = internal::worst_case_illuminant(F, m, c, false);
  BOOST_TEST(fast.angle_deg == slow.angle_deg);
  BOOST_TEST(fast.location == slow.location);
  BOOST_TEST(fast.at_vertex == slow.at_vertex);
  ++t.cases;
  t.at_edge += !slow.at_vertex;
  t.many_vertices += F.vertices.size() >= 100;
}

// Maps to measure from: F's first vertex, its 2-D mean (long exact digits on many-vertex sets),
// and random positive points around F.
std::vector<Point2> maps_for(Rng& rng, const ConvexSet2& F) {
  std::vector<Point2> ms{F.vertices.front(), *mean_2d(F).exact};
  for (int i = 0; i < 3; ++i) ms.push_back(test::random_points(rng, 1, 1, 6, 13)[0]);
  return ms;
}

Colour random_light(Rng& rng) {
  return {test::random_rational(rng, 1, 9, 5), test::random_rational(rng, 1, 9, 5), test::random_rational(rng, 1, 9, 5)};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(worst_case_illuminant_filters)

BOOST_AUTO_TEST_CASE(filtered_equals_unfiltered) {
  Rng rng(1313);
  Tally t;
  // Random polygons, segments and points (grids give the degenerate kinds).
  for (int trial = 0; trial < 150; ++trial) {
    const ConvexSet2 F = convex_hull(test::random_points(rng, 1 + trial % 12, 1, 5, trial % 2 ? 3 : 40));
    const Colour c = trial % 3 ? random_light(rng) : Colour{1, 1, 1};
    for (const Point2& m : maps_for(rng, F)) compare(F, m, c, t);
  }
  // Many-vertex polygons: a circle's rational points, and the feasible set of issue 13's
  // parabola gamut (1 + t, 1 + t²) for the colours (1, 1), (1.001, 1), (1, 1.001).
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<Point2> circle;
    const int d = 30 + 20 * trial;
    for (int k = -2 * d; k < 2 * d; ++k) {
      const Rational s(k, d), w = 1 + s * s;
      circle.push_back({Rational(3 + (1 - s * s) / w), Rational(3 + 2 * s / w)});
    }
    const ConvexSet2 F = convex_hull(circle);
    for (const Point2& m : maps_for(rng, F)) compare(F, m, trial % 2 ? random_light(rng) : Colour{1, 1, 1}, t);
  }
  for (int n : {400}) {
    std::vector<Point2> pts;
    for (int i = 0; i < n; ++i) {
      const Rational s(i, n);
      pts.push_back({Rational(1 + s), Rational(1 + s * s)});
    }
    const ConvexSet2 F = feasible_set(convex_hull(pts), {{1, 1}, {Rational(1001, 1000), 1}, {1, Rational(1001, 1000)}});
    for (const Point2& m : maps_for(rng, F)) compare(F, m, {1, 1, 1}, t);
  }
  BOOST_TEST(t.at_edge > 8);  // maxima inside edges: the filtered edges' exact work still runs
  BOOST_TEST(t.many_vertices > 20);
}

BOOST_AUTO_TEST_SUITE_END()
