// F3's clip with its rows generated lazily (internal/lazy_rows.h, docs/derivations.md §4.6 "Rows
// generated lazily") against the whole clip (clip_polytope): the same outcome and the same exact
// set on seeded scenes — many image points on their hull (points near a sphere), points on common
// planes (small integer grids, where vertices lie on many planes), coordinates scaled by 2^±200
// (and by 2^±300, beyond the filter's range: the whole clip decides), several groups at once, and
// the empty, flat and one-point outcomes.
#include "../test_support.h"

#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/geometry/point3_arithmetic.h>

#include "internal/crule_exact.h"
#include "internal/lazy_rows.h"
#include "internal/polytope_clip.h"

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace gmcc;
using gmcc::test::Rng;
using R = Rational;

namespace {

// A number in [0, n).
long below(Rng& rng, long n) { return static_cast<long>(rng() % static_cast<unsigned long>(n)); }

// A canonical gamut's facets as integer half-spaces (with black when asked), from n random
// colours with channels in (0, top]; empty when the colours are flat.
std::vector<internal::IntegerPlane3> gamut_planes(Rng& rng, int n, int top, bool black) {
  std::vector<Point3> g;
  if (black) g.push_back({0, 0, 0});
  for (int i = 0; i < n; ++i) g.push_back({R(1 + below(rng, top)), R(1 + below(rng, top)), R(1 + below(rng, top))});
  g = internal::sorted_unique(std::move(g));
  std::vector<internal::IntegerPlane3> planes;
  if (internal::affine_dimension(g) < 3) return planes;
  for (const internal::HalfSpace3& h : internal::hull_half_spaces_3(g)) {
    const mpz_class l = lcm_of_denominators_of(h.a.x, h.a.y, h.a.z, h.b);
    planes.push_back({{times_lcm(h.a.x, l), times_lcm(h.a.y, l), times_lcm(h.a.z, l)}, times_lcm(h.b, l)});
  }
  return planes;
}

// n image points: near a sphere about (c, c, c) of radius c/2 (most on their hull: as edge
// colours at large σ), or on a small integer grid (many on common planes); each times 2^scale.
std::vector<Point3> image_points(Rng& rng, int n, bool grid, int scale) {
  std::vector<Point3> p;
  const double c = 1000;
  for (int i = 0; i < n; ++i) {
    Point3 q;
    if (grid) {
      q = {R(1 + below(rng, 4)), R(1 + below(rng, 4)), R(1 + below(rng, 4))};
    } else {
      double v[3], norm = 0;
      for (double& x : v) x = double(below(rng, 2001)) - 1000, norm += x * x;
      norm = std::sqrt(norm) + 1;
      q = {R(std::round(c + c / 2 * v[0] / norm)), R(std::round(c + c / 2 * v[1] / norm)),
           R(std::round(c + c / 2 * v[2] / norm))};
    }
    for (int k = 0; k < 3; ++k) coord(q, k) *= scale >= 0 ? R(mpz_class(1) << scale) : R(mpz_class(1), mpz_class(1) << -scale);
    p.push_back(q);
  }
  return internal::sorted_unique(std::move(p));
}

// The same outcome, and the same exact set unless flat.
void same(const internal::ClippedPolytope& x, const internal::ClippedPolytope& y, int trial) {
  BOOST_TEST((x.outcome == y.outcome), "trial " << trial);
  if (x.outcome == y.outcome && x.outcome == internal::ClippedPolytope::Outcome::polytope)
    BOOST_TEST((x.set.exact() == y.set.exact()), "trial " << trial);
}

}  // namespace

BOOST_AUTO_TEST_CASE(lazy_rows_equal_the_whole_clip) {
  Rng rng(4646);
  int polytopes = 0, others = 0;
  const int scales[] = {0, 0, 100, -100, 200, -200, 300};
  for (int trial = 0; trial < 70; ++trial) {
    const bool grid = trial % 5 == 4;
    const std::vector<internal::IntegerPlane3> planes = gamut_planes(rng, 6 + trial % 30, grid ? 3 : 1000, trial % 2 == 0);
    if (planes.empty()) continue;
    const internal::ClipFacets facets = internal::clip_facets(planes);
    const int scale = scales[trial % 7];
    const std::vector<Point3> points = image_points(rng, 20 + 40 * (trial % 8), grid, scale);
    // The box X/P: the canonical gamut's scale over the points', as feasible_set_3d makes it.
    const R side = scale >= 0 ? R(mpz_class(grid ? 4 : 2), mpz_class(1) << scale) : R(mpz_class(grid ? 4 : 2) << -scale);
    const Point3 box{side, side, side};
    internal::ClipCounts counts;
    const internal::ClippedPolytope whole = internal::clip_polytope(box, facets, points);
    const internal::ClippedPolytope lazy = internal::clip_polytope_lazy_rows(box, {{&facets, &points}}, &counts);
    same(lazy, whole, trial);
    (whole.outcome == internal::ClippedPolytope::Outcome::polytope && whole.set.kind() == ConvexKind3::polytope ? polytopes : others)++;
  }
  BOOST_TEST(polytopes > 30);
  BOOST_TEST(others > 0);
}

BOOST_AUTO_TEST_CASE(lazy_rows_with_several_groups) {
  // Two gamut types on one map (the n-jet methods: pixel and edge constraints), as one clip.
  Rng rng(4647);
  for (int trial = 0; trial < 20; ++trial) {
    const std::vector<internal::IntegerPlane3> a = gamut_planes(rng, 10 + trial, 1000, true),
                                               b = gamut_planes(rng, 8 + trial, 1000, trial % 2 == 0);
    if (a.empty() || b.empty()) continue;
    const internal::ClipFacets fa = internal::clip_facets(a), fb = internal::clip_facets(b);
    const std::vector<Point3> pa = image_points(rng, 100, false, 0), pb = image_points(rng, 30 + 10 * trial, trial % 3 == 0, 0);
    const Point3 box{R(2), R(2), R(2)};
    const std::vector<internal::ClipGroup> groups{{&fa, &pa}, {&fb, &pb}};
    same(internal::clip_polytope_lazy_rows(box, groups), internal::clip_polytope(box, groups), trial);
  }
}

BOOST_AUTO_TEST_CASE(lazy_rows_empty_flat_and_point) {
  // Explicit half-spaces (points = {(1, 1, 1)}): a tetrahedron, a flat set, the empty set, and
  // one point; and no rows at all (the box).
  using P = internal::IntegerPlane3;
  const auto plane = [](long a, long b, long c, long d) { return P{{mpz_class(a), mpz_class(b), mpz_class(c)}, mpz_class(d)}; };
  const std::vector<std::vector<P>> cases{
      {plane(1, 1, 1, 1)},                           // a tetrahedron
      {plane(1, 1, 1, 1), plane(-1, -1, -1, -1)},    // the triangle x + y + z = 1: flat
      {plane(1, 1, 1, 1), plane(-1, -1, -1, -2)},    // empty
      {plane(1, 1, 1, 0)},                           // the origin alone
      {plane(1, 0, 0, 0), plane(0, 1, 0, 0)},        // a segment of the z axis: flat
  };
  const std::vector<Point3> one{{1, 1, 1}};
  int trial = 0;
  for (const std::vector<P>& planes : cases) {
    const internal::ClipFacets f = internal::clip_facets(planes);
    same(internal::clip_polytope_lazy_rows({1, 1, 1}, {{&f, &one}}), internal::clip_polytope({1, 1, 1}, f, one), trial++);
  }
  const internal::ClippedPolytope box = internal::clip_polytope_lazy_rows({1, 2, 3}, {});
  BOOST_TEST((box.outcome == internal::ClippedPolytope::Outcome::polytope));
  BOOST_TEST(box.set.size() == 8u);
}
