// CRULE in 3-D: max-volume (exact and certified quadratic-irrational answers) and the centroid,
// against hand cases, dense searches and the worst-case property on noise-free scenes.
#include "../test_support.h"

#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_volume.h>

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
  BOOST_TEST(c.volume == 1);
  BOOST_TEST((*c.max_volume->estimate.exact == Point3{2, 2, 2}));
  BOOST_TEST((*c.centroid->estimate.exact == Point3{R(3, 2), R(3, 2), R(3, 2)}));
  // Seen from the diagonal, the corners (2, 1, 1), (1, 2, 1), (1, 1, 2) are the farthest
  // (cos = 4/√18, against 5/√27 for (2, 2, 1) and 1 for (1, 1, 1) and (2, 2, 2)).
  BOOST_TEST(*c.centroid->worst_case_deg == diagonal_map_angular_error_deg({1, 1, 1}, {2, 1, 1}));
  // The simplex d >= 0, d1 + d2 + d3 <= 3 (the colours 3e_k and black): the facet point (1, 1, 1).
  const Crule3d s = crule_3d({{3, 0, 0}, {0, 3, 0}, {0, 0, 3}}, {{1, 1, 1}});
  BOOST_TEST(s.volume == R(9, 2));
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
