#include "../test_support.h"
#include "quadrature_reference.h"

#include <gmcc/selection/mean_3d_analytic.h>
#include <gmcc/selection/mean_3d_double.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
double max_abs_diff(const std::array<double, 2>& a, const std::array<long double, 2>& b) {
  return static_cast<double>(std::max(std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1])));
}
double max_abs_diff(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return std::max(std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]));
}
// A 5-gon of the given width around (11/10, 7/10) (MATH §1a.7's conditioning example).
ConvexSet2 small_pentagon(const Rational& width) {
  const Point2 c{Rational(11, 10), Rational(7, 10)};
  const std::vector<std::pair<int, int>> shape{{0, 0}, {3, -1}, {5, 2}, {2, 5}, {-1, 3}};
  std::vector<Point2> pts;
  for (auto [dx, dy] : shape) pts.push_back({Rational(c.x + width * dx / 5), Rational(c.y + width * dy / 5)});
  return convex_hull(pts);
}
}  // namespace

BOOST_AUTO_TEST_SUITE(mean_3d_rule)

// Finlayson & Hordley (1999) toy example: the 3-D mean recovers the true map (1, 1) under the
// fan-bisector convention for segments (MATH §1a.6).
BOOST_AUTO_TEST_CASE(paper_toy_example_recovers_the_identity) {
  const ConvexSet2 toy{ConvexKind::segment, {{Rational(1, 3), Rational(2, 3)}, {3, 2}}};
  const MapEstimate e = mean_3d_analytic(toy);
  BOOST_TEST(e.method == "analytic");
  BOOST_TEST(std::fabs(e.map[0] - 1.0) <= e.error_bound);
  BOOST_TEST(std::fabs(e.map[1] - 1.0) <= e.error_bound);
  BOOST_TEST(e.error_bound < 1e-15);
  BOOST_TEST((*e.enclosure)[0][0] <= 1.0);
  BOOST_TEST((*e.enclosure)[0][1] >= 1.0);
}

BOOST_AUTO_TEST_CASE(a_point_is_itself_exactly) {
  const ConvexSet2 pt{ConvexKind::point, {{Rational(1, 3), 2}}};
  const MapEstimate e = mean_3d_analytic(pt);
  BOOST_TEST((*e.exact == Point2{Rational(1, 3), 2}));
}

BOOST_AUTO_TEST_CASE(reversing_the_vertex_order_changes_nothing) {
  Rng rng(41);
  for (int trial = 0; trial < 20; ++trial) {
    ConvexSet2 F = convex_hull(test::random_points(rng, 8, 1, 4, 7));
    if (F.kind != ConvexKind::polygon) continue;
    const MapEstimate ccw = mean_3d_analytic(F);
    std::reverse(F.vertices.begin(), F.vertices.end());
    const MapEstimate cw = mean_3d_analytic(F);
    BOOST_TEST(cw.map == ccw.map);
  }
}

BOOST_AUTO_TEST_CASE(closed_form_agrees_with_independent_quadrature) {
  Rng rng(1995);
  for (int trial = 0; trial < 40; ++trial) {
    const ConvexSet2 F = convex_hull(test::random_points(rng, 3 + trial % 10, 1, 3, 9));
    if (F.kind != ConvexKind::polygon) continue;
    const MapEstimate e = mean_3d_analytic(F);
    const auto q = test::weighted_centroid_reference(F, 40);
    BOOST_TEST(max_abs_diff(e.map, q) < 1e-12, "trial " << trial);
    BOOST_TEST(e.error_bound < 1e-15 * std::max(e.map[0], e.map[1]) + 1e-300);
    // The 3-D mean is not the 2-D mean: the weight pulls it toward the origin's ray.
  }
}

BOOST_AUTO_TEST_CASE(closed_form_agrees_with_a_4096_bit_evaluation) {
  Rng rng(4096);
  for (int trial = 0; trial < 10; ++trial) {
    const ConvexSet2 F = convex_hull(test::random_points(rng, 9, 1, 5, 11));
    if (F.kind != ConvexKind::polygon) continue;
    const MapEstimate fast = mean_3d_analytic(F);
    const MapEstimate slow = mean_3d_analytic(F, AnalyticOptions{4096});
    BOOST_TEST(slow.precision_bits == 4096u);
    BOOST_TEST(slow.error_bound <= fast.error_bound);
    for (int k = 0; k < 2; ++k) {
      BOOST_TEST(std::fabs(fast.map[k] - slow.map[k]) <= fast.error_bound + slow.error_bound);
      BOOST_TEST((*slow.enclosure)[k][0] >= (*fast.enclosure)[k][0]);  // nested enclosures
      BOOST_TEST((*slow.enclosure)[k][1] <= (*fast.enclosure)[k][1]);
    }
  }
}

// SPEC §6: agrees with a high-precision evaluation to 1e-15 relative down to width 1e-9,
// where the double-precision closed form is garbage (MATH §1a.7).
BOOST_AUTO_TEST_CASE(tiny_feasible_sets_double_fails_mpfi_does_not) {
  for (const char* w : {"1/100", "1/10000", "1/1000000", "1/1000000000", "1/1000000000000"}) {
    const ConvexSet2 F = small_pentagon(Rational(w));
    BOOST_REQUIRE(F.kind == ConvexKind::polygon);
    const MapEstimate e = mean_3d_analytic(F);
    const MapEstimate ref = mean_3d_analytic(F, AnalyticOptions{2048});
    const double scale = std::max(e.map[0], e.map[1]);
    BOOST_TEST(e.error_bound <= 1e-15 * scale, w);
    BOOST_TEST(max_abs_diff(e.map, ref.map) <= 1e-15 * scale, w);
    BOOST_TEST(max_abs_diff(e.map, test::weighted_centroid_reference(F, 8)) <= 1e-15 * scale, w);
  }
  const ConvexSet2 tiny = small_pentagon(Rational(1, 1000000000));
  const double double_error = max_abs_diff(mean_3d_double(tiny), mean_3d_analytic(tiny).map);
  BOOST_TEST(double_error > 1e-6);  // the naive double closed form has lost every digit
}

BOOST_AUTO_TEST_CASE(the_double_baseline_is_fine_on_large_polygons) {
  const ConvexSet2 F = convex_hull({{Rational(3, 10), Rational(1, 4)}, {4, Rational(1, 2)},
                                    {Rational(43, 10), 3}, {2, Rational(13, 4)}, {Rational(1, 2), 2}});
  BOOST_TEST(max_abs_diff(mean_3d_double(F), mean_3d_analytic(F).map) < 1e-13);
}

BOOST_AUTO_TEST_SUITE_END()
