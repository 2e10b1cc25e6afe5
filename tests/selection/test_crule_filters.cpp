// CRULE's filtered selections (issue 16): max_volume's double-enclosure filter and the filter of
// worst_case_map_deg_3d give the answers of their exact routes, map for map and bit for bit; the
// certified centroid encloses the exact one; contains()'s filter answers as the exact test; on
// hundreds of seeded F3s (Munsell-like random gamuts with shading and highlights, with and without
// black) and on polytopes built so that a facet's stationary point lies exactly on an edge or
// 2^-70 inside or outside it, edges' roots fall exactly at their ends (the cube with black), and
// vertices tie in angle (the exact stage decides there); containment also of points 2^-80 beyond
// each vertex, which only the exact test can place. The oracles of the worst case and of containment are written here: every non-zero
// vertex's cos² compared in ℚ, every facet's plane evaluated in ℚ.
#include "../test_support.h"
#include "crule_oracles.h"

#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/centroid_3.h>
#include <gmcc/selection/max_volume.h>

#include "internal/centroid_3_route.h"
#include "internal/max_volume_route.h"
#include "internal/rounded_component.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace gmcc;
using gmcc::test::Rng;
using gmcc::test::same_estimate;
using gmcc::test::worst_case_oracle;
using R = Rational;

namespace {

// The oracle: p on the inner side of every facet's plane (outward normal from its first three
// vertices), in ℚ.
bool contains_oracle(const ConvexSet3& F, const Point3& p) {
  const auto& v = F.vertices;
  for (const auto& f : F.faces) {
    const Point3 a{R(v[f[1]].x - v[f[0]].x), R(v[f[1]].y - v[f[0]].y), R(v[f[1]].z - v[f[0]].z)};
    const Point3 b{R(v[f[2]].x - v[f[0]].x), R(v[f[2]].y - v[f[0]].y), R(v[f[2]].z - v[f[0]].z)};
    const Point3 n{R(a.y * b.z - a.z * b.y), R(a.z * b.x - a.x * b.z), R(a.x * b.y - a.y * b.x)};
    if (sgn(dot(n, {R(p.x - v[f[0]].x), R(p.y - v[f[0]].y), R(p.z - v[f[0]].z)})) > 0) return false;
  }
  return true;
}

// The certified centroid holds the exact one within its enclosure and its bound.
void centroid_enclosed(const ConvexSet3& F) {
  const Point3 exact = centroid(F);
  const MapEstimate3 c = centroid_3(F, Crule3dRoute::certified);
  BOOST_TEST(c.rule == "centroid");
  if (c.method == "exact") {
    BOOST_TEST((*c.exact == exact));
    return;
  }
  BOOST_TEST(c.method == "certified");
  const R* e[3] = {&exact.x, &exact.y, &exact.z};
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(rational_from_double(c.enclosure[k][0]) <= *e[k]);
    BOOST_TEST(*e[k] <= rational_from_double(c.enclosure[k][1]));
    BOOST_TEST(abs(R(*e[k] - rational_from_double(c.map[k]))) <= rational_from_double(c.error_bound));
  }
  BOOST_TEST(c.error_bound <= internal::certified_centroid_relative_bound *
                                 std::max({std::fabs(c.map[0]), std::fabs(c.map[1]), std::fabs(c.map[2])}));
}

std::size_t size(const internal::MaxVolumeCandidates& c) {
  return c.vertices.size() + c.faces.size() + c.edges.size();
}

// How many candidates the filter left to the exact stage, of how many.
struct Kept {
  std::size_t contenders = 0, candidates = 0;
};

// Both selections against their exact routes on F, and the worst case from several maps.
void agree(const ConvexSet3& F, Rng& rng, Kept& kept) {
  if (F.kind == ConvexKind3::empty) return;
  const MapEstimate3 staged = max_volume(F);
  const internal::MaxVolumeCandidates all = internal::all_max_volume_candidates(F);
  same_estimate(staged, internal::max_volume_over(F, all));
  if (const auto c = internal::max_volume_contenders(F)) {  // how much the filter left
    kept.contenders += size(*c);
    kept.candidates += size(all);
  }
  centroid_enclosed(F);
  // Containment of a polytope: the vertices (on the boundary), the centroid, points 10^-9 beyond
  // a vertex (the filter decides) and 2^-80 beyond it (only the exact test can).
  const R far(1, 1000000000), near(1, mpz_class(1) << 80);
  for (const Point3& v : F.vertices) {
    BOOST_TEST(contains(F, v));
    if (F.kind != ConvexKind3::polytope) continue;
    for (const R& nudge : {far, near})
      for (int sign : {1, -1}) {
        const Point3 p{R(v.x * (1 + sign * nudge)), R(v.y * (1 + sign * nudge)), R(v.z * (1 - sign * nudge))};
        BOOST_TEST(contains(F, p) == contains_oracle(F, p));
      }
  }
  if (F.kind == ConvexKind3::polytope) BOOST_TEST(contains(F, centroid(F)));
  bool nonzero = false;
  for (const Point3& v : F.vertices) nonzero = nonzero || !is_zero(v);
  if (!nonzero) return;
  std::vector<Point3> maps{measured_map(staged), centroid(F), F.vertices.back(), test::random_point3(rng, 1, 9, 7)};
  for (const Point3& m : maps)
    if (!is_zero(m)) BOOST_TEST(worst_case_map_deg_3d(F, m) == worst_case_oracle(F, m));
}

Colour random_colour(Rng& rng, long hi, long den) {
  return {test::random_rational(rng, 1, hi, den), test::random_rational(rng, 1, hi, den),
          test::random_rational(rng, 1, hi, den)};
}

// The convex hull of `colours` as F3 (the image white: F3 is the canonical gamut itself).
ConvexSet3 gamut(const std::vector<Colour>& colours, CanonicalBlack black = CanonicalBlack::exclude) {
  return feasible_set_3d(colours, {{1, 1, 1}}, black);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(crule_filters)

BOOST_AUTO_TEST_CASE(random_scenes_agree_with_the_exact_routes) {
  Rng rng(16016);
  const internal::StageCounts& counts = internal::max_volume_stage_counts();
  const std::uint64_t filtered0 = counts[0], contenders0 = counts[1];
  const std::uint64_t certified0 = internal::certified_centroid_stage_counts()[0];
  int polytopes = 0;
  Kept kept;
  for (int trial = 0; trial < 150; ++trial) {
    std::vector<Colour> canonical;
    for (int i = 0; i < 8 + trial % 20; ++i) canonical.push_back(random_colour(rng, 40, 1 + trial % 9));
    const CanonicalBlack black = trial % 2 ? CanonicalBlack::include : CanonicalBlack::exclude;
    const CanonicalConstraints3 G(canonical, black);
    const Point3 d = test::random_point3(rng, 1, 5, 4);
    std::vector<Colour> image;
    for (int i = 0; i < 1 + trial % 11; ++i) {
      Colour c = test::divided(canonical[static_cast<std::size_t>(rng() % canonical.size())], d);
      const R shade = trial % 3 == 0 ? test::random_rational(rng, 3, 10, 1) / 10 : R(1);
      const R highlight = trial % 5 == 0 ? test::random_rational(rng, 0, 3, 7) : R(0);
      for (R* x : {&c.r, &c.g, &c.b}) *x = *x * shade + highlight;
      image.push_back(c);
    }
    const ConvexSet3 F = feasible_set_3d(G, image);
    polytopes += F.kind == ConvexKind3::polytope;
    agree(F, rng, kept);
  }
  BOOST_TEST(polytopes > 60);
  // Every polytope was filtered: a vertex won outright, or the exact stage saw only the
  // contenders, a few per cent of the candidates.
  BOOST_TEST(counts[0] + counts[1] == filtered0 + contenders0 + polytopes);
  BOOST_TEST(counts[0] > filtered0 + 10);
  BOOST_TEST(counts[1] > contenders0 + 10);
  BOOST_TEST(kept.contenders * 20 < kept.candidates);
  // Nearly every polytope's centroid is certified in doubles.
  BOOST_TEST(10 * (internal::certified_centroid_stage_counts()[0] - certified0) >= 9u * static_cast<unsigned>(polytopes));
}

BOOST_AUTO_TEST_CASE(exact_ties_and_touching_candidates) {
  Rng rng(1990);
  Kept kept;
  // The simplex d >= 0, d1 + d2 + d3 <= 3 cut by d1 <= c: for c = 1 the facet's stationary point
  // (1, 1, 1) lies exactly on the cut's edge, for c = 1 ± 2^-70 a hair inside or outside it (the
  // filter cannot place it); for c = 3/2 inside the facet; for c = 1/2 outside.
  const R hair(1, mpz_class(1) << 70);
  for (const R c : {R(1), R(1 + hair), R(1 - hair), R(3, 2), R(1, 2)}) {
    const std::vector<Colour> cut{{0, 0, 0}, {c, 0, 0}, {0, 3, 0}, {0, 0, 3}, {c, R(3 - c), 0}, {c, 0, R(3 - c)}};
    agree(gamut(cut), rng, kept);
  }
  // Boxes and cubes: the far corner wins, every corner ties in angle with its mirror image.
  std::vector<Colour> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({R(1 + (i & 1)), R(1 + (i >> 1 & 1)), R(1 + (i >> 2 & 1))});
  agree(gamut(cube), rng, kept);
  agree(gamut(cube, CanonicalBlack::include), rng, kept);
  // An octahedron about (2, 2, 2): its vertices (2 ± 1, 2, 2) etc.; the stationary point of the
  // facet through (3, 2, 2), (2, 3, 2), (2, 2, 3), d = (7/3)·(1, 1, 1), is the facet's centroid.
  std::vector<Colour> octahedron;
  for (int k = 0; k < 3; ++k)
    for (int s : {-1, 1}) {
      Colour v{2, 2, 2};
      (k == 0 ? v.r : k == 1 ? v.g : v.b) += s;
      octahedron.push_back(v);
    }
  agree(gamut(octahedron), rng, kept);
  // Integer grids: many vertices, many equal products and angles.
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Colour> grid;
    for (int i = 0; i < 6 + trial % 10; ++i)
      grid.push_back({R(1 + rng() % 4), R(1 + rng() % 4), R(1 + rng() % 4)});
    agree(gamut(grid, trial % 2 ? CanonicalBlack::include : CanonicalBlack::exclude), rng, kept);
  }
  // Lower-dimensional F3 (polygon, segment, point) take the exact route.
  agree(gamut({{1, 1, 1}, {2, 1, 1}, {1, 2, 1}}), rng, kept);
  agree(gamut({{1, 4, 1}, {4, 1, 2}}), rng, kept);
  agree(gamut({{1, 2, 3}}), rng, kept);
}

// An exact map's reported components (exact_map_estimate_3): the integer fast path for normal
// doubles against the defining properties, which fix every field: lo <= q <= hi exactly, equal
// iff q is a double, else adjacent; nearest one of them; error_bound the least double >= |nearest
// − q|. On random fractions of up to 200 bits, exact doubles, midpoints between adjacent doubles
// (ties), and values about the subnormal threshold and DBL_MAX (the MPFR route).
BOOST_AUTO_TEST_CASE(exact_components_round_as_directed) {
  Rng rng(53);
  const double inf = std::numeric_limits<double>::infinity();
  auto check = [&](const R& q) {
    const internal::RoundedComponent c = internal::rounded_component(q);
    BOOST_TEST(c.nearest == to_double_nearest(q));
    BOOST_TEST(rational_from_double(c.lo) <= q);
    BOOST_TEST(q <= rational_from_double(c.hi));
    if (rational_from_double(c.lo) == q) BOOST_TEST(c.hi == c.lo);
    else BOOST_TEST(c.hi == std::nextafter(c.lo, inf));
    BOOST_TEST((c.nearest == c.lo || c.nearest == c.hi));
    const R error = abs(R(rational_from_double(c.nearest) - q));
    BOOST_TEST(error <= rational_from_double(c.error_bound));
    if (c.error_bound > 0) BOOST_TEST(rational_from_double(std::nextafter(c.error_bound, 0.0)) < error);
  };
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    auto bits = [&](int b) {  // a random integer below 2^b
      mpz_class z = 0;
      for (int w = 0; w < b; w += 64) z = (z << 64) + mpz_class(std::to_string(rng()));
      return mpz_class(z >> static_cast<mp_bitcnt_t>((b + 63) / 64 * 64 - b));
    };
    const mpz_class n = bits(1 + trial % 200), d = bits(1 + trial * 7 % 200);
    R q(n, d + 1);
    q.canonicalize();
    check(trial % 2 ? q : R(-q));
    const double x = std::ldexp(unit(rng), static_cast<int>(rng() % 2096) - 1074);
    check(rational_from_double(x));
    check(R((rational_from_double(x) + rational_from_double(std::nextafter(x, inf))) / 2));
  }
  const double tiny = std::numeric_limits<double>::min(), huge = std::numeric_limits<double>::max();
  const R hair(1, mpz_class(1) << 1100);
  for (const double x : {tiny, std::nextafter(tiny, 0.0), std::nextafter(tiny, 1.0), std::nextafter(huge, 0.0), 1.0, -1.0})
    for (const R& q : {rational_from_double(x), R(rational_from_double(x) + hair), R(rational_from_double(x) - hair)})
      check(q);
  check(rational_from_double(huge));
  check(R(rational_from_double(huge) - hair));
  check(R(0));
}

BOOST_AUTO_TEST_SUITE_END()
