// Finlayson's (1996) illumination constraint: C = conv{c ⊘ e_j} in perspective, and F ∩ C.
#include "../test_support.h"

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/geometry/intersection.h>

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
Colour times(const Colour& s, const Colour& e) {
  return {Rational(s.r * e.r), Rational(s.g * e.g), Rational(s.b * e.b)};
}
std::vector<Point2> chromaticities(const std::vector<Colour>& cs) {
  return perspective_chromaticities(cs, NonPositiveBluePolicy::reject).points;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(illumination_constraint_2d)

BOOST_AUTO_TEST_CASE(map_of_a_light_is_c_over_e_in_perspective) {
  // c = (2, 3, 5), e = (1, 2, 4): d = (2, 3/2, 5/4), m = (8/5, 6/5).
  BOOST_TEST((illuminant_map({1, 2, 4}, {2, 3, 5}) == Point2{Rational(8, 5), Rational(6, 5)}));
  BOOST_TEST((illuminant_map({3, 3, 3}, {1, 1, 1}) == Point2{1, 1}));
  BOOST_CHECK_THROW(illuminant_map({0, 1, 1}, {1, 1, 1}), std::invalid_argument);
  const ConvexSet2 one = illumination_constraint({{1, 2, 4}}, {2, 3, 5});
  BOOST_TEST(one.kind == ConvexKind::point);
  // Lights that differ only in intensity have one map.
  BOOST_TEST(illumination_constraint({{1, 2, 4}, {2, 4, 8}}, {1, 1, 1}).kind == ConvexKind::point);
  try {
    illumination_constraint({{1, 1, 1}, {1, 0, 1}}, {1, 1, 1});
    BOOST_FAIL("expected NonPositiveIlluminant");
  } catch (const NonPositiveIlluminant& e) {
    BOOST_TEST(e.index == 1u);
  }
  BOOST_CHECK_THROW(illumination_constraint({}, {1, 1, 1}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(intersection_of_any_kinds_is_exact) {
  const ConvexSet2 sq = convex_hull({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  const ConvexSet2 tri = convex_hull({{1, 1}, {3, 1}, {1, 3}});
  BOOST_TEST(intersection(sq, tri) == convex_hull({{1, 1}, {2, 1}, {2, 2}, {1, 2}}));
  // Touching along an edge: a segment, not empty (no regularisation).
  const ConvexSet2 right = convex_hull({{2, 0}, {4, 0}, {4, 2}, {2, 2}});
  BOOST_TEST(intersection(sq, right) == convex_hull({{2, 0}, {2, 2}}));
  // Touching at a corner: a point.
  BOOST_TEST(intersection(sq, convex_hull({{2, 2}, {3, 2}, {3, 3}})) == convex_hull({{2, 2}}));
  // Segment through a polygon, point in and out, disjoint.
  BOOST_TEST(intersection(convex_hull({{-1, 1}, {3, 1}}), sq) == convex_hull({{0, 1}, {2, 1}}));
  BOOST_TEST(intersection(convex_hull({{1, 1}}), sq) == convex_hull({{1, 1}}));
  BOOST_TEST(intersection(convex_hull({{3, 1}}), sq).kind == ConvexKind::empty);
  BOOST_TEST(intersection(sq, convex_hull({{5, 5}, {6, 5}, {6, 6}})).kind == ConvexKind::empty);
  BOOST_TEST(intersection(ConvexSet2{}, sq).kind == ConvexKind::empty);
  // Two crossing segments meet in a point; collinear overlapping ones in a segment.
  BOOST_TEST(intersection(convex_hull({{0, 0}, {2, 2}}), convex_hull({{0, 2}, {2, 0}})) ==
             convex_hull({{1, 1}}));
  BOOST_TEST(intersection(convex_hull({{0, 0}, {2, 2}}), convex_hull({{1, 1}, {3, 3}})) ==
             convex_hull({{1, 1}, {2, 2}}));
}

BOOST_AUTO_TEST_CASE(random_intersections_contain_exactly_the_common_points) {
  Rng rng(1996);
  int proper = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const ConvexSet2 a = convex_hull(test::random_points(rng, 1 + trial % 9, 0, 4, 3));
    const ConvexSet2 b = convex_hull(test::random_points(rng, 1 + trial % 7, 0, 4, 3));
    const ConvexSet2 r = intersection(a, b);
    BOOST_TEST(intersection(b, a) == r);  // the same exact set either way round
    proper += r.kind == ConvexKind::polygon;
    for (const Point2& v : r.vertices) BOOST_TEST((contains(a, v) && contains(b, v)));
    // Points on the grid of the inputs and half-way between: in r iff in both.
    for (int s = 0; s < 60; ++s) {
      const Point2 m = test::random_points(rng, 1, 0, 4, 6)[0];
      BOOST_TEST(contains(r, m) == (contains(a, m) && contains(b, m)));
    }
    // The vertices of a and b that lie in both are in r (touching results are not lost).
    for (const ConvexSet2* s : {&a, &b})
      for (const Point2& v : s->vertices)
        if (contains(a, v) && contains(b, v)) BOOST_TEST(contains(r, v));
  }
  BOOST_TEST(proper > 20);
}

// Surfaces seen under a canonical light c and under the scene light e_true (diagonal model):
// two surfaces leave a large F; the plausible lights cut it down to a small set around the truth.
BOOST_AUTO_TEST_CASE(constraint_turns_a_large_feasible_set_into_a_small_one_with_the_truth) {
  const Colour c{1, 1, 1};
  const std::vector<Colour> surfaces{{1, 1, 1},       {Rational(9, 10), Rational(1, 5), 1},
                                     {Rational(1, 5), Rational(9, 10), Rational(1, 2)},
                                     {1, Rational(4, 5), Rational(1, 5)},
                                     {Rational(1, 10), Rational(1, 5), 1}};
  std::vector<Colour> canonical;
  for (const Colour& s : surfaces) canonical.push_back(times(s, c));
  const Colour e_true{Rational(6, 5), 1, Rational(7, 10)};  // a yellowish light
  const std::vector<Colour> image{times(surfaces[0], e_true), times(surfaces[1], e_true)};
  const ConvexSet2 G = convex_hull(chromaticities(canonical));
  const ConvexSet2 F = feasible_set(G, chromaticities(image));
  const Point2 truth = illuminant_map(e_true, c);
  BOOST_TEST(F.kind == ConvexKind::polygon);
  BOOST_TEST(contains(F, truth));

  // Plausible lights: a small daylight-like family around e_true, e_true among them.
  const std::vector<Colour> lights{e_true,
                                   {Rational(13, 10), 1, Rational(6, 10)},
                                   {Rational(11, 10), 1, Rational(8, 10)},
                                   {Rational(6, 5), Rational(21, 20), Rational(7, 10)}};
  const ConvexSet2 C = illumination_constraint(lights, c);
  const ConvexSet2 R = intersection(F, C);
  BOOST_TEST(R.kind != ConvexKind::empty);
  BOOST_TEST(contains(R, truth));
  BOOST_TEST(contains(C, truth));
  BOOST_TEST(area(R) * 20 < area(F));  // at least twenty times smaller
  for (const Point2& v : R.vertices)
    BOOST_TEST(test::feasible_by_definition(G, chromaticities(image), v));
}

BOOST_AUTO_TEST_CASE(constraint_can_make_the_feasible_set_empty) {
  const ConvexSet2 G = convex_hull({{1, 1}, {2, 1}, {2, 2}, {1, 2}});
  const ConvexSet2 F = feasible_set(G, {{1, 1}});  // = G
  // Only bluish lights: their maps (1/e_r, 1/e_g)·e_b are all > 2 in both components.
  const ConvexSet2 C = illumination_constraint({{1, 1, 3}, {1, 2, 5}, {2, 1, 5}}, {1, 1, 1});
  BOOST_TEST(C.kind == ConvexKind::polygon);
  BOOST_TEST(intersection(F, C).kind == ConvexKind::empty);
  // A light whose map is a corner of F: F ∩ C is that point.
  const ConvexSet2 corner = illumination_constraint({{1, 1, 2}, {1, 1, 3}}, {1, 1, 1});
  BOOST_TEST(intersection(F, corner) == convex_hull({{2, 2}}));
}

BOOST_AUTO_TEST_SUITE_END()
