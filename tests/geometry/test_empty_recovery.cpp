// Recovery policies for an empty feasible set: grow the canonical gamut (bisection on the
// multiplicative factor) and Chebyshev least violation (exact LP).
#include "../test_support.h"

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/grow_canonical.h>
#include <gmcc/geometry/intersection.h>
#include <gmcc/geometry/min_violation.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
const std::vector<Point2> unit_square{{1, 1}, {2, 1}, {2, 2}, {1, 2}};

// Independent of the library's half-plane formula: the Chebyshev distance from x to a segment
// p–r is min over s ∈ [0, 1] of max(|f1(s)|, |f2(s)|) with f = x − p − s(r − p), a convex
// piecewise-linear function whose minimum is at s = 0, 1 or where f1, f2, f1 ± f2 vanish.
Rational chebyshev_to_segment(const Point2& x, const Point2& p, const Point2& r) {
  const Rational a1 = x.x - p.x, a2 = x.y - p.y, u1 = r.x - p.x, u2 = r.y - p.y;
  std::vector<Rational> ss{0, 1};
  auto root = [&ss](const Rational& a, const Rational& u) {  // a − s·u = 0
    if (sgn(u) != 0) ss.push_back(a / u);
  };
  root(a1, u1), root(a2, u2), root(a1 - a2, u1 - u2), root(a1 + a2, u1 + u2);
  Rational best = -1;
  for (const Rational& s : ss) {
    if (sgn(s) < 0 || s > 1) continue;
    const Rational d = std::max(abs(Rational(a1 - s * u1)), abs(Rational(a2 - s * u2)));
    if (sgn(best) < 0 || d < best) best = d;
  }
  return best;
}
// δ(x, G): + distance to G outside, − distance to the boundary inside (G a polygon).
Rational signed_chebyshev(const Point2& x, const ConvexSet2& G) {
  Rational best = -1;
  const auto& v = G.vertices;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Rational d = chebyshev_to_segment(x, v[i], v[(i + 1) % v.size()]);
    if (sgn(best) < 0 || d < best) best = d;
  }
  return contains(G, x) ? Rational(-best) : best;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(empty_feasible_set_recovery)

BOOST_AUTO_TEST_CASE(grow_canonical_brackets_an_irrational_threshold) {
  // G = [1, 2]², image x-extent 1..4: m1 ∈ [1/s, 2s] ∩ [1/(4s), s/2] needs s² >= 2, so the least
  // factor is √2 − 1, irrational: the result brackets it.
  const std::vector<Point2> image{{1, 1}, {4, 1}};
  BOOST_TEST(feasible_set(convex_hull(unit_square), image).kind == ConvexKind::empty);
  GrowCanonicalOptions o;
  o.precision = Rational(1, 1000000);
  const GrownFeasibleSet g = grow_canonical_until_feasible(unit_square, image, {}, o);
  BOOST_REQUIRE(g.found);
  BOOST_REQUIRE(g.empty_below.has_value());
  const Rational lo = *g.empty_below, hi = g.factor;
  BOOST_TEST(hi - lo <= o.precision);
  BOOST_TEST((1 + lo) * (1 + lo) < 2);
  BOOST_TEST((1 + hi) * (1 + hi) >= 2);
  // The statement holds by recomputation: empty at lo, non-empty at hi.
  const auto F_at = [&](const Rational& f) {
    return feasible_set(canonical_gamut(unit_square, {ExpansionPolicy::multiplicative, f}), image);
  };
  BOOST_TEST(F_at(lo).kind == ConvexKind::empty);
  BOOST_TEST(F_at(hi) == g.feasible);
  BOOST_TEST(g.feasible.kind != ConvexKind::empty);
  BOOST_TEST(g.canonical == canonical_gamut(unit_square, {ExpansionPolicy::multiplicative, hi}));
}

BOOST_AUTO_TEST_CASE(grow_canonical_with_a_constraint_and_when_nothing_helps) {
  // F = G = [1, 2]² misses the map (3, 3) of the only plausible light; growth by s = 3/2 reaches it.
  const ConvexSet2 C = convex_hull({{3, 3}});
  const GrownFeasibleSet g = grow_canonical_until_feasible(unit_square, {{1, 1}}, C);
  BOOST_REQUIRE(g.found);
  BOOST_TEST(*g.empty_below < Rational(1, 2));
  BOOST_TEST(g.factor >= Rational(1, 2));
  BOOST_TEST(g.feasible == C);
  // Already feasible at the start: nothing grows.
  const GrownFeasibleSet same = grow_canonical_until_feasible(unit_square, {{1, 1}});
  BOOST_TEST(same.found);
  BOOST_TEST(same.factor == 0);
  BOOST_TEST(!same.empty_below.has_value());
  // An image colour with r = 0 can never be mapped into a gamut with r/b >= 1/s > 0.
  GrowCanonicalOptions o;
  o.max_factor = 64;
  const GrownFeasibleSet never = grow_canonical_until_feasible(unit_square, {{0, 1}, {1, 1}}, {}, o);
  BOOST_TEST(!never.found);
  BOOST_TEST(never.feasible.kind == ConvexKind::empty);
  BOOST_TEST(*never.empty_below == 64);
}

BOOST_AUTO_TEST_CASE(min_violation_by_hand) {
  // m1 must serve q1 = 1 (m1 ∈ [1, 2]) and q1 = 4 (m1 ∈ [1/4, 1/2]): the Chebyshev compromise
  // 1 − m1 = 4·m1 − 2 gives m1 = 3/5 and violation 2/5; m2 is free within 2/5 of [1, 2].
  const ConvexSet2 G = convex_hull(unit_square);
  const std::vector<Point2> image{{1, 1}, {4, 1}};
  const MinViolation v = min_violation(G, image);
  BOOST_TEST(v.violation == Rational(2, 5));
  BOOST_TEST(v.feasible == convex_hull({{Rational(3, 5), Rational(3, 5)},
                                        {Rational(3, 5), Rational(12, 5)}}));
  BOOST_TEST(v.canonical == convex_hull({{Rational(3, 5), Rational(3, 5)},
                                         {Rational(12, 5), Rational(3, 5)},
                                         {Rational(12, 5), Rational(12, 5)},
                                         {Rational(3, 5), Rational(12, 5)}}));
  // The minimisers are exactly the feasible set of the grown gamut.
  BOOST_TEST(feasible_set(v.canonical, image) == v.feasible);
  // A non-empty F: t* <= 0 and the minimisers are its Chebyshev-deepest maps.
  const MinViolation inside = min_violation(G, {{1, 1}});
  BOOST_TEST(inside.violation == Rational(-1, 2));
  BOOST_TEST(inside.feasible == convex_hull({{Rational(3, 2), Rational(3, 2)}}));
  // A hard constraint moves the answer: m must be (1, 3).
  const MinViolation forced = min_violation(G, {{1, 1}}, convex_hull({{1, 3}}));
  BOOST_TEST(forced.violation == 1);
  BOOST_TEST(forced.feasible == convex_hull({{1, 3}}));
}

BOOST_AUTO_TEST_CASE(min_violation_is_the_chebyshev_optimum_on_random_scenes) {
  Rng rng(2002);
  int empties = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const ConvexSet2 G = convex_hull(test::random_points(rng, 3 + trial % 9, 1, 4, 4));
    if (G.kind != ConvexKind::polygon) continue;
    std::vector<Point2> image = test::random_points(rng, 1 + trial % 6, 1, 5, 4);
    const ConvexSet2 F = feasible_set(G, image);
    const MinViolation v = min_violation(G, image);
    empties += F.kind == ConvexKind::empty;
    BOOST_TEST((sgn(v.violation) > 0) == (F.kind == ConvexKind::empty));
    BOOST_REQUIRE(v.feasible.kind != ConvexKind::empty);
    // The measure, independently: max over image colours of the signed Chebyshev distance.
    auto measure = [&](const Point2& m) {
      Rational worst;
      bool first = true;
      for (const Point2& q : image) {
        const Rational d = signed_chebyshev(test::times(m, q), G);
        if (first || d > worst) worst = d, first = false;
      }
      return worst;
    };
    for (const Point2& m : v.feasible.vertices) {
      BOOST_TEST(measure(m) == v.violation);
      BOOST_TEST(gamut_violation(G, image, m) == v.violation);
    }
    // No map does better (random maps, and maps near the minimisers).
    const Point2 c = centroid(v.feasible);
    for (int s = 0; s < 40; ++s) {
      const Point2 m = s % 2 ? test::random_points(rng, 1, 0, 3, 8)[0]
                             : Point2{Rational(c.x + test::random_rational(rng, -8, 8, 64)),
                                      Rational(c.y + test::random_rational(rng, -8, 8, 64))};
      if (sgn(m.x) < 0 || sgn(m.y) < 0) continue;
      const Rational value = measure(m);
      BOOST_TEST(value >= v.violation);
      BOOST_TEST(gamut_violation(G, image, m) == value);
      BOOST_TEST((value == v.violation) == contains(v.feasible, m));
    }
  }
  BOOST_TEST(empties > 10);
}

BOOST_AUTO_TEST_SUITE_END()
