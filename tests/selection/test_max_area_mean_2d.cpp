#include "../test_support.h"

#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
const ConvexSet2 toy{ConvexKind::segment, {{Rational(1, 3), Rational(2, 3)}, {3, 2}}};
}

BOOST_AUTO_TEST_SUITE(max_area_rule)

// Finlayson & Hordley (1999) toy example: max-area picks the end (3, 2).
BOOST_AUTO_TEST_CASE(paper_toy_example) {
  const MapEstimate e = max_area(toy);
  BOOST_REQUIRE(e.exact.has_value());
  BOOST_TEST((*e.exact == Point2{3, 2}));
  BOOST_TEST(e.map[0] == 3.0);
  BOOST_TEST(e.error_bound == 0.0);
}

BOOST_AUTO_TEST_CASE(optimum_inside_an_edge_is_the_midpoint_of_the_intercepts) {
  // The edge x + y = 4 between (1,3) and (3,1): a·b is largest at (2, 2).
  const ConvexSet2 tri = convex_hull({{1, 3}, {3, 1}, {1, 1}});
  BOOST_TEST((max_area_point(tri) == Point2{2, 2}));
  // On a segment with the optimum inside.
  const ConvexSet2 seg{ConvexKind::segment, {{1, 3}, {3, 1}}};
  BOOST_TEST((max_area_point(seg) == Point2{2, 2}));
  const ConvexSet2 pt{ConvexKind::point, {{Rational(2, 7), 5}}};
  BOOST_TEST((max_area_point(pt) == Point2{Rational(2, 7), 5}));
}

BOOST_AUTO_TEST_CASE(exact_candidate_beats_a_dense_exact_search_and_is_unique) {
  Rng rng(300);
  int interior_optima = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const ConvexSet2 F = convex_hull(test::random_points(rng, 3 + trial % 12, 1, 5, 8));
    if (F.kind == ConvexKind::empty) continue;
    const Point2 best = max_area_point(F);
    BOOST_TEST(contains(F, best));
    const Rational best_value = best.x * best.y;
    bool at_vertex = false;
    const auto& v = F.vertices;
    for (std::size_t i = 0; i < v.size(); ++i) {
      at_vertex = at_vertex || v[i] == best;
      const Point2& p = v[i];
      const Point2& q = v[(i + 1) % v.size()];
      for (int s = 0; s <= 200; ++s) {  // dense exact samples along every edge
        Rational t(s, 200);
        t.canonicalize();
        const Point2 x{Rational(p.x + t * (q.x - p.x)), Rational(p.y + t * (q.y - p.y))};
        const Rational value = x.x * x.y;
        BOOST_TEST((value < best_value || x == best), "x=" << x << " best=" << best << " F=" << F);
      }
    }
    interior_optima += !at_vertex;
  }
  BOOST_TEST(interior_optima > 0);  // the edge stationary points are exercised
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(mean_2d_rule)

BOOST_AUTO_TEST_CASE(paper_toy_example) {
  const MapEstimate e = mean_2d(toy);
  BOOST_TEST((*e.exact == Point2{Rational(5, 3), Rational(4, 3)}));
  BOOST_TEST(e.map[0] == 5.0 / 3.0);
  BOOST_TEST(e.map[1] == 4.0 / 3.0);
  // The reported bound covers the rounding to double, and the enclosure brackets 5/3.
  BOOST_TEST(e.error_bound > 0.0);
  BOOST_TEST(e.error_bound < 1e-15);
  BOOST_TEST((*e.enclosure)[0][0] < (*e.enclosure)[0][1]);
}

BOOST_AUTO_TEST_CASE(centroid_of_a_triangle_is_the_vertex_mean) {
  const ConvexSet2 tri = convex_hull({{1, 1}, {4, 1}, {1, 7}});
  BOOST_TEST((*mean_2d(tri).exact == Point2{2, 3}));
}

BOOST_AUTO_TEST_SUITE_END()
