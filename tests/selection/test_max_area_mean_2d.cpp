#include "../test_support.h"

#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/numerics/platform.h>

#include "internal/max_area_route.h"

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

// The filtered stage (x87 intervals) and the exact stage are one candidate enumeration over two
// number types: wherever the filter answers it must give the exact stage's point, on grids where
// ties, repeated vertices and near-ties are common, and on segments and points.
BOOST_AUTO_TEST_CASE(filtered_and_exact_stages_agree) {
  Rng rng(3110);
  int answered = 0, declined = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const ConvexSet2 F = convex_hull(test::random_points(rng, 1 + trial % 12, 1, 6, trial % 2 ? 7 : 1000003));
    const Point2 exact = internal::max_area_exact(F);
    BOOST_TEST(max_area_point(F) == exact);
    if (const auto filtered = internal::max_area_filtered(F)) {
      ++answered;
      BOOST_TEST(*filtered == exact, "trial " << trial);
    } else {
      ++declined;
    }
  }
  BOOST_TEST(answered > 300);  // the filter decides most sets
  BOOST_TEST(declined > 0);    // and the grids' ties reach the exact stage
}

// The staged rule counts which stage answered: a generic polygon is the filter's (where the x87
// path runs); an edge whose stationary point is exactly its end (f′ = 0 at (2, 2) on the edge to
// (1, 3)) cannot be decided in intervals and goes to the exact stage.
BOOST_AUTO_TEST_CASE(stage_counts_show_the_fallbacks) {
  const internal::StageCounts& counts = internal::max_area_stage_counts();
  const std::uint64_t filtered0 = counts[0], exact0 = counts[1];
  const ConvexSet2 generic = convex_hull({{1, 3}, {3, 1}, {Rational(1, 2), Rational(1, 2)}, {3, 3}});
  BOOST_TEST((max_area_point(generic) == Point2{3, 3}));
  const ConvexSet2 at_end = convex_hull({{1, 3}, {2, 2}, {Rational(1, 2), Rational(1, 2)}});
  BOOST_TEST((max_area_point(at_end) == Point2{2, 2}));
  if (numerics::extended_precision_active()) {
    BOOST_TEST(counts[0] == filtered0 + 1);
    BOOST_TEST(counts[1] == exact0 + 1);
  } else {  // the filter is not tried
    BOOST_TEST(counts[0] == filtered0);
    BOOST_TEST(counts[1] == exact0 + 2);
  }
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
