// CRULE in 3-D: max-volume (exact and certified quadratic-irrational answers) and the centroid,
// against hand cases, dense searches and the worst-case property on noise-free scenes; max-trace
// and the cone mean of F3's perspective image (issue 16).
#include "../test_support.h"

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/geometry/perspective_image.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_trace.h>
#include <gmcc/selection/max_volume.h>
#include <gmcc/selection/mean_3d.h>
#include <gmcc/selection/perspective_cone_mean.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace gmcc;
using gmcc::test::Rng;
using R = Rational;

namespace {
R product(const Point3& d) { return R(d.x * d.y * d.z); }
Point3 mix(const Point3& a, const Point3& b, const R& t) {
  return {R(a.x + t * (b.x - a.x)), R(a.y + t * (b.y - a.y)), R(a.z + t * (b.z - a.z))};
}
// An exact upper bound on the winner's product: the product of its enclosure's upper ends.
R upper_product(const MapEstimate3& e) {
  return R(rational_from_double(e.enclosure[0][1]) * rational_from_double(e.enclosure[1][1]) *
           rational_from_double(e.enclosure[2][1]));
}
R lower_product(const MapEstimate3& e) {
  return R(rational_from_double(e.enclosure[0][0]) * rational_from_double(e.enclosure[1][0]) *
           rational_from_double(e.enclosure[2][0]));
}
}  // namespace

BOOST_AUTO_TEST_SUITE(crule_3d_selections)

BOOST_AUTO_TEST_CASE(hand_cases) {
  // The cube [1, 2]³: the far corner; its centroid.
  std::vector<Colour> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({R(1 + (i & 1)), R(1 + (i >> 1 & 1)), R(1 + (i >> 2 & 1))});
  const Crule3d c = crule_3d(cube, {{1, 1, 1}}, CanonicalBlack::exclude);
  BOOST_TEST(*c.volume == 1);
  BOOST_TEST((*c.max_volume->estimate.exact == Point3{2, 2, 2}));
  BOOST_TEST((*c.centroid->estimate.exact == Point3{R(3, 2), R(3, 2), R(3, 2)}));
  // Seen from the diagonal, the corners (2, 1, 1), (1, 2, 1), (1, 1, 2) are the farthest
  // (cos = 4/√18, against 5/√27 for (2, 2, 1) and 1 for (1, 1, 1) and (2, 2, 2)).
  BOOST_TEST(*c.centroid->worst_case_deg == diagonal_map_angular_error_deg({1, 1, 1}, {2, 1, 1}));
  // The simplex d >= 0, d1 + d2 + d3 <= 3 (the colours 3e_k and black): the facet point (1, 1, 1).
  const Crule3d s = crule_3d({{3, 0, 0}, {0, 3, 0}, {0, 0, 3}}, {{1, 1, 1}});
  BOOST_TEST(*s.volume == R(9, 2));
  BOOST_TEST((*s.max_volume->estimate.exact == Point3{1, 1, 1}));
  BOOST_TEST((*s.centroid->estimate.exact == Point3{R(3, 4), R(3, 4), R(3, 4)}));
  // The segment 0–(2, 3, 4) (one colour and black): the far end; a point is itself.
  const Crule3d seg = crule_3d({{2, 3, 4}}, {{1, 1, 1}});
  BOOST_TEST((*seg.max_volume->estimate.exact == Point3{2, 3, 4}));
  BOOST_TEST((*seg.centroid->estimate.exact == Point3{1, R(3, 2), 2}));
  // An empty F3 has no selections.
  const Crule3d none = crule_3d(cube, {{1, 1, 1}, {4, 1, 1}}, CanonicalBlack::exclude);
  BOOST_TEST(!none.max_volume.has_value());
  BOOST_TEST(!none.centroid.has_value());
}

BOOST_AUTO_TEST_CASE(edge_maximum_is_a_certified_quadratic_irrational) {
  // On the segment from (1, 4, 1) to (4, 1, 2) the product is a cubic whose maximum lies at an
  // irrational t; F3 is that segment (one image colour, the canonical gamut the segment).
  const ConvexSet3 F = feasible_set_3d({{1, 4, 1}, {4, 1, 2}}, {{1, 1, 1}}, CanonicalBlack::exclude);
  BOOST_REQUIRE(F.kind == ConvexKind3::segment);
  const MapEstimate3 e = max_volume(F);
  BOOST_TEST(e.method == "certified");
  BOOST_TEST(!e.exact.has_value());
  BOOST_REQUIRE(e.edge_root.has_value());
  BOOST_TEST(e.error_bound < 1e-15);
  // f(t) = (1 + 3t)(4 − 3t)(1 + t) = −9t³ + 13t + 4, f'(t) = −27t² + 13: the stored
  // quadratic; the maximiser is t = √(13/27), irrational.
  const auto& r = *e.edge_root;
  BOOST_TEST(r.a == -27);
  BOOST_TEST(r.b == 0);
  BOOST_TEST(r.c == 13);
  BOOST_TEST(r.sign * r.a > 0);  // (−b + sign·√disc)/(2a) > 0 with b = 0 needs sign·a > 0
  const double t = std::sqrt(13.0 / 27.0);
  BOOST_TEST(std::abs(e.map[0] - (1 + 3 * t)) < 1e-14);
  BOOST_TEST(std::abs(e.map[2] - (1 + t)) < 1e-14);
  // Dense search: no point of the segment beats the enclosure's upper product, and the best
  // grid point comes within 1e-5 of its lower product.
  R best = 0;
  for (int k = 0; k <= 4000; ++k) {
    const R value = product(mix(F.vertices[0], F.vertices[1], R(k, 4000)));
    BOOST_TEST(value <= upper_product(e));
    best = std::max(best, value);
  }
  BOOST_TEST(best >= lower_product(e) - R(1, 100000));
}

BOOST_AUTO_TEST_CASE(max_volume_beats_dense_searches_on_random_polytopes) {
  Rng rng(1990);
  int certified = 0, exact = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Colour> canonical;
    for (int i = 0; i < 4 + trial % 6; ++i)
      canonical.push_back({test::random_rational(rng, 1, 30, 3), test::random_rational(rng, 1, 30, 3),
                           test::random_rational(rng, 1, 30, 3)});
    // Image white: F3 is the canonical gamut itself.
    const ConvexSet3 F = feasible_set_3d(canonical, {{1, 1, 1}}, CanonicalBlack::exclude);
    if (F.kind == ConvexKind3::empty) continue;
    const MapEstimate3 e = max_volume(F);
    (e.exact ? exact : certified)++;
    const R hi = e.exact ? product(*e.exact) : upper_product(e);
    if (e.exact) BOOST_TEST(contains(F, *e.exact));
    // Vertices, edge grids and random convex combinations never beat it.
    for (const Point3& v : F.vertices) BOOST_TEST(product(v) <= hi);
    for (const auto& f : F.faces)
      for (std::size_t i = 0; i < f.size(); ++i)
        for (int k = 1; k < 64; ++k)
          BOOST_TEST(product(mix(F.vertices[f[i]], F.vertices[f[(i + 1) % f.size()]], R(k, 64))) <= hi);
    for (int s = 0; s < 50; ++s) {
      const std::size_t a = rng() % F.vertices.size(), b = rng() % F.vertices.size(),
                        c = rng() % F.vertices.size();
      const Point3 p = mix(mix(F.vertices[a], F.vertices[b], R(rng() % 100, 100)), F.vertices[c],
                           R(rng() % 100, 100));
      BOOST_TEST(product(p) <= hi);
    }
  }
  BOOST_TEST(certified > 3);  // both kinds of answer are exercised
  BOOST_TEST(exact > 3);
}

BOOST_AUTO_TEST_CASE(noise_free_scenes_truth_within_the_worst_case) {
  Rng rng(1999);
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<Colour> canonical;
    for (int i = 0; i < 6 + trial % 6; ++i) {
      const Point3 p = test::random_point3(rng, 1, 20, 4);
      canonical.push_back({p.x, p.y, p.z});
    }
    const Point3 d = test::random_point3(rng, 1, 8, 3);
    std::vector<Colour> image;
    for (int i = 0; i < 1 + trial % 5; ++i)
      image.push_back(test::divided(canonical[static_cast<std::size_t>(i * 5 + trial) % canonical.size()], d));
    const CanonicalBlack black = trial % 2 ? CanonicalBlack::include : CanonicalBlack::exclude;
    const Crule3d r = crule_3d(canonical, image, black);
    BOOST_REQUIRE(contains(r.feasible, d));
    for (const auto* s : {&*r.max_volume, &*r.centroid}) {
      const auto& m = s->estimate.map;
      const Point3 mm{rational_from_double(m[0]), rational_from_double(m[1]), rational_from_double(m[2])};
      BOOST_TEST(diagonal_map_angular_error_deg(mm, d) <= *s->worst_case_deg + 1e-12);
    }
    BOOST_TEST(contains(r.feasible, *r.centroid->estimate.exact));
  }
}

BOOST_AUTO_TEST_SUITE_END()

// The selections of issue 16 item 3 on F3: max-trace (a vertex; against brute force over points
// of F3) and the cone mean of F3's perspective image (the image against its definition and
// against the 2-D feasible set, which contains it).
BOOST_AUTO_TEST_SUITE(crule_3d_more_selections)

BOOST_AUTO_TEST_CASE(max_trace_hand_cases_and_ties) {
  std::vector<Colour> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({R(1 + (i & 1)), R(1 + (i >> 1 & 1)), R(1 + (i >> 2 & 1))});
  const Crule3d c = crule_3d(cube, {{1, 1, 1}}, CanonicalBlack::exclude);
  const MapEstimate3 t = max_trace(c.feasible);
  BOOST_TEST((*t.exact == Point3{2, 2, 2}));
  BOOST_TEST(t.rule == "max_trace");
  BOOST_TEST(t.method == "exact");
  // The simplex d >= 0, d1 + d2 + d3 <= 3: the whole facet ties at 3; the lexicographically
  // smallest vertex, (0, 0, 3), is returned.
  const Crule3d s = crule_3d({{3, 0, 0}, {0, 3, 0}, {0, 0, 3}}, {{1, 1, 1}});
  BOOST_TEST((*max_trace(s.feasible).exact == Point3{0, 0, 3}));
  BOOST_CHECK_THROW(max_trace(ConvexSet3{}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(max_trace_beats_every_point_of_f3) {
  Rng rng(16);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Colour> canonical, image;
    for (int i = 0; i < 8; ++i)
      canonical.push_back({test::random_rational(rng, 1, 20, 4), test::random_rational(rng, 1, 20, 4),
                           test::random_rational(rng, 1, 20, 4)});
    for (int i = 0; i < 1 + trial % 4; ++i)
      image.push_back({test::random_rational(rng, 1, 20, 4), test::random_rational(rng, 1, 20, 4),
                       test::random_rational(rng, 1, 20, 4)});
    const Crule3d r = crule_3d(canonical, image, trial % 2 ? CanonicalBlack::include : CanonicalBlack::exclude);
    if (r.feasible.kind == ConvexKind3::empty) continue;
    const MapEstimate3 t = max_trace(r.feasible);
    const Point3& m = *t.exact;
    BOOST_TEST(contains(r.feasible, m));
    const R best = m.x + m.y + m.z;
    // Brute force: every vertex, and random convex combinations of them (points of F3).
    for (const Point3& v : r.feasible.vertices) {
      BOOST_TEST(R(v.x + v.y + v.z) <= best);
      if (R(v.x + v.y + v.z) == best) BOOST_TEST(!(v < m));  // ties: the smallest is returned
    }
    for (int k = 0; k < 20; ++k) {
      const Point3& a = r.feasible.vertices[rng() % r.feasible.vertices.size()];
      const Point3& b = r.feasible.vertices[rng() % r.feasible.vertices.size()];
      const Point3 p = mix(a, b, R(static_cast<long>(rng() % 17), 16));
      BOOST_TEST(R(p.x + p.y + p.z) <= best);
    }
  }
}

BOOST_AUTO_TEST_CASE(perspective_image_by_definition) {
  // The cube [1, 2]³ seen in perspective: the hull of (a/c, b/c) over its corners.
  std::vector<Colour> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({R(1 + (i & 1)), R(1 + (i >> 1 & 1)), R(1 + (i >> 2 & 1))});
  const ConvexSet3 F = crule_3d(cube, {{1, 1, 1}}, CanonicalBlack::exclude).feasible;
  const std::optional<ConvexSet2> P = perspective_image(F);
  BOOST_REQUIRE(P.has_value());
  BOOST_TEST((P->kind == ConvexKind::polygon));
  // The six extreme points: (1/2, 1/2), (1, 1/2), (2, 1), (2, 2), (1, 2), (1/2, 1).
  BOOST_TEST(P->vertices.size() == 6u);
  BOOST_TEST(contains(*P, Point2{R(1, 2), R(1, 2)}));
  BOOST_TEST(contains(*P, Point2{2, 2}));
  BOOST_TEST(!contains(*P, Point2{R(2), R(1, 2)}));
  // With black the origin is a vertex with d3 = 0 and is left out; a non-zero one makes the
  // image unbounded: the simplex {d >= 0, d1 + d2 + d3 <= 3} has (3, 0, 0).
  BOOST_TEST(!perspective_image(crule_3d({{3, 0, 0}, {0, 3, 0}, {0, 0, 3}}, {{1, 1, 1}}).feasible).has_value());
  // {0} alone: no point with d3 > 0, the image is empty.
  const ConvexSet3 origin = canonical_convex_set_3(ConvexKind3::point, {Point3{0, 0, 0}}, {});
  BOOST_TEST((perspective_image(origin)->kind == ConvexKind::empty));
  BOOST_TEST(!perspective_cone_mean(origin).has_value());
}

// On scenes drawn from a canonical gamut with black: every point of F3 with d3 > 0 projects into
// the image, every image vertex is a vertex of F3 projected, and the image is the 2-D feasible
// set F (⊆: d ⊙ p ∈ G_c3 puts d's perspective map in F; ⊇: a small multiple of (m, 1) fits), so
// the cone mean is the paper's 3-D mean of F.
BOOST_AUTO_TEST_CASE(perspective_image_inside_the_2d_feasible_set) {
  Rng rng(1999);
  int polygons = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Colour> canonical;
    for (int i = 0; i < 10; ++i)
      canonical.push_back({test::random_rational(rng, 1, 20, 4), test::random_rational(rng, 1, 20, 4),
                           test::random_rational(rng, 1, 20, 4)});
    const Point3 d{test::random_rational(rng, 1, 8, 3), test::random_rational(rng, 1, 8, 3),
                   test::random_rational(rng, 1, 8, 3)};
    std::vector<Colour> image;
    for (int i = 0; i < 1 + trial % 4; ++i) {
      const Colour& p = canonical[static_cast<std::size_t>(i * 3 + trial) % canonical.size()];
      image.push_back({R(p.r / d.x), R(p.g / d.y), R(p.b / d.z)});
    }
    const ConvexSet3 F3 = crule_3d(canonical, image).feasible;
    const std::optional<ConvexSet2> P = perspective_image(F3);
    BOOST_REQUIRE(P.has_value());
    polygons += P->kind == ConvexKind::polygon;
    for (int k = 0; k < 30; ++k) {
      const Point3& a = F3.vertices[rng() % F3.vertices.size()];
      const Point3& b = F3.vertices[rng() % F3.vertices.size()];
      const Point3 q = mix(a, b, R(static_cast<long>(1 + rng() % 15), 16));
      if (sgn(q.z) > 0) BOOST_TEST(contains(*P, Point2{R(q.x / q.z), R(q.y / q.z)}));
    }
    for (const Point2& v : P->vertices) {
      bool found = false;
      for (const Point3& w : F3.vertices) found = found || (sgn(w.z) > 0 && R(w.x / w.z) == v.x && R(w.y / w.z) == v.y);
      BOOST_TEST(found);
    }
    const ConvexSet2 F2 = feasible_set(canonical_gamut(perspective_chromaticities(canonical, NonPositiveBluePolicy::drop).points),
                                       perspective_chromaticities(image, NonPositiveBluePolicy::drop).points);
    for (const Point2& v : P->vertices) BOOST_TEST(contains(F2, v));
    // With black in G_c3 the image is all of F (docs/math.md §1c): the same exact set.
    BOOST_TEST((*P == F2));
    BOOST_TEST(contains(*P, Point2{R(d.x / d.z), R(d.y / d.z)}));  // the truth's perspective
    const std::optional<MapEstimate> mean = perspective_cone_mean(F3);
    BOOST_REQUIRE(mean.has_value());
    BOOST_TEST(mean->rule == "cone_mean");
    BOOST_TEST(mean->valid);
    const MapEstimate direct = mean_3d(*P);
    BOOST_TEST(mean->map[0] == direct.map[0]);
    BOOST_TEST(mean->map[1] == direct.map[1]);
    if (P->kind == ConvexKind::polygon) BOOST_TEST(contains(*P, measured_map(*mean)));
  }
  BOOST_TEST(polygons > 5);
}

BOOST_AUTO_TEST_SUITE_END()
