#include "../test_support.h"
#include "feasible_set_reference.h"

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_set.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
ConvexSet2 square(const Rational& lo, const Rational& hi) {
  return convex_hull({{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}});
}
bool on_boundary(const ConvexSet2& set, const Point2& p) {
  const auto& v = set.vertices;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (sgn(orientation(v[i], v[(i + 1) % v.size()], p)) == 0) return true;
  return false;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(feasible_set_2d)

// Finlayson & Hordley (1999) Fig. 1 / BMVC'97 §3: canonical colours (3,2,1) and (1,2,3), image
// colour (1,1,1): the feasible maps are the segment (3,2)–(1/3,2/3) (docs/derivations.md §1.5).
BOOST_AUTO_TEST_CASE(paper_toy_example_is_a_segment) {
  const auto c = perspective_chromaticities({{3, 2, 1}, {1, 2, 3}}, NonPositiveBluePolicy::reject);
  const ConvexSet2 F = feasible_set(convex_hull(c.points), {{1, 1}});
  BOOST_TEST(F.kind == ConvexKind::segment);
  BOOST_TEST((F.vertices == std::vector<Point2>{{Rational(1, 3), Rational(2, 3)}, {3, 2}}));
  BOOST_TEST(area(F) == 0);
}

BOOST_AUTO_TEST_CASE(single_colours_give_a_point) {
  const ConvexSet2 F = feasible_set(convex_hull({{2, 3}}), {{4, Rational(1, 2)}});
  BOOST_TEST(F.kind == ConvexKind::point);
  BOOST_TEST((F.vertices == std::vector<Point2>{{Rational(1, 2), 6}}));
}

BOOST_AUTO_TEST_CASE(duplicates_and_interior_colours_change_nothing) {
  const ConvexSet2 G = convex_hull({{1, 1}, {3, 1}, {3, 2}, {1, 3}});
  const std::vector<Point2> image{{1, 1}, {Rational(3, 2), Rational(5, 4)}};
  const ConvexSet2 F = feasible_set(G, image);
  BOOST_TEST(F.kind == ConvexKind::polygon);
  BOOST_TEST(feasible_set(G, {image[0], image[1], image[0], image[1], image[1]}) == F);
  // A colour inside the image hull adds no constraint.
  const Point2 mid{Rational(5, 4), Rational(9, 8)};
  BOOST_TEST(feasible_set(G, {image[0], mid, image[1]}) == F);
}

BOOST_AUTO_TEST_CASE(collinear_image_colours_only_their_ends_matter) {
  const ConvexSet2 G = convex_hull({{1, 1}, {4, 1}, {4, 3}, {2, 4}, {1, 3}});
  const std::vector<Point2> ends{{1, 1}, {2, Rational(3, 2)}};
  const std::vector<Point2> line{{1, 1}, {Rational(3, 2), Rational(5, 4)}, {2, Rational(3, 2)},
                                 {Rational(5, 4), Rational(9, 8)}};
  BOOST_TEST(feasible_set(G, line) == feasible_set(G, ends));
}

BOOST_AUTO_TEST_CASE(image_colour_on_the_canonical_boundary) {
  // The identity map is feasible and lies on the boundary of F.
  const ConvexSet2 G = convex_hull({{1, 1}, {4, 1}, {4, 3}, {1, 3}});
  const ConvexSet2 F = feasible_set(G, {{4, 2}, {2, 2}});
  BOOST_TEST(F.kind == ConvexKind::polygon);
  BOOST_TEST(contains(F, {1, 1}));
  BOOST_TEST(on_boundary(F, {1, 1}));
}

BOOST_AUTO_TEST_CASE(point_segment_and_empty_feasible_sets) {
  const ConvexSet2 G = square(1, 2);
  // The image is the canonical gamut itself: only the identity fits.
  const ConvexSet2 point = feasible_set(G, G.vertices);
  BOOST_TEST(point.kind == ConvexKind::point);
  BOOST_TEST((point.vertices == std::vector<Point2>{{1, 1}}));
  // Image as wide as G in x, narrower in y: m1 = 1, m2 ∈ [1, 4/3].
  const ConvexSet2 segment = feasible_set(G, {{1, 1}, {2, Rational(3, 2)}});
  BOOST_TEST(segment.kind == ConvexKind::segment);
  BOOST_TEST((segment.vertices == std::vector<Point2>{{1, 1}, {1, Rational(4, 3)}}));
  // Too wide in x: m1 ∈ [1, 2] and m1 ∈ [1/4, 1/2] cannot both hold.
  const ConvexSet2 empty = feasible_set(G, {{1, 1}, {4, 1}});
  BOOST_TEST(empty.kind == ConvexKind::empty);
  BOOST_TEST(empty.vertices.empty());
}

BOOST_AUTO_TEST_CASE(canonical_segment_and_point) {
  const ConvexSet2 G = convex_hull({{1, 1}, {3, 2}});
  const ConvexSet2 F = feasible_set(G, {{1, 1}});
  BOOST_TEST(F == G);
  // Two image colours on a line through the origin of the map: only one map fits.
  const ConvexSet2 P = feasible_set(G, {{1, 1}, {3, 2}});
  BOOST_TEST(P.kind == ConvexKind::point);
  BOOST_TEST((P.vertices == std::vector<Point2>{{1, 1}}));
  const ConvexSet2 single = feasible_set(convex_hull({{2, 2}}), {{1, 1}, {2, 1}});
  BOOST_TEST(single.kind == ConvexKind::empty);
}

BOOST_AUTO_TEST_CASE(tiny_feasible_set_of_width_1e_9_is_exact) {
  const Rational w(1, 1000000000);
  const ConvexSet2 G = convex_hull({{1, 1}, {1 + w, 1}, {1 + w, 1 + w}, {1, 1 + w}});
  const ConvexSet2 F = feasible_set(G, {{2, Rational(1, 2)}});
  BOOST_TEST(F.kind == ConvexKind::polygon);
  BOOST_TEST(F.vertices.size() == 4u);
  BOOST_TEST(area(F) == Rational(w * w));  // scaled by 1/2 · 2
  BOOST_TEST((F.vertices.front() == Point2{Rational(1, 2), 2}));
}

BOOST_AUTO_TEST_CASE(image_colours_with_a_zero_channel) {
  const ConvexSet2 G = convex_hull({{0, 1}, {2, 1}, {2, 3}, {0, 3}});
  // q = (0, 1) constrains only m2; q = (1, 1) bounds m1.
  const ConvexSet2 F = feasible_set(G, {{0, 1}, {1, 1}});
  BOOST_TEST(F.kind == ConvexKind::polygon);
  BOOST_TEST(contains(F, {1, 2}));
  BOOST_CHECK_THROW(feasible_set(G, {{0, 1}, {0, 2}}), UnboundedFeasibleSet);
}

BOOST_AUTO_TEST_CASE(random_scenes_order_invariance_containment_and_maximality) {
  Rng rng(1999);
  int polygons = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const auto canonical_pts = test::random_points(rng, 3 + trial % 25, 1, 4, 6);
    const ConvexSet2 G = convex_hull(canonical_pts);
    // Image: canonical chromaticities under a random map, plus optional outliers.
    const Point2 d{test::random_rational(rng, 2, 12, 6), test::random_rational(rng, 2, 12, 6)};
    std::vector<Point2> image;
    const int k = 1 + trial % 8;
    for (int i = 0; i < k; ++i) {
      const Point2& p = canonical_pts[std::uniform_int_distribution<std::size_t>(
          0, canonical_pts.size() - 1)(rng)];
      image.push_back({Rational(p.x / d.x), Rational(p.y / d.y)});
    }
    if (trial % 5 == 0) image.push_back(test::random_points(rng, 1, 1, 3, 5)[0]);
    const ConvexSet2 F = feasible_set(G, image);
    polygons += F.kind == ConvexKind::polygon;

    // Order invariance: any permutation of either input gives the identical exact set.
    auto g2 = canonical_pts;
    auto i2 = image;
    std::shuffle(g2.begin(), g2.end(), rng);
    std::shuffle(i2.begin(), i2.end(), rng);
    BOOST_TEST(feasible_set(convex_hull(g2), i2) == F);

    // Noise-free scene without outliers: the true map lies in F.
    if (trial % 5 != 0) BOOST_TEST(contains(F, d));

    // Every vertex maps every image colour into G (exactly).
    for (const Point2& v : F.vertices) BOOST_TEST(test::feasible_by_definition(G, image, v));

    // Maximality: random maps around F are in F exactly when the definition says so.
    if (F.kind == ConvexKind::empty) continue;
    Rational lo_x = F.vertices[0].x, hi_x = lo_x, lo_y = F.vertices[0].y, hi_y = lo_y;
    for (const Point2& v : F.vertices) {
      lo_x = std::min(lo_x, v.x), hi_x = std::max(hi_x, v.x);
      lo_y = std::min(lo_y, v.y), hi_y = std::max(hi_y, v.y);
    }
    const Rational pad_x = (hi_x - lo_x) / 4 + Rational(1, 100);
    const Rational pad_y = (hi_y - lo_y) / 4 + Rational(1, 100);
    for (int s = 0; s < 60; ++s) {
      const Rational tx = test::random_rational(rng, 0, 1000, 1) / 1000;
      const Rational ty = test::random_rational(rng, 0, 1000, 1) / 1000;
      const Point2 m{Rational(lo_x - pad_x + tx * (hi_x - lo_x + 2 * pad_x)),
                     Rational(lo_y - pad_y + ty * (hi_y - lo_y + 2 * pad_y))};
      BOOST_TEST(contains(F, m) == test::feasible_by_definition(G, image, m));
    }
  }
  BOOST_TEST(polygons > 40);  // the generator does exercise proper polygons
}

// The filtered predicates against the unfiltered reference (every decision in GMP integers), on
// grid scenes where repeated, collinear and on-the-line vertices are common.
BOOST_AUTO_TEST_CASE(filtered_clipping_equals_exact_clipping_on_degenerate_grids) {
  Rng rng(6);
  int kinds[4] = {};
  for (int trial = 0; trial < 400; ++trial) {
    const auto canonical_pts = test::random_points(rng, 1 + trial % 9, 1, 4, 2 + trial % 3);
    const ConvexSet2 G = convex_hull(canonical_pts);
    std::vector<Point2> image;
    const Point2 d{test::random_rational(rng, 1, 6, 2), test::random_rational(rng, 1, 6, 2)};
    for (int i = 0; i < 1 + trial % 6; ++i) {
      const Point2& p = canonical_pts[std::uniform_int_distribution<std::size_t>(0, canonical_pts.size() - 1)(rng)];
      image.push_back(trial % 3 ? Point2{Rational(p.x / d.x), Rational(p.y / d.y)}
                                : test::random_points(rng, 1, 1, 4, 2)[0]);
    }
    const ConvexSet2 F = feasible_set(G, image);
    BOOST_TEST(F == test::reference::feasible_set_reference(G, image));
    ++kinds[static_cast<int>(F.kind)];
  }
  for (int k = 0; k < 4; ++k) BOOST_TEST(kinds[k] > 5);  // polygons, segments, points, empty sets
}

// Ulp-level degeneracies: canonical vertices a few ulps of double apart, and image colours whose
// constraint lines pass within 2^-70 of a vertex of F or exactly through it. The double filter
// cannot decide these; the exact fallback must, and the result must equal the reference.
BOOST_AUTO_TEST_CASE(filtered_clipping_on_ulp_level_degeneracies) {
  Rng rng(7);
  const Rational ulp(1, mpz_class(1) << 52), tiny(1, mpz_class(1) << 70);
  for (int trial = 0; trial < 150; ++trial) {
    const Rational base = test::random_rational(rng, 1, 8, 3);
    const Rational e = trial % 2 ? ulp : tiny;
    const int k = 1 + trial % 3;
    const ConvexSet2 G = convex_hull({{base, base},
                                      {Rational(base + k * e), base},
                                      {Rational(base + k * e), Rational(base + e)},
                                      {base, Rational(base + 2 * e)},
                                      {Rational(2 * base), Rational(base + e)}});
    std::vector<Point2> image{{1, 1}};
    if (trial % 5) image.push_back({Rational(1 + (trial % 4) * e), Rational(1 - (trial % 3) * e)});
    if (trial % 7 == 0) image.push_back({Rational(2), Rational(1)});
    const ConvexSet2 F = feasible_set(G, image);
    BOOST_TEST(F == test::reference::feasible_set_reference(G, image));
  }
}

// Inputs beyond the filter's range (coordinates near 2^±200) take the exact path throughout.
BOOST_AUTO_TEST_CASE(filtered_clipping_out_of_range_inputs_are_exact) {
  const Rational big(mpz_class(1) << 200), small(1, mpz_class(1) << 200);
  const ConvexSet2 G = convex_hull({{1, 1}, {3, 1}, {3, 2}, {1, 3}});
  for (const Rational& s : {big, small}) {
    const std::vector<Point2> image{{s, s}, {Rational(2 * s), s}};
    BOOST_TEST(feasible_set(G, image) == test::reference::feasible_set_reference(G, image));
  }
  const CanonicalConstraints prepared(G);
  const std::vector<Point2> image{{1, 1}, {Rational(3, 2), Rational(5, 4)}};
  BOOST_TEST(feasible_set(prepared, image) == feasible_set(G, image));
}

BOOST_AUTO_TEST_CASE(bad_arguments_throw) {
  BOOST_CHECK_THROW(feasible_set(ConvexSet2{}, {{1, 1}}), std::invalid_argument);
  BOOST_CHECK_THROW(feasible_set(convex_hull({{1, 1}}), {}), std::invalid_argument);
  BOOST_CHECK_THROW(feasible_set(convex_hull({{1, 1}}), {{-1, 1}}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
