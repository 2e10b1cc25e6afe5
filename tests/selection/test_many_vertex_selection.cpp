// Selection on many-vertex feasible sets (issue 13: a many-vertex canonical gamut gives F of
// 10^5–10^6 vertices): worst_case_illuminant's double-precision filters against the unfiltered
// exact route (the same angle, location and kind of location, bit for bit, on random polygons,
// segments and points and on many-vertex polygons, with maps inside, on and outside F, short and
// long), and the 3-D mean's middle stage, whose precision grows with log2(n), deciding the
// correctly rounded map of a many-vertex F without the exact products.
#include "../test_support.h"

#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/numerics/platform.h>
#include <gmcc/selection/mean_3d_analytic.h>

#include "internal/worst_case_illuminant_route.h"

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using gmcc::test::Rng;

namespace {

struct Tally {
  int cases = 0, at_edge = 0, many_vertices = 0;
};

void compare(const ConvexSet2& F, const Point2& m, const Colour& c, Tally& t) {
  const IlluminantWorstCase fast = internal::worst_case_illuminant(F, m, c, internal::IlluminantRoute::certified);
  const IlluminantWorstCase slow = internal::worst_case_illuminant(F, m, c, internal::IlluminantRoute::exact);
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

// The feasible set of issue 13's parabola gamut (1 + t, 1 + t²), t = i/n, for the colours
// (1, 1), (1.001, 1), (1, 1.001).
ConvexSet2 parabola_feasible_set(int n) {
  std::vector<Point2> pts;
  for (int i = 0; i < n; ++i) {
    const Rational s(i, n);
    pts.push_back({Rational(1 + s), Rational(1 + s * s)});
  }
  return feasible_set(convex_hull(pts), {{1, 1}, {Rational(1001, 1000), 1}, {1, Rational(1001, 1000)}});
}

Colour random_light(Rng& rng) {
  return {test::random_rational(rng, 1, 9, 5), test::random_rational(rng, 1, 9, 5), test::random_rational(rng, 1, 9, 5)};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(many_vertex_selection)

BOOST_AUTO_TEST_CASE(illuminant_worst_case_filtered_equals_unfiltered) {
  Rng rng(1313);
  Tally t;
  // Random polygons, segments and points (grids give the degenerate kinds).
  for (int trial = 0; trial < 100; ++trial) {
    const ConvexSet2 F = convex_hull(test::random_points(rng, 1 + trial % 12, 1, 5, trial % 2 ? 3 : 40));
    const Colour c = trial % 3 ? random_light(rng) : Colour{1, 1, 1};
    for (const Point2& m : maps_for(rng, F)) compare(F, m, c, t);
  }
  // Many-vertex polygons: a circle's rational points, and the feasible set of issue 13's
  // parabola gamut (1 + t, 1 + t²) for the colours (1, 1), (1.001, 1), (1, 1.001).
  for (int trial = 0; trial < 3; ++trial) {
    std::vector<Point2> circle;
    const int d = 30 + 20 * trial;
    for (int k = -2 * d; k < 2 * d; ++k) {
      const Rational s(k, d), w = 1 + s * s;
      circle.push_back({Rational(3 + (1 - s * s) / w), Rational(3 + 2 * s / w)});
    }
    const ConvexSet2 F = convex_hull(circle);
    for (const Point2& m : maps_for(rng, F)) compare(F, m, trial % 2 ? random_light(rng) : Colour{1, 1, 1}, t);
  }
  const ConvexSet2 F = parabola_feasible_set(250);
  for (const Point2& m : maps_for(rng, F)) compare(F, m, {1, 1, 1}, t);
  BOOST_TEST(t.at_edge > 5);  // maxima inside edges: the filtered edges' exact work still runs
  BOOST_TEST(t.many_vertices > 15);
}

// On F of 20,000 vertices the double-word stage (106 bits; each c_i from vertex enclosures loses
// about log2(n) bits, which 106 bits can spare) decides both components: the same correctly
// rounded map as the exact products at a forced 200 bits, without falling through to the middle
// MPFI stage (73 + log2(n) = 88 bits) or to them.
BOOST_AUTO_TEST_CASE(mean_3d_first_stage_decides_on_many_vertices) {
  const ConvexSet2 F = parabola_feasible_set(20000);
  BOOST_REQUIRE(F.vertices.size() > 16384);
  const MapEstimate automatic = mean_3d_analytic(F);
  BOOST_TEST(automatic.precision_bits == 106u);
  BOOST_TEST(automatic.correctly_rounded[0]);
  BOOST_TEST(automatic.correctly_rounded[1]);
  AnalyticOptions forced;
  forced.precision_bits = 200;
  const MapEstimate exact_products = mean_3d_analytic(F, forced);
  BOOST_TEST(exact_products.correctly_rounded[0]);
  BOOST_TEST(exact_products.correctly_rounded[1]);
  BOOST_TEST(automatic.map[0] == exact_products.map[0]);
  BOOST_TEST(automatic.map[1] == exact_products.map[1]);
}

BOOST_AUTO_TEST_SUITE_END()
