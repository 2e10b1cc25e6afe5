// Truth in F3 up to intensity (feasible_ray_3d.h): the row-wise interval test against an
// independent route through F3's exact vertices (the ray meets conv(V) iff d lies in the cone of
// V, decided by the exact 2-D hull of V's central projection onto d1 + d2 + d3 = 1), on random
// scenes whose canonical gamuts have vertices on the axes and whose images have zero channels,
// with black included and excluded.
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_ray_3d.h>
#include <gmcc/geometry/feasible_set.h>

#include <boost/test/unit_test.hpp>

#include <random>

using namespace gmcc;

namespace {

// The oracle: d ≠ 0 is a positive multiple of a point of conv(V) iff d ∈ cone(V), and for
// points of the closed octant that is: d's central projection lies in the hull of V's.
bool ray_meets_by_vertices(const ConvexSet3& F, const Point3& d) {
  std::vector<Point2> projected;
  for (const Point3& v : F.vertices) {
    const Rational s = v.x + v.y + v.z;
    if (sgn(s) != 0) projected.push_back({Rational(v.x / s), Rational(v.y / s)});
  }
  if (projected.empty()) return false;
  const Rational s = d.x + d.y + d.z;
  return contains(convex_hull(projected), Point2{Rational(d.x / s), Rational(d.y / s)});
}

Rational small(std::mt19937& rng, int lo, int hi) { return Rational(std::uniform_int_distribution<int>(lo, hi)(rng)); }

}  // namespace

BOOST_AUTO_TEST_SUITE(feasible_ray_3d)

BOOST_AUTO_TEST_CASE(agrees_with_the_cone_of_the_exact_vertices) {
  std::mt19937 rng(4107);
  int inside = 0, outside = 0, zero_component_vertices = 0;
  for (int scene = 0; scene < 300; ++scene) {
    // Canonical colours in {0..6}^3 (some on the axes and faces of the octant), the image the
    // canonical colours under a light, a few of them darkened to a zero channel.
    std::vector<Colour> canonical;
    const int n = std::uniform_int_distribution<int>(3, 9)(rng);
    for (int i = 0; i < n; ++i) canonical.push_back({small(rng, 0, 6), small(rng, 0, 6), small(rng, 0, 6)});
    canonical.push_back({small(rng, 1, 6), small(rng, 1, 6), small(rng, 1, 6)});
    const Colour e{small(rng, 1, 5), small(rng, 1, 5), small(rng, 1, 5)};
    std::vector<Colour> image;
    for (const Colour& c : canonical)
      if (std::uniform_int_distribution<int>(0, 2)(rng)) image.push_back({c.r * e.r, c.g * e.g, c.b * e.b});
    image.push_back({small(rng, 1, 9), small(rng, 1, 9), small(rng, 1, 9)});
    if (scene % 3 == 0) image.push_back({small(rng, 0, 9), 0, small(rng, 1, 9)});
    const CanonicalBlack black = scene % 4 == 3 ? CanonicalBlack::exclude : CanonicalBlack::include;
    const CanonicalConstraints3 prepared(canonical, black);
    ConvexSet3 F;
    try {
      F = feasible_set_3d(prepared, image);
    } catch (const UnboundedFeasibleSet&) {
      BOOST_CHECK_THROW(feasible_set_3d_meets_ray({{&prepared, &image}}, Point3{1, 1, 1}), UnboundedFeasibleSet);
      continue;
    }
    for (const Point3& v : F.vertices)
      zero_component_vertices += (sgn(v.x) == 0 || sgn(v.y) == 0 || sgn(v.z) == 0) && (v != Point3{0, 0, 0});
    // The true map c ⊘ e with c = white, its multiples, and random positive maps.
    std::vector<Point3> maps = {{Rational(1) / e.r, Rational(1) / e.g, Rational(1) / e.b},
                                {Rational(7) / e.r, Rational(7) / e.g, Rational(7) / e.b}};
    for (int k = 0; k < 6; ++k) {
      Point3 d{small(rng, 1, 12), small(rng, 1, 12), small(rng, 1, 12)};
      d.x /= small(rng, 1, 7), d.y /= small(rng, 1, 7), d.z /= small(rng, 1, 7);
      maps.push_back(d);
    }
    for (const Point3& d : maps) {
      const bool rows = feasible_set_3d_meets_ray({{&prepared, &image}}, d);
      const bool oracle = ray_meets_by_vertices(F, d);
      BOOST_TEST(rows == oracle, "scene " << scene);
      (rows ? inside : outside)++;
      // Scale does not matter: the same ray.
      const Point3 scaled{d.x * Rational(1, 1000), d.y * Rational(1, 1000), d.z * Rational(1, 1000)};
      BOOST_TEST(feasible_set_3d_meets_ray({{&prepared, &image}}, scaled) == rows);
    }
  }
  // The scenes reach both answers and F3s with vertices on coordinate planes (the photographs'
  // case that the perspective image cannot answer).
  BOOST_TEST(inside > 100);
  BOOST_TEST(outside > 100);
  BOOST_TEST(zero_component_vertices > 50);
}

BOOST_AUTO_TEST_CASE(several_gamut_types_intersect) {
  // Two types: the ray must meet both F3s at a common t.
  const CanonicalConstraints3 a({Colour{2, 2, 2}}, CanonicalBlack::include);  // the segment 0..(2,2,2)
  const CanonicalConstraints3 b({Colour{1, 1, 1}, Colour{3, 3, 3}}, CanonicalBlack::exclude);
  const std::vector<Colour> image = {Colour{1, 1, 1}};
  // a: t <= 2; b: 1 <= t <= 3. Together [1, 2]: the ray through (1, 1, 1) meets.
  BOOST_TEST(feasible_set_3d_meets_ray({{&a, &image}, {&b, &image}}, Point3{1, 1, 1}));
  const CanonicalConstraints3 c({Colour{3, 3, 3}, Colour{4, 4, 4}}, CanonicalBlack::exclude);  // 3 <= t <= 4
  BOOST_TEST(!feasible_set_3d_meets_ray({{&a, &image}, {&c, &image}}, Point3{1, 1, 1}));
  BOOST_TEST(!feasible_set_3d_meets_ray({{&a, &image}}, Point3{1, 2, 1}));  // off the segment's ray
  BOOST_CHECK_THROW(feasible_set_3d_meets_ray({{&a, &image}}, Point3{0, 1, 1}), std::invalid_argument);
  BOOST_CHECK_THROW(feasible_set_3d_meets_ray({}, Point3{1, 1, 1}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
