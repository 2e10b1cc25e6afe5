// score_rules: the one place the experiments' route is chosen. Its certified route must agree
// with its exact route within rule_errors_accuracy, take the exact route whenever the options
// rule the certified one out, and its exact route must equal select_maps with angular_error.h.
#include "../test_support.h"

#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/score_rules.h>
#include <gmcc/selection/select_maps.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
struct Scene {
  FeasiblePolygon F;
  Point2 truth;
  Colour c;
};

// A canonical polygon, an image of 2–6 of its colours under a random true map (truth in F),
// a random canonical light.
Scene random_scene(Rng& rng, int trial) {
  const auto pts = test::random_points(rng, 8 + trial % 12, 1, 5, 10007);
  const ConvexSet2 G = convex_hull(pts);
  const Point2 truth{test::random_rational(rng, 100, 900, 997), test::random_rational(rng, 100, 900, 991)};
  std::vector<Point2> image;
  for (int i = 0; i < 2 + trial % 5; ++i) {
    const Point2& p = pts[std::uniform_int_distribution<std::size_t>(0, pts.size() - 1)(rng)];
    image.push_back({Rational(p.x / truth.x), Rational(p.y / truth.y)});
  }
  return {feasible_polygon(CanonicalConstraints(G), image), truth,
          Colour{test::random_rational(rng, 1, 9, 7), test::random_rational(rng, 1, 9, 7),
                 test::random_rational(rng, 1, 9, 7)}};
}

bool close(double a, double b) { return std::fabs(a - b) <= rule_errors_accuracy * (1 + std::fabs(b)) + 1e-13; }
}  // namespace

BOOST_AUTO_TEST_SUITE(score_rules_route)

BOOST_AUTO_TEST_CASE(certified_and_exact_routes_agree) {
  Rng rng(1425);
  int certified = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const Scene s = random_scene(rng, trial);
    BOOST_REQUIRE(s.F.kind() != ConvexKind::empty);
    const ScoredRules fast = score_rules(s.F, s.truth, s.c, {});
    ScoreOptions exact_only;
    exact_only.certified_route = false;
    const ScoredRules exact = score_rules(s.F, s.truth, s.c, exact_only);
    BOOST_TEST(!exact.certified);
    certified += fast.certified;
    for (std::size_t r = 0; r < 3; ++r) {
      BOOST_TEST_REQUIRE(fast.rules.values[r].has_value());
      BOOST_TEST_REQUIRE(exact.rules.values[r].has_value());
      const RuleErrors &a = *fast.rules.values[r], &b = *exact.rules.values[r];
      BOOST_TEST(close(a.map_error_deg, b.map_error_deg), "rule " << r << " trial " << trial);
      BOOST_TEST(close(a.worst_case_deg, b.worst_case_deg), "rule " << r << " trial " << trial);
      BOOST_TEST(a.positive_map == b.positive_map);
      if (a.positive_map) {
        BOOST_TEST(close(a.illuminant_error_deg, b.illuminant_error_deg));
        BOOST_TEST(close(a.reproduction_error_deg, b.reproduction_error_deg));
      }
    }
    BOOST_TEST(std::fabs(fast.area - exact.area) <= 1e-9 * exact.area);
  }
  // The certified route answers many of these scenes (most with the x87 stage; about 60% of
  // certified_rule_errors' scenes without it, test_rule_errors.cpp).
  BOOST_TEST(certified > 30);
}

// The exact route is select_maps with the angular_error.h functions on each rule's exact map.
BOOST_AUTO_TEST_CASE(exact_route_is_select_maps_and_the_exact_angles) {
  Rng rng(1426);
  for (int trial = 0; trial < 20; ++trial) {
    const Scene s = random_scene(rng, trial);
    ScoreOptions exact_only;
    exact_only.certified_route = false;
    const ScoredRules x = score_rules(s.F, s.truth, s.c, exact_only);
    const Selections sel = select_maps(s.F.exact());
    const std::array<const std::optional<Selection>*, 3> rules{&sel[gmcc::Rule::max_area], &sel[gmcc::Rule::mean_2d], &sel[gmcc::Rule::mean_3d]};
    BOOST_TEST(x.area == to_double_nearest(area(s.F.exact())));
    for (std::size_t r = 0; r < 3; ++r) {
      const MapEstimate& e = (**rules[r]).estimate;
      const Point2 m = e.exact ? *e.exact : Point2{rational_from_double(e.map[0]), rational_from_double(e.map[1])};
      BOOST_TEST(x.rules.values[r]->map_error_deg == map_angular_error_deg(m, s.truth));
      BOOST_TEST(x.rules.values[r]->worst_case_deg == *(**rules[r]).worst_case_deg);
      BOOST_TEST(x.rules.values[r]->map[0] == e.map[0]);
      BOOST_TEST(x.rules.values[r]->map[1] == e.map[1]);
    }
  }
}

// Options that rule the certified route out: a 3-D mean by Monte Carlo or quadrature, or a
// forced precision. The Monte Carlo record with too few samples in the cone is absent.
BOOST_AUTO_TEST_CASE(options_that_rule_out_the_certified_route) {
  Rng rng(1427);
  const Scene s = random_scene(rng, 3);
  ScoreOptions mc;
  mc.mean3d.method = Mean3dMethod::monte_carlo;
  mc.mean3d.samples = 20000;
  ScoreOptions forced;
  forced.mean3d.precision_bits = 200;
  for (const ScoreOptions& o : {mc, forced}) BOOST_TEST(!score_rules(s.F, s.truth, s.c, o).certified);
  mc.mean3d.samples = 1;  // no sample can land in the cone often enough
  const ScoredRules few = score_rules(s.F, s.truth, s.c, mc);
  BOOST_TEST(few.rules.values[0].has_value());
  BOOST_TEST(!few.rules.values[2].has_value());
  BOOST_CHECK_THROW(score_rules(s.F, s.truth, Colour{1, 1, 0}, {}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
