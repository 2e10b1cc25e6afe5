// The three routes to the 3-D mean (docs/math.md §2) against each other, within their own bounds.
#include "../test_support.h"

#include <gmcc/selection/mean_3d.h>
#include <gmcc/numerics/platform.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
double distance(const MapEstimate& a, const MapEstimate& b) {
  return std::max(std::fabs(a.map[0] - b.map[0]), std::fabs(a.map[1] - b.map[1]));
}
ConvexSet2 random_polygon(Rng& rng, int n) {
  for (;;) {
    ConvexSet2 F = convex_hull(test::random_points(rng, n, 1, 3, 9));
    if (F.kind == ConvexKind::polygon) return F;
  }
}
// A quadrilateral of the given width around (6/5, 4/5).
ConvexSet2 small_quad(const Rational& w) {
  const Point2 c{Rational(6, 5), Rational(4, 5)};
  return convex_hull({c, {Rational(c.x + w), c.y}, {Rational(c.x + w), Rational(c.y + w / 2)},
                      {Rational(c.x + w / 3), Rational(c.y + w)}});
}
}  // namespace

BOOST_AUTO_TEST_SUITE(mean_3d_routes)

BOOST_AUTO_TEST_CASE(analytic_quadrature_and_monte_carlo_agree_within_their_bounds) {
  Rng rng(2024);
  for (int trial = 0; trial < 25; ++trial) {
    const ConvexSet2 F = random_polygon(rng, 3 + trial % 10);
    const MapEstimate a = mean_3d(F, {Mean3dMethod::analytic});
    const MapEstimate q = mean_3d(F, {Mean3dMethod::quadrature, 0, 12});
    const MapEstimate mc = mean_3d(F, {Mean3dMethod::monte_carlo, 0, 12, 200000, 7u + trial});
    BOOST_TEST(a.method == "analytic");
    BOOST_TEST(q.method == "quadrature");
    BOOST_TEST(mc.method == "monte-carlo");
    BOOST_REQUIRE(mc.valid);
    BOOST_TEST(distance(a, q) <= a.error_bound + q.error_bound, "trial " << trial);
    for (int k = 0; k < 2; ++k)  // deterministic seeds: 5 sigma never trips by chance here
      BOOST_TEST(std::fabs(mc.map[k] - a.map[k]) <= 5 * mc.standard_error[k], "trial " << trial);
  }
}

BOOST_AUTO_TEST_CASE(analytic_uses_the_double_fast_path_only_when_its_bound_allows) {
  Rng rng(53);
  const ConvexSet2 big = random_polygon(rng, 12);
  const MapEstimate fast = mean_3d_analytic(big);
  // The double-word stage decides on every platform (docs/math.md "The double-word stage"; its
  // precision is reported since output contract 2, docs/cli.md "JSON output").
  BOOST_TEST(fast.precision_bits == 106u);
  BOOST_TEST(fast.error_bound <= std::ldexp(std::max(fast.map[0], fast.map[1]), -49));
  const MapEstimate reference = mean_3d_analytic(big, {1024});
  BOOST_TEST(distance(fast, reference) <= fast.error_bound + reference.error_bound);
  // At width 1e-9 a double or x87 enclosure is far too wide: the double-word stage from exact
  // edges (losing log2(1/w) bits of 106) or MPFI takes over.
  const MapEstimate tiny = mean_3d_analytic(small_quad(Rational(1, 1000000000)));
  BOOST_TEST(tiny.precision_bits > 64u);
  BOOST_TEST(tiny.error_bound <= 1e-15 * tiny.map[0]);
}

BOOST_AUTO_TEST_CASE(quadrature_error_estimate_is_honest_and_converges) {
  Rng rng(12);
  for (int trial = 0; trial < 8; ++trial) {
    const ConvexSet2 F = random_polygon(rng, 8);
    const MapEstimate a = mean_3d_analytic(F, {512});
    double previous = INFINITY;
    for (unsigned n : {2u, 4u, 8u, 16u}) {
      const MapEstimate q = mean_3d_quadrature(F, n);
      const double actual = distance(q, a);
      BOOST_TEST(actual <= 1.5 * q.error_bound + a.error_bound, "order " << n);
      BOOST_TEST(actual <= previous * 1.0001 + 1e-15, "order " << n);
      previous = actual;
    }
  }
}

BOOST_AUTO_TEST_CASE(quadrature_in_offsets_keeps_tiny_polygons_accurate) {
  for (const char* w : {"1/1000000", "1/1000000000", "1/1000000000000"}) {
    const ConvexSet2 F = small_quad(Rational(w));
    const MapEstimate a = mean_3d_analytic(F), q = mean_3d_quadrature(F, 8);
    BOOST_TEST(distance(a, q) <= 2e-16 * a.map[0], w);
  }
}

BOOST_AUTO_TEST_CASE(reversing_the_vertex_order_changes_nothing) {
  Rng rng(99);
  for (int trial = 0; trial < 10; ++trial) {
    ConvexSet2 F = random_polygon(rng, 7);
    const MapEstimate a = mean_3d_analytic(F), q = mean_3d_quadrature(F);
    std::reverse(F.vertices.begin(), F.vertices.end());
    BOOST_TEST(mean_3d_analytic(F).map == a.map);
    BOOST_TEST(distance(mean_3d_quadrature(F), q) <= 2 * q.error_bound);
  }
}

BOOST_AUTO_TEST_CASE(segment_and_point_conventions) {
  const ConvexSet2 toy{ConvexKind::segment, {{Rational(1, 3), Rational(2, 3)}, {3, 2}}};
  const MapEstimate q = mean_3d_quadrature(toy, 12);
  BOOST_TEST(std::fabs(q.map[0] - 1.0) <= q.error_bound);  // the paper's (1, 1)
  BOOST_TEST(std::fabs(q.map[1] - 1.0) <= q.error_bound);
  BOOST_TEST(q.error_bound < 1e-12);
  const MapEstimate mc = mean_3d_monte_carlo(toy, 1000, 1);
  BOOST_TEST(!mc.valid);
  BOOST_TEST(mc.note.find("segment") != std::string::npos);
  const ConvexSet2 pt{ConvexKind::point, {{Rational(2, 3), 5}}};
  for (Mean3dMethod m : {Mean3dMethod::analytic, Mean3dMethod::quadrature, Mean3dMethod::monte_carlo}) {
    const MapEstimate e = mean_3d(pt, {m});
    BOOST_TEST((*e.exact == Point2{Rational(2, 3), 5}));
    BOOST_TEST(e.method == to_string(m));
  }
}

BOOST_AUTO_TEST_CASE(monte_carlo_standard_error_matches_its_spread_over_seeds) {
  Rng rng(314);
  const ConvexSet2 F = random_polygon(rng, 6);
  const MapEstimate a = mean_3d_analytic(F);
  double sum_z2 = 0;
  int within_2 = 0, count = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const MapEstimate mc = mean_3d_monte_carlo(F, 20000, seed);
    BOOST_REQUIRE(mc.valid);
    for (int k = 0; k < 2; ++k) {
      const double z = (mc.map[k] - a.map[k]) / mc.standard_error[k];
      sum_z2 += z * z;
      within_2 += std::fabs(z) < 2;
      ++count;
    }
  }
  // If the standard error is right, z is ≈ N(0,1): E z² = 1 and 95% lie within 2.
  BOOST_TEST(sum_z2 / count > 0.75);
  BOOST_TEST(sum_z2 / count < 1.3);
  BOOST_TEST(within_2 > 0.9 * count);
  BOOST_TEST(within_2 < 0.99 * count);
}

BOOST_AUTO_TEST_CASE(monte_carlo_is_reproducible_and_refuses_tiny_sets) {
  Rng rng(5);
  const ConvexSet2 F = random_polygon(rng, 5);
  const MapEstimate a = mean_3d_monte_carlo(F, 50000, 42), b = mean_3d_monte_carlo(F, 50000, 42);
  BOOST_TEST(a.map == b.map);
  BOOST_TEST(a.samples_kept == b.samples_kept);
  BOOST_TEST(mean_3d_monte_carlo(F, 50000, 43).map != a.map);
  const MapEstimate tiny = mean_3d_monte_carlo(small_quad(Rational(1, 1000000)), 100000, 1);
  BOOST_TEST(!tiny.valid);
  BOOST_TEST(tiny.samples_kept < monte_carlo_min_kept);
  BOOST_TEST(tiny.note.find("too small") != std::string::npos);
}

// A segment whose ends are equally far from the origin has the bisector (u1 + u2)/2 as its
// mean: with u1 = (1, 1 + 2^-52, 1), u2 = (1 + 2^-52, 1, 1) that is 1 + 2^-53 in both
// coordinates, exactly the midpoint between the doubles 1 and 1 + 2^-52. No enclosure can lie
// inside one rounding interval: the analytic route must stop at its cap, say so, and still
// bound the error; a forced precision says so too.
BOOST_AUTO_TEST_CASE(analytic_at_a_rounding_tie_stops_at_the_cap_and_says_so) {
  const Rational one(1), next(Rational(1) + Rational(1, mpz_class(1) << 52));
  const ConvexSet2 F = convex_hull({{one, next}, {next, one}});
  BOOST_REQUIRE(F.kind == ConvexKind::segment);
  const MapEstimate e = mean_3d(F, {Mean3dMethod::analytic});
  BOOST_TEST(e.valid);
  BOOST_TEST(e.precision_bits >= 8192u);
  BOOST_TEST(!e.note.empty());
  const Rational truth = Rational(1) + Rational(1, mpz_class(1) << 53);
  for (int k = 0; k < 2; ++k) {
    BOOST_TEST(!e.correctly_rounded[k]);
    BOOST_TEST((e.map[k] == 1.0 || e.map[k] == std::nextafter(1.0, 2.0)));
    BOOST_TEST(rational_from_double(e.error_bounds[k]) >= abs(Rational(rational_from_double(e.map[k]) - truth)));
  }
  const MapEstimate forced = mean_3d(F, {Mean3dMethod::analytic, 200});
  BOOST_TEST(forced.precision_bits == 200u);
  BOOST_TEST((!forced.correctly_rounded[0] && !forced.note.empty()));
  // Away from the tie the same kind of segment is decided at once.
  const MapEstimate off = mean_3d(convex_hull({{one, next}, {Rational(next + next - 1), one}}),
                                  {Mean3dMethod::analytic});
  BOOST_TEST((off.correctly_rounded[0] && off.correctly_rounded[1] && off.note.empty()));
}

// Where the weight (1 + |x|²)^-2 leaves the long double's range (|x| beyond ~10^1233) the
// quadrature cannot state its error: no map, and a note, never a silently wrong number.
BOOST_AUTO_TEST_CASE(quadrature_declines_beyond_the_extended_range) {
  const Rational big(mpz_class("1" + std::string(1300, '0')));
  const ConvexSet2 F = convex_hull({{big, big}, {Rational(2 * big), big}, {big, Rational(3 * big)}});
  BOOST_REQUIRE(F.kind == ConvexKind::polygon);
  const MapEstimate q = mean_3d(F, {Mean3dMethod::quadrature, 0, 12});
  BOOST_TEST(!q.valid);
  BOOST_TEST(q.note.find("quadrature cannot") != std::string::npos);
  // Such a map is beyond the doubles anyway: the analytic route says so at once (it used to
  // double its precision to 2^20 bits first), and so does quadrature just beyond 1.8e308.
  const MapEstimate a = mean_3d(F, {Mean3dMethod::analytic});
  BOOST_TEST((!a.valid && a.note.find("beyond the range of doubles") != std::string::npos));
  const Rational far(mpz_class("1" + std::string(309, '0')));
  const ConvexSet2 G = convex_hull({{far, far}, {Rational(2 * far), far}, {far, Rational(3 * far)}});
  const MapEstimate q2 = mean_3d(G, {Mean3dMethod::quadrature, 0, 12});
  BOOST_TEST((!q2.valid && q2.note.find("beyond the range of doubles") != std::string::npos));
  // Just inside the range both routes answer and agree.
  const Rational near(mpz_class("1" + std::string(300, '0')));
  const ConvexSet2 H = convex_hull({{near, near}, {Rational(2 * near), near}, {near, Rational(3 * near)}});
  const MapEstimate a3 = mean_3d(H, {Mean3dMethod::analytic}), q3 = mean_3d(H, {Mean3dMethod::quadrature, 0, 12});
  BOOST_TEST((a3.valid && q3.valid && a3.correctly_rounded[0] && a3.correctly_rounded[1]));
  for (int k = 0; k < 2; ++k)
    BOOST_TEST(std::fabs(a3.map[k] - q3.map[k]) <= a3.error_bounds[k] + q3.error_bounds[k]);
}

BOOST_AUTO_TEST_CASE(method_names_round_trip) {
  for (Mean3dMethod m : {Mean3dMethod::analytic, Mean3dMethod::quadrature, Mean3dMethod::monte_carlo})
    BOOST_TEST((mean3d_method_from_string(to_string(m)) == m));
  BOOST_CHECK_THROW(mean3d_method_from_string("simpson"), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
