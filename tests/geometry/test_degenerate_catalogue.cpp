// The degenerate-gamut catalogue of docs/degenerate.md: one test per entry, each stating what
// gmcc returns (exactly) and what a plain double-precision pipeline (tests/baseline) returns on
// the same input. The double results asserted here are what IEEE-754 binary64 with
// round-to-nearest gives (x86-64 SSE2, no FMA contraction: the default x86-64 target has no FMA;
// GCC would contract a·b + c in C++ on a target that has it, whatever the -std).
#include "../baseline/double_pipeline.h"
#include "../test_support.h"

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_set.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace gmcc;
namespace base = gmcc::baseline;
using R = Rational;

namespace {
std::vector<base::P> to_double(const std::vector<Point2>& v) {
  std::vector<base::P> out;
  for (const Point2& p : v) {
    const auto d = to_double_nearest(p);
    out.push_back({d[0], d[1]});
  }
  return out;
}
// The set the double pipeline reports, taken exactly: the hull of its vertices.
ConvexSet2 exact_of(const std::vector<base::P>& f) {
  std::vector<Point2> v;
  for (const base::P& p : f) v.push_back({rational_from_double(p.x), rational_from_double(p.y)});
  return convex_hull(v);
}
struct Both {
  ConvexSet2 exact;
  std::vector<base::P> dbl;
};
Both both(const std::vector<Point2>& canonical, const std::vector<Point2>& image) {
  return {feasible_set(convex_hull(canonical), image),
          base::feasible_set(to_double(canonical), to_double(image))};
}
R decimal(const char* s) { return parse_rational(s); }
}  // namespace

BOOST_AUTO_TEST_SUITE(degenerate_catalogue)

// 1. One canonical colour, one image colour: exactly one map.
BOOST_AUTO_TEST_CASE(single_colour) {
  const Both b = both({{2, 3}}, {{4, R(1, 2)}});
  BOOST_TEST(b.exact == convex_hull({{R(1, 2), 6}}));
  // A one-point hull has no edges, so nothing is clipped: the whole starting box comes back.
  BOOST_TEST(base::kind(b.dbl) == "polygon");
  BOOST_TEST(exact_of(b.dbl) == convex_hull({{0, 0}, {R(1, 2), 0}, {R(1, 2), 6}, {0, 6}}));
}

// 2. A canonical gamut that is one point cannot take two different image colours.
BOOST_AUTO_TEST_CASE(canonical_gamut_a_point) {
  const Both b = both({{2, 2}}, {{1, 1}, {2, 1}});
  BOOST_TEST(b.exact.kind == ConvexKind::empty);
  BOOST_TEST(base::kind(b.dbl) == "polygon");  // the unclipped box again
}

// 3. Duplicate colours change nothing: the identical exact set.
BOOST_AUTO_TEST_CASE(duplicates) {
  const std::vector<Point2> G{{1, 1}, {3, 1}, {3, 2}, {1, 3}};
  const std::vector<Point2> I{{1, 1}, {R(3, 2), R(5, 4)}};
  const ConvexSet2 F = feasible_set(convex_hull(G), I);
  BOOST_TEST(feasible_set(convex_hull({G[0], G[1], G[1], G[2], G[3], G[0]}), {I[0], I[1], I[0]}) == F);
  BOOST_TEST(F == convex_hull({{1, 1}, {2, 1}, {2, R(8, 5)}, {1, R(11, 5)}}));
  // Doubles: the kind survives, but the vertex (1, 1) comes out as (1, 1 − 2^-53), an
  // infeasible map.
  const auto f = base::feasible_set(to_double(G), to_double({I[0], I[1], I[0]}));
  BOOST_TEST(base::kind(f) == "polygon");
  BOOST_TEST(!(exact_of(f) == F));
  BOOST_TEST(!contains(F, {1, rational_from_double(std::nextafter(1.0, 0.0))}));
  BOOST_TEST(contains(exact_of(f), {1, rational_from_double(std::nextafter(1.0, 0.0))}));
}

// 4. Collinear canonical colours: the canonical gamut is a segment, and so is F.
BOOST_AUTO_TEST_CASE(collinear_canonical_colours_and_a_segment_gamut) {
  const Both b = both({{1, 1}, {2, R(3, 2)}, {3, 2}}, {{1, 1}});
  BOOST_TEST(b.exact == convex_hull({{1, 1}, {3, 2}}));
  // A two-vertex hull gives two opposite edge half-planes and no end caps: the whole line
  // through the segment, cut only by the starting box — a segment too long.
  BOOST_TEST(base::kind(b.dbl) == "segment");
  BOOST_TEST(exact_of(b.dbl) == convex_hull({{0, R(1, 2)}, {3, 2}}));
  BOOST_TEST(std::isnan(base::mean_2d(b.dbl).x));  // the shoelace centroid of a segment
}

// 5. The paper's toy example (Finlayson & Hordley 1999 Fig. 1): canonical (3,2,1), (1,2,3),
//    image (1,1,1); F is the segment (1/3, 2/3)–(3, 2).
BOOST_AUTO_TEST_CASE(paper_toy_example) {
  const auto c = perspective_chromaticities({{3, 2, 1}, {1, 2, 3}}, NonPositiveBluePolicy::reject);
  const Both b = both(c.points, {{1, 1}});
  BOOST_TEST(b.exact == convex_hull({{R(1, 3), R(2, 3)}, {3, 2}}));
  // 1/3 and 2/3 round differently; the line's two half-planes no longer agree and only (3, 2)
  // survives: a point instead of a segment, so every rule returns the max-area answer.
  BOOST_TEST(base::kind(b.dbl) == "point");
}

// 6. Collinear image colours: only the two ends constrain F.
BOOST_AUTO_TEST_CASE(collinear_image_colours) {
  const ConvexSet2 G = convex_hull({{1, 1}, {4, 1}, {4, 3}, {2, 4}, {1, 3}});
  const std::vector<Point2> line{{1, 1}, {R(3, 2), R(5, 4)}, {2, R(3, 2)}, {R(5, 4), R(9, 8)}};
  BOOST_TEST(feasible_set(G, line) == feasible_set(G, {{1, 1}, {2, R(3, 2)}}));
  BOOST_TEST(feasible_set(G, line).kind == ConvexKind::polygon);
}

// 7. An image colour on the canonical boundary: the true map lies on the boundary of F.
BOOST_AUTO_TEST_CASE(image_colour_on_the_canonical_boundary) {
  // Canonical chromaticities in tenths; the image colour is the corner (0.1, 0.1) ⊘ (7, 3), so
  // the true map (7, 3) is the lower-left vertex of F.
  const std::vector<Point2> G{{decimal("0.1"), decimal("0.1")}, {decimal("0.3"), decimal("0.1")},
                              {decimal("0.3"), decimal("0.7")}, {decimal("0.1"), decimal("0.7")}};
  const Both b = both(G, {{R(G[0].x / 7), R(G[0].y / 3)}});
  BOOST_TEST(contains(b.exact, {7, 3}));
  BOOST_TEST(b.exact.kind == ConvexKind::polygon);
  BOOST_TEST((b.exact.vertices.front() == Point2{7, 3}));
  BOOST_TEST(base::kind(b.dbl) == "polygon");
  BOOST_TEST(!contains(exact_of(b.dbl), {7, 3}));  // rounding moved an edge past the truth
}

// 8. The true map on the boundary with nothing else feasible: F is a point.
BOOST_AUTO_TEST_CASE(point_feasible_set_from_decimal_data) {
  const std::vector<Point2> G{{decimal("0.1"), decimal("0.1")}, {decimal("0.3"), decimal("0.1")},
                              {decimal("0.3"), decimal("0.7")}, {decimal("0.1"), decimal("0.7")}};
  std::vector<Point2> I;
  for (const Point2& p : G) I.push_back({R(p.x / 3), R(p.y / 7)});
  const Both b = both(G, I);
  BOOST_TEST(b.exact == convex_hull({{3, 7}}));
  BOOST_TEST(base::kind(b.dbl) == "empty");  // the one feasible map is lost
}

// 9. A segment F (image as wide as the gamut in one direction).
BOOST_AUTO_TEST_CASE(segment_feasible_set) {
  const Both b = both({{1, 1}, {2, 1}, {2, 2}, {1, 2}}, {{1, 1}, {2, R(3, 2)}});
  BOOST_TEST(b.exact == convex_hull({{1, 1}, {1, R(4, 3)}}));
  BOOST_TEST(base::kind(b.dbl) == "segment");
  BOOST_TEST(std::isnan(base::mean_2d(b.dbl).x));  // the 2-D mean of a segment: 0/0
}

// 10. Tiny feasible sets: width 1e-9 keeps its exact area w²; in doubles the shoelace centroid
//     breaks down, and at width 1e-17 the gamut itself collapses to a point.
BOOST_AUTO_TEST_CASE(tiny_feasible_sets) {
  const R w(1, 1000000000);
  const Both b = both({{1, 1}, {1 + w, 1}, {1 + w, 1 + w}, {1, 1 + w}}, {{2, R(1, 2)}});
  BOOST_TEST(b.exact.kind == ConvexKind::polygon);
  BOOST_TEST(area(b.exact) == R(w * w));
  BOOST_TEST(base::kind(b.dbl) == "polygon");
  BOOST_TEST(!std::isfinite(base::mean_2d(b.dbl).x));
  const R v = parse_rational("1e-17");
  const Both c = both({{1, 1}, {1 + v, 1}, {1 + v, 1 + v}, {1, 1 + v}}, {{2, R(1, 2)}});
  BOOST_TEST(c.exact.kind == ConvexKind::polygon);
  BOOST_TEST(area(c.exact) == R(v * v));
  // 1 + 1e-17 rounds to 1: a one-point gamut, no edges, the unclipped box of area 1.
  BOOST_TEST(area(exact_of(c.dbl)) == 1);
}

// 11. Colours with a zero channel: r = 0 constrains one map component only; b = 0 has no
//     chromaticity (gmcc drops and counts it; doubles divide by zero).
BOOST_AUTO_TEST_CASE(colours_with_a_zero_channel) {
  const Both r0 = both({{0, 1}, {2, 1}, {2, 3}, {0, 3}}, {{0, 1}, {1, 1}});
  BOOST_TEST(r0.exact == convex_hull({{0, 1}, {2, 1}, {2, 3}, {0, 3}}));
  BOOST_TEST(exact_of(r0.dbl) == r0.exact);  // the doubles happen to be exact here

  const std::vector<Colour> square{{1, 1, 1}, {2, 1, 1}, {2, 2, 1}, {1, 2, 1}};
  const std::vector<Colour> image{{3, 3, 2}, {1, 1, 0}};
  const auto iq = perspective_chromaticities(image, NonPositiveBluePolicy::drop);
  BOOST_TEST(iq.dropped == 1u);
  const ConvexSet2 F = feasible_set(
      convex_hull(perspective_chromaticities(square, NonPositiveBluePolicy::reject).points), iq.points);
  BOOST_TEST(F == convex_hull({{R(2, 3), R(2, 3)}, {R(4, 3), R(2, 3)}, {R(4, 3), R(4, 3)},
                               {R(2, 3), R(4, 3)}}));
  auto rgb = [](const std::vector<Colour>& cs) {
    std::vector<std::array<double, 3>> out;
    for (const Colour& c : cs)
      out.push_back({to_double_nearest(c.r), to_double_nearest(c.g), to_double_nearest(c.b)});
    return out;
  };
  // (1, 1, 0) → (inf, inf): the box becomes [0, 0]², and NaN comparisons then drop everything.
  const auto f = base::feasible_set(base::chromaticities(rgb(square)), base::chromaticities(rgb(image)));
  BOOST_TEST(base::kind(f) == "empty");
}

// 12. Noise-free synthetic scenes: canonical = random rational chromaticities, image = a random
//     subset divided by a random rational map d. d is always feasible, and lies on ∂F (each image
//     colour is mapped onto a canonical colour). gmcc's F contains d in every scene; the double
//     pipeline's F (taken exactly as the hull of its vertices) misses it in most.
BOOST_AUTO_TEST_CASE(random_noise_free_scenes_exact_never_misses_the_true_map) {
  test::Rng rng(1990);
  const int scenes = 10000;
  int exact_misses = 0, exact_points = 0, dbl_misses = 0, dbl_empty = 0, dbl_wrong_kind = 0,
      dbl_max_area_infeasible = 0;
  for (int s = 0; s < scenes; ++s) {
    const int nc = 3 + s % 10;
    std::vector<Point2> canonical;
    for (int i = 0; i < nc; ++i)
      canonical.push_back({test::random_rational(rng, 10, 300, 100), test::random_rational(rng, 10, 300, 100)});
    const Point2 d{test::random_rational(rng, 20, 500, 100), test::random_rational(rng, 20, 500, 100)};
    std::vector<Point2> image;
    for (int i = 0; i < 1 + s % 8; ++i) {
      const Point2& p = canonical[std::uniform_int_distribution<int>(0, nc - 1)(rng)];
      image.push_back({R(p.x / d.x), R(p.y / d.y)});
    }
    const Both b = both(canonical, image);
    exact_misses += !contains(b.exact, d);
    exact_points += b.exact.kind == ConvexKind::point;
    if (b.dbl.empty()) {
      ++dbl_empty, ++dbl_misses, ++dbl_wrong_kind;
      continue;
    }
    dbl_misses += !contains(exact_of(b.dbl), d);
    dbl_wrong_kind += base::kind(b.dbl) != to_string(b.exact.kind);
    const base::P m = base::max_area(b.dbl);
    dbl_max_area_infeasible +=
        !contains(b.exact, {rational_from_double(m.x), rational_from_double(m.y)});
  }
  BOOST_TEST(exact_misses == 0);
  // The figures quoted in docs/degenerate.md (seed 1990, libstdc++'s distributions).
  BOOST_TEST(exact_points == 5232);
  BOOST_TEST(dbl_misses == 8360);
  BOOST_TEST(dbl_empty == 3601);
  BOOST_TEST(dbl_wrong_kind == 4387);
  BOOST_TEST(dbl_max_area_infeasible == 4730);
}

BOOST_AUTO_TEST_SUITE_END()
