// Forsyth's CRULE feasible set in 3-D from a prepared canonical gamut (the filtered clip) against
// the LP route it replaced (test::feasible_set_3d_reference in tests/support, the oracle): the same canonical
// ConvexSet3 on hundreds of seeded scenes — Munsell-like random gamuts with and without black,
// planar, collinear and one-colour gamuts, images with zero channels, empty F3, F3 a point, a
// segment or a polygon, integer grids where many planes meet (the exact stage decides), and
// images large enough for the filtered image-hull prefilter.
#include "../test_support.h"

#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/numerics/truncated_quotient.h>

#include "internal/clip_filter.h"
#include "internal/crule_exact.h"
#include "internal/plane_meets.h"
#include "internal/polytope_clip.h"
#include "internal/shifted_sieve.h"
#include "support/cgal_references.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include <stdexcept>
#include <thread>

using namespace gmcc;
using gmcc::test::Rng;
using R = Rational;

namespace {

struct Tally {
  int polytope = 0, polygon = 0, segment = 0, point = 0, empty = 0, unbounded = 0;
};

// New route (prepared, and through the old signature) against the oracle; both throw alike.
void agree(const std::vector<Colour>& canonical, const std::vector<Colour>& image, bool black, Tally& t) {
  const CanonicalBlack b = black ? CanonicalBlack::include : CanonicalBlack::exclude;
  ConvexSet3 old;
  try {
    old = test::feasible_set_3d_reference(canonical, image, b);
  } catch (const UnboundedFeasibleSet&) {
    ++t.unbounded;
    BOOST_CHECK_THROW(feasible_set_3d(CanonicalConstraints3(canonical, b), image), UnboundedFeasibleSet);
    return;
  }
  const ConvexSet3 now = feasible_set_3d(CanonicalConstraints3(canonical, b), image);
  BOOST_TEST((now == old));
  BOOST_TEST((feasible_set_3d(canonical, image, b) == old));
  switch (old.kind) {
    case ConvexKind3::polytope: ++t.polytope; break;
    case ConvexKind3::polygon: ++t.polygon; break;
    case ConvexKind3::segment: ++t.segment; break;
    case ConvexKind3::point: ++t.point; break;
    case ConvexKind3::empty: ++t.empty; break;
  }
}

Colour random_colour(Rng& rng, long hi, long den) {
  return {test::random_rational(rng, 0, hi, den), test::random_rational(rng, 0, hi, den),
          test::random_rational(rng, 0, hi, den)};
}

// The image of `surfaces` under the illuminant's diagonal map 1/d, each scaled by a shading factor.
std::vector<Colour> image_of(Rng& rng, const std::vector<Colour>& surfaces, const Colour& d, int n, bool shade) {
  std::vector<Colour> out;
  std::uniform_int_distribution<std::size_t> pick(0, surfaces.size() - 1);
  for (int i = 0; i < n; ++i) {
    const Colour& s = surfaces[pick(rng)];
    const R f = shade ? test::random_rational(rng, 1, 10, 10) / 10 : R(1);
    out.push_back({R(s.r / d.r * f), R(s.g / d.g * f), R(s.b / d.b * f)});
  }
  return out;
}

// The facets of conv(g) (full-dimensional) as integer planes: each half-space times the lcm of
// its denominators.
std::vector<internal::IntegerPlane3> integer_facet_planes(const std::vector<Point3>& g) {
  std::vector<internal::IntegerPlane3> planes;
  for (const internal::HalfSpace3& h : internal::hull_half_spaces_3(g)) {
    const mpz_class l = lcm_of_denominators_of(h.a.x, h.a.y, h.a.z, h.b);
    planes.push_back({{times_lcm(h.a.x, l), times_lcm(h.a.y, l), times_lcm(h.a.z, l)}, times_lcm(h.b, l)});
  }
  return planes;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(feasible_set_3d_prepared)

BOOST_AUTO_TEST_CASE(munsell_like_random_gamuts_agree_with_the_lp_route) {
  Rng rng(20260);
  Tally t;
  for (int trial = 0; trial < 240; ++trial) {
    std::vector<Colour> canonical;
    const int n = 5 + trial % 25;
    // Munsell-like: reflectance-ish rationals with up to 6-digit denominators.
    for (int i = 0; i < n; ++i) canonical.push_back(random_colour(rng, 1000, trial % 3 == 0 ? 999983 : 64));
    const Colour d{test::random_rational(rng, 1, 9, 4), test::random_rational(rng, 1, 9, 4),
                   test::random_rational(rng, 1, 9, 4)};
    std::vector<Colour> image = image_of(rng, canonical, d, 1 + trial % 11, trial % 4 == 1);
    if (trial % 7 == 3) image.push_back(random_colour(rng, 3000, 16));  // noise: F3 may be empty
    agree(canonical, image, trial % 2 == 0, t);
  }
  BOOST_TEST(t.polytope > 80);
  BOOST_TEST(t.empty + t.point + t.segment + t.polygon > 0);
}

BOOST_AUTO_TEST_CASE(integer_grids_where_many_planes_meet_agree) {
  // Small integer coordinates: coplanar canonical facets, image colours on the same planes,
  // vertices of F3 where more than three planes meet, ties the filters cannot settle.
  Rng rng(77);
  Tally t;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Colour> canonical;
    for (int i = 0; i < 4 + trial % 9; ++i) canonical.push_back(random_colour(rng, 3, 1));
    std::vector<Colour> image;
    for (int i = 0; i < 1 + trial % 5; ++i) image.push_back(random_colour(rng, 3, 1 + trial % 2));
    try {
      agree(canonical, image, trial % 3 != 0, t);
    } catch (const std::invalid_argument&) {
      BOOST_TEST(false);  // channels are >= 0 and lists non-empty
    }
  }
  BOOST_TEST(t.polytope > 20);
  BOOST_TEST(t.polygon + t.segment + t.point > 10);
  BOOST_TEST(t.unbounded > 0);
  BOOST_TEST(t.empty > 0);
}

BOOST_AUTO_TEST_CASE(flat_canonical_gamuts_agree) {
  Rng rng(1990);
  Tally t;
  for (int trial = 0; trial < 90; ++trial) {
    std::vector<Colour> canonical;
    const int kind = trial % 3;  // 0: planar, 1: collinear, 2: one colour
    const Colour p = random_colour(rng, 20, 3), q = random_colour(rng, 20, 3), r = random_colour(rng, 20, 3);
    for (int i = 0; i < (kind == 2 ? 1 : 6); ++i) {
      const R s = test::random_rational(rng, 0, 4, 4), w = kind == 0 ? test::random_rational(rng, 0, 4, 4) : R(0);
      canonical.push_back({R(p.r + s * (q.r - p.r) + w * (r.r - p.r)), R(p.g + s * (q.g - p.g) + w * (r.g - p.g)),
                           R(p.b + s * (q.b - p.b) + w * (r.b - p.b))});
    }
    for (Colour& c : canonical)  // keep channels >= 0
      for (R* x : {&c.r, &c.g, &c.b})
        if (sgn(*x) < 0) *x = -*x;
    const Colour d{test::random_rational(rng, 1, 5, 3), test::random_rational(rng, 1, 5, 3),
                   test::random_rational(rng, 1, 5, 3)};
    agree(canonical, image_of(rng, canonical, d, 1 + trial % 4, false), trial % 2 == 0, t);
  }
  BOOST_TEST(t.polytope + t.polygon + t.segment + t.point > 60);
}

BOOST_AUTO_TEST_CASE(hand_cases_every_kind) {
  const std::vector<Colour> cube{{1, 1, 1}, {2, 1, 1}, {1, 2, 1}, {1, 1, 2},
                                 {2, 2, 1}, {2, 1, 2}, {1, 2, 2}, {2, 2, 2}};
  Tally t;
  agree(cube, {{1, 1, 1}}, false, t);                    // polytope
  agree(cube, {{1, 1, 1}, {2, 1, 1}}, false, t);         // polygon
  agree(cube, {{1, 1, 1}, {2, 2, 1}}, false, t);         // segment
  agree(cube, {{1, 1, 1}, {2, 2, 2}}, false, t);         // point
  agree(cube, {{1, 1, 1}, {4, 1, 1}}, false, t);         // empty
  agree(cube, {{1, 1, 1}, {4, 1, 1}}, true, t);          // black: never empty
  agree(cube, {{0, 1, 1}}, true, t);                     // unbounded
  agree(cube, {{0, 1, 1}, {1, 0, 1}, {1, 1, 0}}, true, t);  // zero channels, bounded
  BOOST_TEST(t.polytope == 1);
  BOOST_TEST(t.polygon == 1);
  BOOST_TEST(t.segment == 2);  // with black, {(1,1,1), (4,1,1)} leaves a segment from 0
  BOOST_TEST(t.point == 2);    // with black, one zero channel per colour leaves only 0
  BOOST_TEST(t.empty == 1);
  BOOST_TEST(t.unbounded == 1);
  BOOST_CHECK_THROW(CanonicalConstraints3({}), std::invalid_argument);
  BOOST_CHECK_THROW(feasible_set_3d(CanonicalConstraints3(cube), {}), std::invalid_argument);
  BOOST_CHECK_THROW(feasible_set_3d(CanonicalConstraints3(cube), {{1, -1, 1}}), std::invalid_argument);
  BOOST_TEST(CanonicalConstraints3(cube).dimension() == 3);
  BOOST_TEST(CanonicalConstraints3(cube, CanonicalBlack::exclude).half_spaces() == 6u);
  BOOST_TEST(CanonicalConstraints3({{1, 2, 3}}, CanonicalBlack::exclude).dimension() == 0);
}

// fuzz_crule's finding (fuzz/corpus/crule/finding_vertex_made_exact_then_one_out_of_range),
// reduced: F3's final vertices are known by their truncated doubles, one of them made exact on
// the way (its double-word copy did not decide it), and a later one outside the range policy's
// first range (channels from 2^-56 to 2^52) sends every vertex to the exact route, which read the
// first one's coordinates after they had been moved on (W = 0: an InternalError). The route
// must give the LP route's F3, and so must the lazy set made exact.
BOOST_AUTO_TEST_CASE(a_vertex_made_exact_then_one_out_of_range) {
  const std::vector<Colour> canonical{
      {85, 0, 0}, {R(mpz_class("21712730222"), mpz_class("241089902801")), R(7, 18), 196608}, {65536, 0, R(mpz_class("51539607552"))}};
  const std::vector<Colour> image{{R(mpz_class("4503599627370496")), R(2, 3), 171},
                                  {R(1, mpz_class("72057594037927936")), R(mpz_class("35184372088832")), R(mpz_class("21474836480"))}};
  Tally t;
  agree(canonical, image, true, t);
  BOOST_TEST(t.polytope == 1);
  const CanonicalConstraints3 prepared(canonical, CanonicalBlack::include);
  BOOST_TEST((feasible_set_3d_lazy({GamutConstraint3{&prepared, &image}}).exact() ==
              test::feasible_set_3d_reference(canonical, image, CanonicalBlack::include)));
}

// The lazy set's final vertices are made from rows kept as their canonical facet and image point
// (issue 46 item 3, fourth round): made exact only after the prepared gamuts are gone (their
// memory reused by others), with two constraints (two groups of rows, the second group's points
// after the first's), they must be the LP route's F3. Fails if the set does not keep the facets
// alive (under the sanitizers at least) or reads a group's points at the wrong place.
BOOST_AUTO_TEST_CASE(lazy_rows_outlive_the_prepared_gamuts_and_serve_several_groups) {
  Rng rng(4607);
  int polytopes = 0;
  for (int trial = 0; trial < 16; ++trial) {
    std::vector<Colour> g[2];
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 8 + trial % 9; ++i) g[k].push_back(random_colour(rng, 1000, trial % 2 ? 999983 : 64));
    const Colour d{test::random_rational(rng, 1, 9, 4), test::random_rational(rng, 1, 9, 4),
                   test::random_rational(rng, 1, 9, 4)};
    // Each image colour the mean of three of its gamut's colours, halved, under 1/d: d maps it
    // inside G_c3, so F3 is (generically) a polytope.
    std::vector<Colour> image[2];
    for (int k = 0; k < 2; ++k) {
      const std::vector<Colour> a = image_of(rng, g[k], d, 3 * (3 + (trial + k) % 5), false);
      for (std::size_t i = 0; i + 2 < a.size(); i += 3)
        image[k].push_back({R((a[i].r + a[i + 1].r + a[i + 2].r) / 6), R((a[i].g + a[i + 1].g + a[i + 2].g) / 6),
                            R((a[i].b + a[i + 1].b + a[i + 2].b) / 6)});
    }
    LazyConvexSet3 F;
    {
      const CanonicalConstraints3 c0(g[0], CanonicalBlack::include), c1(g[1], CanonicalBlack::include);
      F = feasible_set_3d_lazy({{&c0, &image[0]}, {&c1, &image[1]}});
    }
    for (int k = 0; k < 2; ++k) {  // other gamuts in the memory the first ones had
      std::vector<Colour> other;
      for (int i = 0; i < 12; ++i) other.push_back(random_colour(rng, 50, 3));
      const CanonicalConstraints3 junk(other, CanonicalBlack::exclude);
      BOOST_TEST(junk.dimension() == 3);
    }
    std::vector<Point3> points[2], hull[2];
    std::vector<internal::HalfSpace3> half_spaces[2];
    Point3 max[2];
    for (int k = 0; k < 2; ++k) {
      hull[k].push_back({0, 0, 0});  // black included
      for (const Colour& c : g[k]) {
        hull[k].push_back({c.r, c.g, c.b});
        max[k] = {std::max(max[k].x, c.r), std::max(max[k].y, c.g), std::max(max[k].z, c.b)};
      }
      for (const Colour& c : image[k]) points[k].push_back({c.r, c.g, c.b});
      half_spaces[k] = internal::hull_half_spaces_3(hull[k]);
    }
    const ConvexSet3 want = internal::feasible_set_3d_lp(
        {{&half_spaces[0], &max[0], &points[0]}, {&half_spaces[1], &max[1], &points[1]}});
    BOOST_TEST((F.exact() == want), "trial " << trial);
    polytopes += want.kind == ConvexKind3::polytope;
  }
  BOOST_TEST(polytopes > 10);
}

BOOST_AUTO_TEST_CASE(large_images_through_the_hull_prefilter_agree) {
  Rng rng(4242);
  Tally t;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<Colour> canonical;
    for (int i = 0; i < 12; ++i) canonical.push_back(random_colour(rng, 1000, 97));
    const Colour d{test::random_rational(rng, 1, 9, 4), test::random_rational(rng, 1, 9, 4),
                   test::random_rational(rng, 1, 9, 4)};
    // 64 to 600 colours, shaded: most strictly inside the hull of the rest. From 4 of the 12
    // surfaces F3 is a polytope; from all 12 (every third trial) with black, the segment [0, d].
    const std::vector<Colour> seen(canonical.begin(), canonical.begin() + (trial % 3 == 2 ? 12 : 4));
    std::vector<Colour> image = image_of(rng, seen, d, 64 + 50 * trial, true);
    if (trial % 4 == 3)  // flat image: every colour on one plane through the origin
      for (Colour& c : image) c.b = c.r;
    agree(canonical, image, trial % 2 == 0, t);
  }
  BOOST_TEST(t.polytope >= 3);
  BOOST_TEST(t.polytope + t.polygon + t.segment + t.point + t.empty == 12);
}

BOOST_AUTO_TEST_CASE(one_prepared_gamut_shared_by_threads) {
  Rng rng(5);
  std::vector<Colour> canonical;
  for (int i = 0; i < 20; ++i) canonical.push_back(random_colour(rng, 1000, 97));
  const CanonicalConstraints3 prepared(canonical);
  std::vector<std::vector<Colour>> images;
  for (int i = 0; i < 16; ++i) images.push_back(image_of(rng, canonical, {2, 3, R(1, 2)}, 8, true));
  std::vector<ConvexSet3> a(images.size()), b(images.size());
  auto run = [&](std::vector<ConvexSet3>& out) {
    for (std::size_t i = 0; i < images.size(); ++i) out[i] = feasible_set_3d(prepared, images[i]);
  };
  std::thread one(run, std::ref(a)), two(run, std::ref(b));
  one.join(), two.join();
  for (std::size_t i = 0; i < images.size(); ++i) {
    BOOST_TEST((a[i] == b[i]));
    BOOST_TEST((a[i] == test::feasible_set_3d_reference(canonical, images[i], CanonicalBlack::include)));
  }
}

BOOST_AUTO_TEST_CASE(clip_decides_ties_exactly) {
  // The unit cube cut by x + y + z <= 1 and by planes through its vertices: every new plane
  // passes through existing vertices (side exactly 0), which the filter cannot settle.
  std::vector<internal::IntegerPlane3> planes;
  auto plane = [](long a, long b, long c, long d) {
    return internal::IntegerPlane3{{mpz_class(a), mpz_class(b), mpz_class(c)}, mpz_class(d)};
  };
  planes.push_back(plane(1, 1, 1, 1));   // the corner simplex
  planes.push_back(plane(1, 1, 0, 1));   // through three of its vertices: changes nothing
  planes.push_back(plane(1, -1, 0, 0));  // x <= y, through the origin and (0, 0, 1)
  internal::ClipCounts counts;
  const internal::ClippedPolytope r = internal::clip_polytope({1, 1, 1}, planes, &counts);
  BOOST_TEST((r.outcome == internal::ClippedPolytope::Outcome::polytope));
  const std::vector<Point3> want{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {R(1, 2), R(1, 2), 0}};
  BOOST_TEST((r.set.exact().vertices == want));
  BOOST_TEST(r.set.faces().size() == 4u);
  BOOST_TEST(volume(r.set.exact()) == R(1, 12));
  BOOST_TEST(counts.exact > 0);
  BOOST_TEST(counts.filtered > 0);
  // A plane that leaves only a face: flat; one that leaves nothing: empty.
  planes.push_back(plane(-1, -1, -1, -1));
  BOOST_TEST((internal::clip_polytope({1, 1, 1}, planes).outcome == internal::ClippedPolytope::Outcome::flat));
  planes.back() = plane(-1, -1, -1, -2);
  BOOST_TEST((internal::clip_polytope({1, 1, 1}, planes).outcome == internal::ClippedPolytope::Outcome::empty));
  // One that leaves only the vertex 0 (x + y + z <= 0): the point, when the other rows hold there
  // (z <= 1, and a row through it), else empty (x >= 1/4) — in whichever order the rows come.
  planes.back() = plane(1, 1, 1, 0);
  planes.push_back(plane(0, 0, 1, 1));
  planes.push_back(plane(2, -1, 0, 0));
  const internal::ClippedPolytope p = internal::clip_polytope({1, 1, 1}, planes);
  BOOST_TEST((p.outcome == internal::ClippedPolytope::Outcome::polytope));
  BOOST_TEST((p.set.kind() == ConvexKind3::point));
  BOOST_TEST((p.set.exact().vertices == std::vector<Point3>{{0, 0, 0}}));
  planes.push_back(plane(-4, 0, 0, -1));
  BOOST_TEST((internal::clip_polytope({1, 1, 1}, planes).outcome == internal::ClippedPolytope::Outcome::empty));
}


namespace {
// The vertices and facets of {x : 0 <= x <= box, a·x <= b for each plane} by brute force: each
// triple of the planes (box sides included) meeting in one point that satisfies them all, exactly
// (sorted); each facet as the sorted indices of the vertices on a plane that holds a 2-dimensional
// set of them (facets sorted, no repeats).
struct BruteForce {
  std::vector<Point3> vertices;
  std::vector<std::vector<std::size_t>> facets;
};
BruteForce brute_force(const Point3& box, const std::vector<internal::IntegerPlane3>& planes) {
  struct P { R a[3]; R b; };
  std::vector<P> all;
  for (int k = 0; k < 3; ++k) {
    P lo{{0, 0, 0}, 0}, hi{{0, 0, 0}, k == 0 ? box.x : k == 1 ? box.y : box.z};
    lo.a[k] = -1, hi.a[k] = 1;
    all.push_back(lo), all.push_back(hi);
  }
  for (const internal::IntegerPlane3& p : planes) all.push_back({{R(p.a[0]), R(p.a[1]), R(p.a[2])}, R(p.b)});
  std::vector<Point3> out;
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      for (std::size_t k = j + 1; k < all.size(); ++k) {
        const R(&x)[3] = all[i].a, (&y)[3] = all[j].a, (&z)[3] = all[k].a;
        const R c0 = y[1] * z[2] - y[2] * z[1], c1 = y[2] * z[0] - y[0] * z[2], c2 = y[0] * z[1] - y[1] * z[0];
        const R det = x[0] * c0 + x[1] * c1 + x[2] * c2;
        if (sgn(det) == 0) continue;
        // Cramer's rule: x_m = det_m / det, column m replaced by the offsets.
        R v[3];
        for (int m = 0; m < 3; ++m) {
          R r[3][3];
          for (int c = 0; c < 3; ++c) r[0][c] = x[c], r[1][c] = y[c], r[2][c] = z[c];
          r[0][m] = all[i].b, r[1][m] = all[j].b, r[2][m] = all[k].b;
          v[m] = (r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) - r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                  r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0])) / det;
        }
        bool inside = true;
        for (const P& q : all) inside = inside && q.a[0] * v[0] + q.a[1] * v[1] + q.a[2] * v[2] <= q.b;
        if (inside) out.push_back({v[0], v[1], v[2]});
      }
  BruteForce r{internal::sorted_unique(std::move(out)), {}};
  for (const P& q : all) {
    std::vector<std::size_t> on;
    std::vector<Point3> points;
    for (std::size_t i = 0; i < r.vertices.size(); ++i) {
      const Point3& v = r.vertices[i];
      if (q.a[0] * v.x + q.a[1] * v.y + q.a[2] * v.z == q.b) on.push_back(i), points.push_back(v);
    }
    if (!points.empty() && internal::affine_dimension(points) == 2) r.facets.push_back(on);
  }
  std::sort(r.facets.begin(), r.facets.end());
  r.facets.erase(std::unique(r.facets.begin(), r.facets.end()), r.facets.end());
  return r;
}
}  // namespace

// Every side decision of the clip (the vertex's own bound first, then the plane's, then exact)
// against brute force, on planes through the box's corners and points in thirds of it (vertices
// exactly on a plane, as in half the cuts of CRULE's scenes), at scales 2^-200, 1 and 2^200 of
// the box and offsets (the filters' range limits), with a small offset that leaves a vertex just
// outside or inside.
BOOST_AUTO_TEST_CASE(clip_sides_agree_with_brute_force_at_extreme_scales) {
  Rng rng(4603);
  std::uniform_int_distribution<long> coefficient(-4, 4), big(-(1L << 30), 1L << 30), pick(0, 15), nudge(-1, 1);
  int polytopes = 0, flats = 0, empties = 0;
  long filtered = 0;
  for (int trial = 0; trial < 90; ++trial) {
    const int s = trial % 3 == 0 ? -200 : trial % 3 == 1 ? 0 : 200;
    mpz_class num = 1, den = 1;  // 2^s = num / den
    if (s > 0) mpz_mul_2exp(num.get_mpz_t(), num.get_mpz_t(), static_cast<mp_bitcnt_t>(s));
    if (s < 0) mpz_mul_2exp(den.get_mpz_t(), den.get_mpz_t(), static_cast<mp_bitcnt_t>(-s));
    const R scale(num, den);
    const Point3 box{R(4 * scale), R(4 * scale), R(4 * scale)};
    std::vector<internal::IntegerPlane3> planes;
    for (int n = 0; n < 3 + trial % 5; ++n) {
      // Small normals half the time, else of up to 31 bits (the vertices' doubles then round).
      long a[3];
      do {
        for (long& x : a) x = trial % 6 < 3 ? coefficient(rng) : big(rng);
      } while (a[0] == 0 && a[1] == 0 && a[2] == 0);
      // Through a point q with coordinates in {0, 4/3, 8/3, 4}·2^s (corners and points in thirds,
      // so that most vertices are not dyadic and their doubles round), nudged by 2^(s-4)/3 now
      // and then: a·x <= (a·q + t/48)·2^s, times 48·den.
      // In two trials of four every plane passes through one inner point (1 or 2 thirds of the box
      // in each coordinate): a vertex on many planes, each cut through it deciding a side of 0.
      const bool apex = trial % 4 < 2;
      const long q = pick(rng), t = trial % 2 && !(apex && n < 3) ? nudge(rng) : 0;
      const long c[3] = {apex ? 1 + trial / 4 % 2 : q % 4, apex ? 1 + trial / 8 % 2 : (q / 4) % 4,
                         apex ? 1 + trial / 16 % 2 : (q + trial) % 4};
      const long off = 64 * (a[0] * c[0] + a[1] * c[1] + a[2] * c[2]) + t;
      planes.push_back({{mpz_class(48 * a[0] * den), mpz_class(48 * a[1] * den), mpz_class(48 * a[2] * den)},
                        mpz_class(off * num)});
    }
    internal::ClipCounts counts;
    const internal::ClippedPolytope r = internal::clip_polytope(box, planes, &counts);
    const BruteForce brute = brute_force(box, planes);
    const std::vector<Point3>& want = brute.vertices;
    filtered += counts.filtered;
    switch (r.outcome) {
      case internal::ClippedPolytope::Outcome::polytope:
        ++polytopes;
      {
        const ConvexSet3 F = r.set.exact();
        BOOST_TEST((F.vertices == want), "trial " << trial);
        std::vector<std::vector<std::size_t>> faces = F.faces;  // as index sets, sorted
        for (std::vector<std::size_t>& f : faces) std::sort(f.begin(), f.end());
        std::sort(faces.begin(), faces.end());
        BOOST_TEST((faces == brute.facets), "trial " << trial);
        break;
      }
      case internal::ClippedPolytope::Outcome::flat:
        ++flats;
        // Lower-dimensional or empty (later rows are for the LP route to read).
        if (!want.empty()) BOOST_TEST(internal::affine_dimension(want) < 3, "trial " << trial);
        break;
      case internal::ClippedPolytope::Outcome::empty:
        ++empties;
        BOOST_TEST(want.empty(), "trial " << trial);
        break;
    }
  }
  BOOST_TEST(polytopes > 30);
  BOOST_TEST(flats + empties > 5);
  BOOST_TEST(filtered > 1000);
}

// The hull of small integer colours (pixel values below 2^16: the prefilter's planes exact in
// double) against the general route on the same colours divided by 3 (rationals: the filtered
// prefilter and CGAL's exact-constructions hull), on sets with many points on the hull's faces
// and edges, flat and collinear sets, repeats, and the extremes 0 and 65535.
BOOST_AUTO_TEST_CASE(rows_of_one_point_settled_by_the_gamut_incidences) {
  // The clip with G's vertices (ClipFacets::on) against the clip without them, on scenes where
  // G's vertices have more than three facets (small integer gamuts) and on Munsell-like ones: the
  // same exact set, and sides the filter cannot settle read from the incidences instead of made
  // exact (docs/derivations.md §4.6, "Rows of one point").
  Rng rng(4606);
  long incident = 0, exact_with = 0, exact_without = 0;
  for (int trial = 0; trial < 120; ++trial) {
    std::vector<Point3> g{{0, 0, 0}};
    for (int i = 0; i < 5 + trial % 20; ++i) {
      const Colour c = random_colour(rng, trial % 2 ? 3 : 1000, trial % 2 ? 1 : 64);
      g.push_back({c.r, c.g, c.b});
    }
    g = internal::sorted_unique(std::move(g));
    if (internal::affine_dimension(g) < 3) continue;
    const std::vector<internal::IntegerPlane3> planes = integer_facet_planes(g);
    const internal::ClipFacets with = internal::clip_facets(planes, internal::extreme_points_3(g));
    const internal::ClipFacets without = internal::clip_facets(planes);
    std::vector<Point3> points;
    for (int i = 0; i < 1 + trial % 6; ++i) {
      const Colour c = random_colour(rng, trial % 2 ? 3 : 1000, trial % 2 ? 1 : 16);
      if (sgn(c.r) > 0 && sgn(c.g) > 0 && sgn(c.b) > 0) points.push_back({c.r, c.g, c.b});
    }
    if (points.empty()) continue;
    points = internal::sorted_unique(std::move(points));
    const Point3 box{R(100), R(100), R(100)};
    internal::ClipCounts a, b;
    const internal::ClippedPolytope x = internal::clip_polytope(box, with, points, &a);
    const internal::ClippedPolytope y = internal::clip_polytope(box, without, points, &b);
    BOOST_TEST((x.outcome == y.outcome));
    if (x.outcome != y.outcome) continue;
    if (x.outcome != internal::ClippedPolytope::Outcome::flat) BOOST_TEST((x.set.exact() == y.set.exact()));
    BOOST_TEST(b.incident == 0);
    incident += a.incident, exact_with += a.exact, exact_without += b.exact;
  }
  BOOST_TEST(incident > 0);
  BOOST_TEST(exact_with + incident == exact_without);
  // Points outside a half-space are refused.
  std::vector<internal::IntegerPlane3> unit{{{mpz_class(1), mpz_class(0), mpz_class(0)}, mpz_class(1)}};
  BOOST_CHECK_THROW(internal::clip_facets(unit, {Point3{2, 0, 0}}), std::invalid_argument);
  BOOST_TEST(internal::clip_facets(unit, {Point3{1, 0, 0}, Point3{0, 0, 0}}).on[0][0] == 1u);
}

BOOST_AUTO_TEST_CASE(small_integer_colour_hulls_agree_with_the_general_route) {
  Rng rng(2611);
  for (int trial = 0; trial < 40; ++trial) {
    const int kind = trial % 5;
    const unsigned top = trial % 2 ? 65535 : 12;  // a small range: many colours on faces and edges
    std::uniform_int_distribution<unsigned> channel(0, top);
    std::vector<Colour> colours;
    const int n = 64 + 97 * trial;
    for (int i = 0; i < n; ++i) {
      unsigned c[3] = {channel(rng), channel(rng), channel(rng)};
      if (kind == 1) c[2] = c[0];                 // flat: the plane b = r
      if (kind == 2) c[1] = c[0], c[2] = c[0];    // collinear: the grey axis
      if (kind == 3) c[i % 3] = i % 2 ? 0 : top;  // most colours on the cube's faces
      colours.push_back({R(c[0]), R(c[1]), R(c[2])});
    }
    std::vector<Colour> thirds;
    for (const Colour& c : colours) thirds.push_back({R(c.r / 3), R(c.g / 3), R(c.b / 3)});
    std::vector<Colour> expected;
    for (const Colour& c : colour_hull_vertices(thirds)) expected.push_back({R(c.r * 3), R(c.g * 3), R(c.b * 3)});
    BOOST_TEST((colour_hull_vertices(colours) == expected), "trial " << trial);
    std::vector<std::array<double, 3>> d;
    for (const Colour& c : colours) d.push_back({c.r.get_d(), c.g.get_d(), c.b.get_d()});
    std::vector<Colour> by_index;
    for (std::size_t i : colour_hull_vertex_indices(d)) by_index.push_back(colours[i]);
    BOOST_TEST((by_index == expected), "trial " << trial);
  }
}

BOOST_AUTO_TEST_CASE(shifted_sieve_four_facets_at_a_time_decides_as_one_at_a_time) {
  // The prefilter's facet test (internal/shifted_sieve.h) with AVX2, four facets at a time, against
  // one at a time: the same indices, bit for bit, for facet counts 1 to 13 (every padding) and
  // colours on or next to the facets' planes (f3/f0 rounded: on the plane where f0 is 1, 2 or 4),
  // negative, zero, out of the range policy, infinite and NaN channels, and none at all (every
  // colour kept). Without AVX2 at run time both calls take the scalar route and the test compares
  // it with itself (said in the log).
#if defined(__x86_64__) && defined(__GNUC__)
  if (!__builtin_cpu_supports("avx2")) BOOST_TEST_MESSAGE("no AVX2 here: both routes are the scalar one");
#endif
  std::mt19937 rng(4649);
  std::uniform_int_distribution<int> small(-4, 4), channel(0, 12);
  for (std::size_t facets = 0; facets <= 13; ++facets)
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<std::array<double, 4>> g(facets);
      for (auto& f : g) f = {double(small(rng)), double(small(rng)), double(small(rng)), double(small(rng) + 20)};
      std::vector<std::array<double, 3>> d;
      for (int i = 0; i < 300; ++i) d.push_back({double(channel(rng)), double(channel(rng)), double(channel(rng))});
      for (const auto& f : g)  // on or next to the plane: f·p = f3 for p = f3/f0 along x
        if (f[0] > 0 && f[3] >= 0) d.push_back({f[3] / f[0], 0, 0});
      d.push_back({-1, 0, 0}), d.push_back({0, 0, 0}), d.push_back({0x1p-200, 1, 1}),
          d.push_back({HUGE_VAL, 1, 1}), d.push_back({std::nan(""), 1, 1}), d.push_back({0.5, 0.25, 1e-3});
      const std::vector<std::size_t> four = internal::not_certified_inside(g, d, true),
                                     one = internal::not_certified_inside(g, d, false);
      BOOST_TEST(four == one, facets << " facets, trial " << trial);
      if (facets == 0) BOOST_TEST(one.size() == d.size());
    }
}

BOOST_AUTO_TEST_CASE(scaled_colour_hulls_through_the_shifted_planes_agree) {
  // Issue 46 (edge colours): the double prefilter's shifted facet planes (one dot product a
  // facet) against the small-integer sieve, an independent route: integer colours, many on
  // planes through the extreme colours (the cube's faces, r + g + b = top, the grey axis), and
  // the same colours times 2^k as doubles (not small integers: the general route), the same
  // vertices by index at every scale.
  Rng rng(4646);
  for (int trial = 0; trial < 24; ++trial) {
    const unsigned top = trial % 3 == 0 ? 12 : trial % 3 == 1 ? 255 : 65535;
    std::uniform_int_distribution<unsigned> channel(0, top);
    std::vector<std::array<double, 3>> colours;
    for (int i = 0; i < 200 + 150 * trial; ++i) {
      unsigned c[3] = {channel(rng), channel(rng), channel(rng)};
      if (i % 4 == 1) c[i % 3] = i % 8 == 1 ? 0 : top;  // on a face of the cube
      if (i % 4 == 2 && c[0] + c[1] <= top) c[2] = top - c[0] - c[1];  // on r + g + b = top
      if (i % 16 == 3) c[1] = c[2] = c[0];  // the grey axis
      colours.push_back({double(c[0]), double(c[1]), double(c[2])});
    }
    const std::vector<std::size_t> want = colour_hull_vertex_indices(colours);
    BOOST_TEST(want.size() >= 4u);
    for (int k : {-100, -30, 1, 7, 100}) {
      std::vector<std::array<double, 3>> scaled;
      for (const auto& c : colours) scaled.push_back({std::ldexp(c[0], k), std::ldexp(c[1], k), std::ldexp(c[2], k)});
      BOOST_TEST((colour_hull_vertex_indices(scaled) == want), "trial " << trial << " scale 2^" << k);
    }
  }
}

// The joint F3 of several gamut types (feasible_set_3d over GamutConstraint3s: one clip over
// every type's rows) against the LP route over the same rows (the oracle, its own hulls):
// pixel-like and edge-like types from one scene, with and without black, flat gamuts, noise that
// empties the set; one type alone is feasible_set_3d, and a type joined with itself is itself.
BOOST_AUTO_TEST_CASE(joint_feasible_sets_of_several_types_agree_with_the_lp_route) {
  Rng rng(2610);
  Tally t;
  for (int trial = 0; trial < 120; ++trial) {
    const bool black = trial % 3 != 2;
    const int types = 2 + trial % 2;
    const Colour d{test::random_rational(rng, 1, 9, 4), test::random_rational(rng, 1, 9, 4),
                   test::random_rational(rng, 1, 9, 4)};
    std::vector<std::vector<Colour>> canonical(types), image(types);
    for (int k = 0; k < types; ++k) {
      if (k == 0)  // pixel-like: surfaces
        for (int i = 0; i < 4 + trial % 9; ++i) canonical[k].push_back(random_colour(rng, 1000, trial % 2 ? 64 : 999983));
      else  // edge-like: channel-wise magnitudes of differences of surfaces (and of those)
        for (std::size_t i = 0; i + 1 < canonical[k - 1].size(); ++i) {
          const Colour &a = canonical[k - 1][i], &b = canonical[k - 1][i + 1];
          canonical[k].push_back({R(abs(a.r - b.r)), R(abs(a.g - b.g)), R(abs(a.b - b.b))});
        }
      if (trial % 11 == 5 && k == 1)  // a flat canonical gamut: the LP route decides
        for (Colour& c : canonical[k]) c.b = c.r;
      image[k] = image_of(rng, canonical[k], d, 1 + (trial + 3 * k) % 4, trial % 4 != 0);
      if (trial % 7 == 3 && k == types - 1) image[k].push_back(random_colour(rng, 3000, 16));
    }
    std::vector<std::vector<internal::HalfSpace3>> halves(types);
    std::vector<Point3> maxima(types);
    std::vector<std::vector<Point3>> points(types);
    std::vector<internal::LpPart> parts;
    std::vector<CanonicalConstraints3> prepared;
    for (int k = 0; k < types; ++k) {
      std::vector<Point3> c;
      for (const Colour& x : canonical[k]) c.push_back({x.r, x.g, x.b});
      if (black) c.push_back({0, 0, 0});
      c = internal::sorted_unique(c);
      halves[k] = internal::hull_half_spaces_3(c);
      for (const Point3& x : c)
        maxima[k] = {std::max(maxima[k].x, x.x), std::max(maxima[k].y, x.y), std::max(maxima[k].z, x.z)};
      for (const Colour& x : image[k]) points[k].push_back({x.r, x.g, x.b});
      points[k] = internal::sorted_unique(points[k]);
      prepared.emplace_back(canonical[k], black ? CanonicalBlack::include : CanonicalBlack::exclude);
    }
    std::vector<GamutConstraint3> constraints;
    for (int k = 0; k < types; ++k) {
      parts.push_back({&halves[k], &maxima[k], &points[k]});
      constraints.push_back({&prepared[k], &image[k]});
    }
    ConvexSet3 oracle;
    try {
      oracle = internal::feasible_set_3d_lp(parts);
    } catch (const UnboundedFeasibleSet&) {
      ++t.unbounded;
      BOOST_CHECK_THROW(feasible_set_3d(constraints), UnboundedFeasibleSet);
      continue;
    }
    const ConvexSet3 joint = feasible_set_3d(constraints);
    BOOST_TEST((joint == oracle), "trial " << trial);
    BOOST_TEST((feasible_set_3d(std::vector<GamutConstraint3>{constraints[0]}) ==
                feasible_set_3d(prepared[0], image[0])));
    BOOST_TEST((feasible_set_3d(std::vector<GamutConstraint3>{constraints[1], constraints[1]}) ==
                feasible_set_3d(prepared[1], image[1])));
    switch (joint.kind) {
      case ConvexKind3::polytope: ++t.polytope; break;
      case ConvexKind3::polygon: ++t.polygon; break;
      case ConvexKind3::segment: ++t.segment; break;
      case ConvexKind3::point: ++t.point; break;
      case ConvexKind3::empty: ++t.empty; break;
    }
  }
  BOOST_TEST(t.polytope >= 10);  // the joint clip
  BOOST_TEST(t.segment + t.point + t.polygon > 0);  // the joint LP route
  BOOST_TEST(t.empty > 0);
  BOOST_CHECK_THROW(feasible_set_3d(std::vector<GamutConstraint3>{}), std::invalid_argument);
}

// Rows that hold on the whole box are left out of the clip's order (deepest_first: the box's own
// filter settles them before the first cut, and no later polytope leaves the box): the outcome and
// the exact set are those of brute force and of the clip without those rows, with rows tangent to
// the box at a corner (kept: the filter cannot settle them), constant rows (0 <= 1 left out,
// 0 <= -1 kept: no map at all), and a row that leaves one corner (the point outcome, whose check of
// the later rows skips those left out).
BOOST_AUTO_TEST_CASE(rows_the_box_holds_are_left_out_and_change_nothing) {
  Rng rng(4631);
  std::uniform_int_distribution<long> coefficient(-5, 5), side(1, 6), extra(0, 3), pick(0, 99);
  auto plane = [](long a, long b, long c, long d) {
    return internal::IntegerPlane3{{mpz_class(a), mpz_class(b), mpz_class(c)}, mpz_class(d)};
  };
  int polytopes = 0, held = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const long B[3] = {side(rng), side(rng), side(rng)};
    const Point3 box{R(B[0]), R(B[1]), R(B[2])};
    std::vector<internal::IntegerPlane3> cutting, all;
    for (int n = 0; n < 2 + trial % 4; ++n) {  // through a point inside the box: they cut it
      long a[3];
      do {
        for (long& x : a) x = coefficient(rng);
      } while (a[0] == 0 && a[1] == 0 && a[2] == 0);
      cutting.push_back(plane(2 * a[0], 2 * a[1], 2 * a[2], a[0] * B[0] + a[1] * B[1] + a[2] * B[2]));
    }
    all = cutting;
    for (int n = 0; n < 14; ++n) {  // holding on the box: strictly, or tangent at a corner
      long a[3], top = 0;
      for (int k = 0; k < 3; ++k) a[k] = coefficient(rng), top += std::max(a[k], 0L) * B[k];
      if (a[0] == 0 && a[1] == 0 && a[2] == 0) continue;
      all.push_back(plane(a[0], a[1], a[2], top + (n % 4 == 0 ? 0 : 1 + extra(rng))));
      held += n % 4 != 0;
    }
    all.push_back(plane(0, 0, 0, 1));
    std::shuffle(all.begin(), all.end(), rng);
    const internal::ClippedPolytope r = internal::clip_polytope(box, all, nullptr);
    const internal::ClippedPolytope c = internal::clip_polytope(box, cutting, nullptr);
    BOOST_TEST((r.outcome == c.outcome), "trial " << trial);
    if (r.outcome != internal::ClippedPolytope::Outcome::polytope || c.outcome != r.outcome) continue;
    ++polytopes;
    const ConvexSet3 F = r.set.exact();
    BOOST_TEST((F == c.set.exact()), "trial " << trial);
    BOOST_TEST((F.vertices == brute_force(box, all).vertices), "trial " << trial);
    // No map at all: 0 <= -1 is never left out.
    all.push_back(plane(0, 0, 0, -1));
    std::shuffle(all.begin(), all.end(), rng);
    BOOST_TEST((internal::clip_polytope(box, all, nullptr).outcome == internal::ClippedPolytope::Outcome::empty));
    // One corner left: -x - y - z <= -(B0 + B1 + B2), then the rows that hold on the box.
    std::vector<internal::IntegerPlane3> corner{plane(-1, -1, -1, -(B[0] + B[1] + B[2]))};
    const std::vector<Point3> corners = brute_force(box, {}).vertices;
    for (const internal::IntegerPlane3& h : all)  // those holding on the box (its corners unchanged)
      if (sgn(h.a[0]) != 0 || sgn(h.a[1]) != 0 || sgn(h.a[2]) != 0)
        if (pick(rng) < 50 && brute_force(box, {h}).vertices == corners) corner.push_back(h);
    const internal::ClippedPolytope x = internal::clip_polytope(box, corner, nullptr);
    BOOST_TEST((x.outcome == internal::ClippedPolytope::Outcome::polytope), "trial " << trial);
    if (x.outcome == internal::ClippedPolytope::Outcome::polytope) {
      BOOST_TEST((x.set.kind() == ConvexKind3::point));
      BOOST_TEST((x.set.exact().vertices == std::vector<Point3>{box}));
    }
  }
  BOOST_TEST(polytopes > 20);
  BOOST_TEST(held > 300);
}

// The implied rows' ranks compare image channels by their truncated doubles and, where those tie,
// exactly: channels 1 and 1 + 2^-70 (one double, two ranks), equal channels (one rank), and
// channels beyond the double range (2^±300, compared exactly), against the LP route.
BOOST_AUTO_TEST_CASE(implied_rows_rank_channels_that_tie_in_double) {
  Rng rng(4632);
  Tally t;
  mpz_class big = 1;
  mpz_mul_2exp(big.get_mpz_t(), big.get_mpz_t(), 70);
  const R close(big + 1, big);  // 1 + 2^-70
  mpz_class huge = 1;
  mpz_mul_2exp(huge.get_mpz_t(), huge.get_mpz_t(), 300);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Colour> canonical = test::random_colours(rng, 4 + trial % 8, 1, 1000, 64);
    const R unit = trial % 4 == 3 ? R(huge) : trial % 4 == 2 ? R(mpz_class(1), huge) : R(1);
    std::vector<Colour> image;
    for (int i = 0; i < 3 + trial % 5; ++i) {
      const Colour c = random_colour(rng, 3, 1);
      const R base[3] = {R(c.r + 1), R(c.g + 1), R(c.b + 1)};
      image.push_back({R(base[0] * unit), R(base[1] * unit), R(base[2] * unit)});
      // Its twin: one channel 2^-70 relative above (the same truncated double), another equal.
      const int k = i % 3;
      image.push_back({R((k == 0 ? base[0] * close : base[0]) * unit), R((k == 1 ? base[1] * close : base[1]) * unit),
                       R((k == 2 ? base[2] * close : base[2]) * unit)});
    }
    agree(canonical, image, trial % 2 == 0, t);
  }
  BOOST_TEST(t.polytope > 10);
}

// The live-vertex filter's bounding box kept across updates (the largest upper bounds made anew
// only when a removed vertex attained one) answers every box test as a filter rebuilt from the
// same live vertices, on seeded sequences of cuts: removed vertices at the top, added ones above
// it, coordinates at 1 and at 2^±300.
BOOST_AUTO_TEST_CASE(live_vertex_filter_box_after_updates_as_rebuilt) {
  Rng rng(4633);
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_int_distribution<int> coin(0, 3);
  long agreed = 0, inside = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const double scale = trial % 3 == 0 ? 0x1p-300 : trial % 3 == 1 ? 1 : 0x1p300;
    internal::LiveVertexFilter filter;
    std::vector<internal::VertexDoubles> made;
    auto make = [&](double x, double y, double z) {
      internal::VertexDoubles v;
      v.h[0] = x * scale, v.h[1] = y * scale, v.h[2] = z * scale, v.h[3] = 1;
      for (int k = 0; k < 3; ++k) v.err[k] = 0x1p-50 * std::fabs(v.h[k]);
      v.filtered = true;
      v.settle();
      filter.add(v);
      made.push_back(v);
      return static_cast<int>(made.size()) - 1;
    };
    std::vector<int> live;
    for (int i = 0; i < 20; ++i) live.push_back(make(unit(rng), unit(rng), unit(rng)));
    filter.rebuild(live);
    for (int cut = 0; cut < 40; ++cut) {
      std::vector<int> removed, added, kept;
      // Remove the vertices largest in a random coordinate (they attain the box) or random ones.
      const int k = coin(rng) % 3;
      std::sort(live.begin(), live.end(), [&](int a, int b) { return made[a].hi[k] > made[b].hi[k]; });
      for (std::size_t j = 0; j < live.size(); ++j)
        ((j < 2 && cut % 2 == 0) || coin(rng) == 0 ? removed : kept).push_back(live[j]);
      for (int n = 0; n < 1 + coin(rng); ++n) {
        const double grow = cut % 5 == 0 ? 1.5 : 0.9;
        added.push_back(make(grow * unit(rng), grow * unit(rng), grow * unit(rng)));
      }
      live = kept;
      live.insert(live.end(), added.begin(), added.end());
      filter.update(live, removed, added);
      internal::LiveVertexFilter fresh;
      for (const internal::VertexDoubles& v : made) fresh.add(v);
      fresh.rebuild(live);
      for (int q = 0; q < 20; ++q) {
        // Planes a·x <= b near the live vertices' largest values (scaled as filter copies are).
        double a[4] = {unit(rng) - 0.3, unit(rng) - 0.3, unit(rng) - 0.3, 0};
        for (const int v : live) a[3] = std::max(a[3], (a[0] * made[v].h[0] + a[1] * made[v].h[1] + a[2] * made[v].h[2]));
        a[3] *= 0.9 + 0.3 * unit(rng);
        const bool x = filter.box_inside(a), y = fresh.box_inside(a);
        BOOST_TEST(x == y, "trial " << trial << " cut " << cut);
        agreed += x == y, inside += x;
      }
    }
  }
  BOOST_TEST(agreed == 30 * 40 * 20);
  BOOST_TEST(inside > 100);
}

BOOST_AUTO_TEST_SUITE_END()

// ClipFacets::on, whose sides the double filter settles where a point is certainly strictly inside
// (docs/derivations.md §4.6) and exact integers decide otherwise, against every side made exact:
// gamuts of small integers (many points on each facet), Munsell-like rationals, and both scaled
// by 2^±100 (in the filter's range) and 2^±300 (beyond it: every side exact), with extra points
// of the gamut (on facets, on edges, inside) beside its vertices.
BOOST_AUTO_TEST_CASE(clip_facet_incidences_filtered_match_the_exact_sides) {
  Rng rng(4646);
  long on_bits = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Point3> g{{0, 0, 0}};
    for (int i = 0; i < 6 + trial % 25; ++i) {
      const Colour c = random_colour(rng, trial % 2 ? 3 : 1000, trial % 2 ? 1 : 999983);
      g.push_back({c.r, c.g, c.b});
    }
    const int shift = trial % 5 == 0 ? 0 : std::vector<int>{100, -100, 300, -300}[static_cast<std::size_t>(trial % 4)];
    for (Point3& p : g)
      for (int k = 0; k < 3; ++k) {
        Rational& x = coord(p, k);
        if (shift > 0) mpq_mul_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(shift));
        if (shift < 0) mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(-shift));
      }
    g = internal::sorted_unique(std::move(g));
    if (internal::affine_dimension(g) < 3) continue;
    const std::vector<internal::IntegerPlane3> planes = integer_facet_planes(g);
    // The vertices, then midpoints of pairs of them (on edges, facets or inside), then the gamut's points.
    std::vector<Point3> points = internal::extreme_points_3(g);
    const std::size_t nv = points.size();
    for (std::size_t i = 0; i + 1 < nv; i += 2) points.push_back(scale(add(points[i], points[i + 1]), Rational(1, 2)));
    points.insert(points.end(), g.begin(), g.end());
    const internal::ClipFacets f = internal::clip_facets(planes, points);
    BOOST_TEST_REQUIRE(f.on.size() == planes.size());
    for (std::size_t p = 0; p < planes.size(); ++p)
      for (std::size_t j = 0; j < points.size(); ++j) {
        const Rational side = planes[p].a[0] * points[j].x + planes[p].a[1] * points[j].y +
                              planes[p].a[2] * points[j].z - planes[p].b;
        BOOST_TEST(sgn(side) <= 0);
        const bool on = (f.on[p][j / 64] >> (j % 64)) & 1u;
        BOOST_TEST(on == (sgn(side) == 0), "trial " << trial << " plane " << p << " point " << j);
        on_bits += on;
      }
  }
  BOOST_TEST(on_bits > 1000);
}

// The facets and the vertices of one hull (hull_facets_and_vertices_3, what CanonicalConstraints3
// builds from) against hull_half_spaces_3 and extreme_points_3 run apart: rationals, doubles
// (extreme_points_3's fast route), small integer grids with many points on faces and edges.
BOOST_AUTO_TEST_CASE(one_hull_gives_the_facets_and_the_vertices) {
  Rng rng(4647);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Point3> g;
    if (trial % 3 == 0) g.push_back({0, 0, 0});
    for (int i = 0; i < 5 + 7 * (trial % 9); ++i) {
      const Colour c = random_colour(rng, trial % 3 == 1 ? 3 : 1000, trial % 3 == 1 ? 1 : trial % 3 == 2 ? 1024 : 999983);
      g.push_back({c.r, c.g, c.b});
    }
    g = internal::sorted_unique(std::move(g));
    if (internal::affine_dimension(g) < 3) continue;
    const internal::HullFacets3 h = internal::hull_facets_and_vertices_3(g);
    const std::vector<internal::HalfSpace3> apart = internal::hull_half_spaces_3(g);
    BOOST_TEST_REQUIRE(h.half_spaces.size() == apart.size());
    for (std::size_t i = 0; i < apart.size(); ++i)
      BOOST_TEST((h.half_spaces[i].a == apart[i].a && h.half_spaces[i].b == apart[i].b), "trial " << trial);
    BOOST_TEST((h.vertices == internal::extreme_points_3(g)), "trial " << trial);
    ++checked;
  }
  BOOST_TEST(checked > 40);
}

// The final vertices' truncated coordinates with cross products shared between vertices on the
// same two planes (the clip makes a_min × a_max once and negates it for the other order;
// internal/plane_meets.h): on random triples of integer planes — coefficients of 12, 60 and 200
// bits, signed, some planes sharing coefficients so that crosses have zero components — every
// truncation decided from crosses given either way round is that of the exact meet (Cramer's
// rule in integers, truncated exactly), and the same as truncated_meet's own when both decide.
BOOST_AUTO_TEST_CASE(shared_cross_products_give_the_exact_truncations) {
  Rng rng(4653);
  auto coefficient = [&](int bits) {
    mpz_class z = 0;
    for (int b = 0; b < bits; b += 30) z = (z << 30) + static_cast<long>(rng() % (1u << 30));
    z >>= (bits + 29) / 30 * 30 - bits;
    return rng() % 2 ? mpz_class(-z) : z;
  };
  std::size_t decided = 0, trials = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int bits = trial % 3 == 0 ? 12 : trial % 3 == 1 ? 60 : 200;
    std::array<internal::IntegerPlane3, 3> pl;
    for (internal::IntegerPlane3& p : pl) {
      for (mpz_class& a : p.a) a = coefficient(bits);
      p.b = coefficient(bits);
    }
    if (trial % 5 == 0) pl[1].a[0] = pl[0].a[0], pl[1].a[1] = pl[0].a[1];  // a cross with a zero component
    std::array<std::array<mpz_class, 3>, 3> scratch;
    std::array<mpz_class, 4> h;
    internal::homogeneous_meet(pl[0], pl[1], pl[2], scratch, h);
    if (sgn(h[3]) == 0) continue;
    if (sgn(h[3]) < 0)
      for (mpz_class& c : h) c = -c;
    std::array<std::optional<double>, 3> exact;
    for (std::size_t k = 0; k < 3; ++k) exact[k] = numerics::truncated_double(h[k].get_mpz_t(), h[3].get_mpz_t());
    std::array<std::optional<internal::WidePlane>, 3> w;
    for (std::size_t i = 0; i < 3; ++i) w[i] = internal::wide_plane(pl[i]);
    if (!w[0] || !w[1] || !w[2]) continue;
    const internal::WidePlane &p = *w[0], &q = *w[1], &r = *w[2];
    auto cross = [&](const internal::WidePlane& s, const internal::WidePlane& u, bool swap) {
      return swap ? internal::negated(internal::wide_cross(u, s)) : internal::wide_cross(s, u);
    };
    const std::array<bool, 3> none{};
    const auto own = internal::truncated_meet(p, q, r, none);
    ++trials;
    for (int way = 0; way < 8; ++way) {
      const auto t = internal::truncated_meet(p, q, r, cross(q, r, way & 1), cross(r, p, way & 2), cross(p, q, way & 4), none);
      if (!t) continue;
      decided += way == 7;
      for (std::size_t k = 0; k < 3; ++k)
        BOOST_TEST((exact[k] && t->truncated[k] == *exact[k]), "trial " << trial << " way " << way << " k " << k);
      if (own) BOOST_TEST((own->truncated == t->truncated), "trial " << trial << " way " << way);
    }
  }
  BOOST_TEST(trials > 2500);
  BOOST_TEST(decided > trials * 9 / 10);
}
