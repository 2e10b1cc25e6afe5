// F3 kept symbolic (issue 28 item 3; lazy_convex_set_3.h): the clip's LazyConvexSet3, whose
// vertices are made exact only when an exact stage asks, against the exact ConvexSet3 of the LP
// route (test::feasible_set_3d_reference in tests/support, the oracle): the same set (exact() equal), the same
// enclosures bit for bit, and every 3-D rule's answer the same map, bound and method — max-volume
// (against its exact stage over every candidate), max-trace and the worst cases (against oracles
// written here over every vertex in ℚ), the centroid on both routes — on hundreds of seeded
// scenes of every kind (polytopes with and without black, shaded and with highlights; planar and
// collinear gamuts giving polygons, segments and points; empty F3). Also: the lazy route makes
// only a few vertices exact, from_homogeneous accepts any scaling and sign of the homogeneous
// coordinates and magnitudes at the double range policy's edge, from_truncated (vertices known by
// their truncated coordinates, made on request) gives the same set, and estimate_3d answers the same
// with or without the exact F3.
#include "../test_support.h"
#include "crule_oracles.h"

#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/geometry/lazy_convex_set_3.h>
#include <gmcc/selection/centroid_3.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_trace.h>
#include <gmcc/selection/max_volume.h>

#include "internal/crule_exact.h"
#include "internal/max_volume_route.h"
#include "support/cgal_references.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <numeric>

using namespace gmcc;
using gmcc::test::Rng;
using gmcc::test::same_estimate;
using gmcc::test::worst_case_oracle;
using R = Rational;

namespace {

void same_enclosures(const LazyConvexSet3& L, const ConvexSet3& E) {
  BOOST_TEST_REQUIRE(L.size() == E.vertices.size());
  for (std::size_t i = 0; i < L.size(); ++i) {
    const Enclosure3 want = enclose_point(E.vertices[i]);
    for (std::size_t k = 0; k < 3; ++k) {
      BOOST_TEST(L.enclosures()[i][k].mid == want[k].mid);
      BOOST_TEST(L.enclosures()[i][k].rad == want[k].rad);
    }
    BOOST_TEST(L.is_zero(i) == is_zero(E.vertices[i]));
  }
}

// The oracles: the first vertex of largest trace, the first non-zero vertex of least cos², in ℚ.
MapEstimate3 max_trace_oracle(const ConvexSet3& F) {
  const Point3* best = &F.vertices.front();
  for (const Point3& v : F.vertices)
    if (R(v.x + v.y + v.z) > R(best->x + best->y + best->z)) best = &v;
  return exact_map_estimate_3("max_trace", *best);
}

struct Tally {
  int polytope = 0, polygon = 0, segment = 0, point = 0, empty = 0;
  std::size_t vertices = 0, made = 0;  // over the polytopes: all, and made exact by the rules
};

// Every rule on a fresh lazy F3 (nothing exact yet) against the exact set E.
void agree(const std::vector<GamutConstraint3>& g, const ConvexSet3& E, Rng& rng, Tally& t) {
  const LazyConvexSet3 L = feasible_set_3d_lazy(g);
  BOOST_TEST((L.kind() == E.kind));
  same_enclosures(L, E);
  BOOST_TEST(L.faces() == E.faces);
  switch (E.kind) {
    case ConvexKind3::polytope: ++t.polytope; break;
    case ConvexKind3::polygon: ++t.polygon; break;
    case ConvexKind3::segment: ++t.segment; break;
    case ConvexKind3::point: ++t.point; break;
    case ConvexKind3::empty: ++t.empty; return;
  }
  const MapEstimate3 mv = max_volume(L);
  same_estimate(mv, internal::max_volume_over(E, internal::all_max_volume_candidates(E)));
  same_estimate(max_trace(L), max_trace_oracle(E));
  same_estimate(centroid_3(L, Crule3dRoute::certified), centroid_3(E, Crule3dRoute::certified));
  bool nonzero = false;
  for (const Point3& v : E.vertices) nonzero = nonzero || !is_zero(v);
  if (nonzero)
    for (const Point3& m : {measured_map(mv), test::random_point3(rng, 1, 9, 7), E.vertices.back()})
      if (!is_zero(m)) BOOST_TEST(worst_case_map_deg_3d(L, m) == worst_case_oracle(E, m));
  if (E.kind == ConvexKind3::polytope) t.vertices += L.size(), t.made += L.exact_vertices();
  // Asked for, the whole set is the oracle's; the exact centroid needs it all.
  BOOST_TEST((L.exact() == E));
  same_estimate(centroid_3(L, Crule3dRoute::exact), centroid_3(E, Crule3dRoute::exact));
}

void agree(const std::vector<Colour>& canonical, const std::vector<Colour>& image, CanonicalBlack black, Rng& rng,
           Tally& t) {
  const CanonicalConstraints3 G(canonical, black);
  const ConvexSet3 E = test::feasible_set_3d_reference(canonical, image, black);
  agree({{&G, &image}}, E, rng, t);
}

Colour random_colour(Rng& rng, long hi, long den) {
  return {test::random_rational(rng, 1, hi, den), test::random_rational(rng, 1, hi, den),
          test::random_rational(rng, 1, hi, den)};
}

// `surfaces` under the light 1/d, each shaded, some with a highlight.
std::vector<Colour> image_of(const std::vector<Colour>& surfaces, Rng& rng, int n, int trial) {
  const Point3 d = test::random_point3(rng, 1, 5, 4);
  std::vector<Colour> image;
  for (int i = 0; i < n; ++i) {
    Colour c = test::divided(surfaces[static_cast<std::size_t>(rng() % surfaces.size())], d);
    const R shade = trial % 3 == 0 ? test::random_rational(rng, 3, 10, 1) / 10 : R(1);
    const R highlight = trial % 5 == 0 ? test::random_rational(rng, 0, 3, 7) : R(0);
    for (R* x : {&c.r, &c.g, &c.b}) *x = *x * shade + highlight;
    image.push_back(c);
  }
  return image;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(crule_lazy)

BOOST_AUTO_TEST_CASE(polytopes_answer_as_the_exact_set) {
  Rng rng(28003);
  Tally t;
  for (int trial = 0; trial < 160; ++trial) {
    std::vector<Colour> canonical;
    for (int i = 0; i < 8 + trial % 30; ++i) canonical.push_back(random_colour(rng, 40, 1 + trial % 9));
    const CanonicalBlack black = trial % 2 ? CanonicalBlack::include : CanonicalBlack::exclude;
    agree(canonical, image_of(canonical, rng, 1 + trial % 13, trial), black, rng, t);
  }
  BOOST_TEST(t.polytope > 60);
  BOOST_TEST(t.empty > 0);
  // The rules and worst cases made few of the polytopes' vertices exact.
  BOOST_TEST(2 * t.made < t.vertices);
}

BOOST_AUTO_TEST_CASE(degenerate_kinds_answer_as_the_exact_set) {
  Rng rng(28004);
  Tally t;
  for (int trial = 0; trial < 90; ++trial) {
    std::vector<Colour> canonical;
    const Colour a = random_colour(rng, 30, 5), b = random_colour(rng, 30, 5);
    const int n = 3 + trial % 6;
    for (int i = 0; i < n; ++i) {
      // Planar (a, b and the origin's plane), collinear (along a) or a single colour.
      const R s = test::random_rational(rng, 1, 9, 4), u = test::random_rational(rng, 0, 9, 4);
      Colour c = trial % 3 == 0   ? Colour{R(s * a.r + u * b.r), R(s * a.g + u * b.g), R(s * a.b + u * b.b)}
                 : trial % 3 == 1 ? Colour{R(s * a.r), R(s * a.g), R(s * a.b)}
                                  : a;
      canonical.push_back(c);
    }
    const CanonicalBlack black = trial % 2 ? CanonicalBlack::include : CanonicalBlack::exclude;
    std::vector<Colour> image = image_of(canonical, rng, 1 + trial % 4, trial);
    if (trial % 7 == 0) image.push_back(random_colour(rng, 60, 3));  // often no map at all
    agree(canonical, image, black, rng, t);
  }
  BOOST_TEST(t.polygon > 5);
  BOOST_TEST(t.segment > 5);
  BOOST_TEST(t.point + t.empty > 5);
}

BOOST_AUTO_TEST_CASE(joint_constraints_answer_as_the_exact_set) {
  Rng rng(28005);
  Tally t;
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<Colour> c1, c2;
    for (int i = 0; i < 10 + trial % 10; ++i) c1.push_back(random_colour(rng, 40, 3)), c2.push_back(random_colour(rng, 40, 3));
    const CanonicalConstraints3 G1(c1), G2(c2);
    const std::vector<Colour> i1 = image_of(c1, rng, 4, trial), i2 = image_of(c2, rng, 3, trial);
    const ConvexSet3 E = feasible_set_3d(std::vector<GamutConstraint3>{{&G1, &i1}, {&G2, &i2}});
    agree({{&G1, &i1}, {&G2, &i2}}, E, rng, t);
  }
  BOOST_TEST(t.polytope > 3);
}

BOOST_AUTO_TEST_CASE(homogeneous_coordinates_in_any_scale_and_order) {
  Rng rng(28006);
  std::vector<Colour> canonical;
  for (int i = 0; i < 30; ++i) canonical.push_back(random_colour(rng, 40, 7));
  const ConvexSet3 F = feasible_set_3d(canonical, {{1, 1, 1}});
  BOOST_TEST_REQUIRE((F.kind == ConvexKind3::polytope));
  // Scaled by 2^e, e at and around the double range policy's limit (138): each side of it, and
  // the band where a fraction not in lowest terms must be reduced first.
  for (long e : {0L, 100L, 136L, 137L, 138L, 139L, 140L, 141L, 150L, -100L, -136L, -137L, -138L, -139L, -140L, -141L, -150L}) {
    const R s = e >= 0 ? R(mpz_class(1) << e) : R(1, mpz_class(1) << -e);
    std::vector<Point3> v;
    for (const Point3& p : F.vertices) v.push_back({R(p.x * s), R(p.y * s), R(p.z * s)});
    const ConvexSet3 E = canonical_convex_set_3(F.kind, v, F.faces);
    // Shuffled, each vertex as (X, Y, Z, W) times a random factor of either sign.
    std::vector<std::size_t> order(v.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::size_t> rank(v.size());
    std::vector<std::array<mpz_class, 4>> h;
    for (std::size_t i = 0; i < order.size(); ++i) {
      rank[order[i]] = i;
      const Point3& p = E.vertices[order[i]];
      const mpz_class w = lcm(lcm(p.x.get_den(), p.y.get_den()), p.z.get_den());
      const mpz_class g = mpz_class(1 + rng() % 1000) * (rng() % 2 ? 1 : -1);
      h.push_back({mpz_class(R(p.x * w)) * g, mpz_class(R(p.y * w)) * g, mpz_class(R(p.z * w)) * g, mpz_class(w * g)});
    }
    std::vector<std::vector<std::size_t>> faces = E.faces;
    for (auto& f : faces)
      for (std::size_t& i : f) i = rank[i];
    const LazyConvexSet3 L = LazyConvexSet3::from_homogeneous(E.kind, std::move(h), std::move(faces));
    same_enclosures(L, E);
    BOOST_TEST(L.exact_vertices() == 0u);
    BOOST_TEST((L.exact() == E));
    BOOST_TEST(L.exact_vertices() == L.size());
  }
}

// from_truncated (the clip's symbolic vertices) against from_homogeneous: vertices given by their
// coordinates' truncated doubles (mpq_get_d, independently of the library) and a maker of their
// homogeneous coordinates give the same set, order, enclosures and faces; the maker runs only for
// vertices whose truncated doubles tie with another's (none on a generic polytope; on a box,
// whose vertices share coordinates, some), and for every vertex once the whole set is asked for.
BOOST_AUTO_TEST_CASE(truncated_vertices_made_on_request) {
  Rng rng(28007);
  std::vector<Colour> generic;
  for (int i = 0; i < 30; ++i) generic.push_back(random_colour(rng, 1000000, 999983));  // no shared coordinate
  const std::vector<Colour> box{{0, 0, 0}, {R(1, 3), 0, 0}, {0, 2, 0}, {0, 0, R(5, 7)}, {R(1, 3), 2, 0},
                                {R(1, 3), 0, R(5, 7)}, {0, 2, R(5, 7)}, {R(1, 3), 2, R(5, 7)}};
  for (const std::vector<Colour>* canonical : {static_cast<const std::vector<Colour>*>(&generic), &box}) {
    const ConvexSet3 E = feasible_set_3d(*canonical, {{1, 1, 1}});
    BOOST_TEST_REQUIRE((E.kind == ConvexKind3::polytope));
    std::vector<std::size_t> order(E.vertices.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::size_t> rank(order.size());
    std::vector<LazyConvexSet3::TruncatedVertex> vertices;
    std::vector<std::array<mpz_class, 4>> h;
    for (std::size_t i = 0; i < order.size(); ++i) {
      rank[order[i]] = i;
      const Point3& p = E.vertices[order[i]];
      vertices.push_back({{mpq_get_d(p.x.get_mpq_t()), mpq_get_d(p.y.get_mpq_t()), mpq_get_d(p.z.get_mpq_t())}, is_zero(p)});
      const mpz_class w = lcm(lcm(p.x.get_den(), p.y.get_den()), p.z.get_den());
      const mpz_class g = mpz_class(1 + rng() % 1000) * (rng() % 2 ? 1 : -1);  // any scale and sign
      h.push_back({mpz_class(R(p.x * w)) * g, mpz_class(R(p.y * w)) * g, mpz_class(R(p.z * w)) * g, mpz_class(w * g)});
    }
    std::vector<std::vector<std::size_t>> faces = E.faces;
    for (auto& f : faces)
      for (std::size_t& i : f) i = rank[i];
    auto made = std::make_shared<std::vector<int>>(h.size(), 0);
    const LazyConvexSet3 L = LazyConvexSet3::from_truncated(E.kind, vertices, faces, [h, made](std::size_t i) {
      ++(*made)[i];
      return h[i];
    });
    same_enclosures(L, E);
    BOOST_TEST((L.faces() == E.faces));
    int during = 0;
    for (int m : *made) during += m > 0;
    if (canonical == &generic) BOOST_TEST(during == 0);
    else BOOST_TEST(during > 0);  // ties broken exactly
    BOOST_TEST((L.exact() == E));
    for (int m : *made) BOOST_TEST(m == 1);  // each vertex made once, then kept
  }
}

// homogeneous(i) and facet_plane(k) against the exact vertices, on a clipped F3 (homogeneous as
// the clip made them) and on the same set made exact (homogeneous made on request): (X, Y, Z)/W is
// the vertex, W > 0; the plane is a positive multiple of ((b − a) × (c − a), ·a) for the facet's
// first three vertices, holds with equality on the facet's vertices and strictly on the others.
BOOST_AUTO_TEST_CASE(homogeneous_vertices_and_integer_facet_planes) {
  Rng rng(28026);
  int polytopes = 0;
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<Colour> canonical;
    for (int i = 0; i < 8 + trial % 20; ++i) canonical.push_back(random_colour(rng, 60, trial % 2 ? 7 : 997));
    const std::vector<Colour> image = image_of(canonical, rng, 1 + trial % 6, trial);
    const CanonicalConstraints3 G(canonical);
    const LazyConvexSet3 clipped = feasible_set_3d_lazy({{&G, &image}});
    if (clipped.kind() != ConvexKind3::polytope) continue;
    ++polytopes;
    const LazyConvexSet3 exact(clipped.exact());
    for (const LazyConvexSet3* L : {&clipped, &exact}) {
      for (std::size_t i = 0; i < L->size(); ++i) {
        const auto& h = L->homogeneous(i);
        BOOST_TEST(sgn(h[3]) > 0);
        Point3 q{R(h[0], h[3]), R(h[1], h[3]), R(h[2], h[3])};
        q.x.canonicalize(), q.y.canonicalize(), q.z.canonicalize();
        BOOST_TEST((q == L->vertex(i)));
      }
      for (std::size_t k = 0; k < L->faces().size(); ++k) {
        const auto& f = L->faces()[k];
        const auto [n, c] = L->facet_plane(k);
        const Point3 &a = L->vertex(f[0]), &b = L->vertex(f[1]), &d = L->vertex(f[2]);
        const Point3 m{R(b.x - a.x), R(b.y - a.y), R(b.z - a.z)}, o{R(d.x - a.x), R(d.y - a.y), R(d.z - a.z)};
        const Point3 want{R(m.y * o.z - m.z * o.y), R(m.z * o.x - m.x * o.z), R(m.x * o.y - m.y * o.x)};
        const R scale = sgn(want.x) ? R(R(n[0]) / want.x) : sgn(want.y) ? R(R(n[1]) / want.y) : R(R(n[2]) / want.z);
        BOOST_TEST(sgn(scale) > 0);
        BOOST_TEST((Point3{R(want.x * scale), R(want.y * scale), R(want.z * scale)} == Point3{R(n[0]), R(n[1]), R(n[2])}));
        const Point3 np{R(n[0]), R(n[1]), R(n[2])};
        BOOST_TEST(dot(np, a) == R(c));
        for (std::size_t i = 0; i < L->size(); ++i) {
          const bool on = std::find(f.begin(), f.end(), i) != f.end();
          BOOST_TEST((on ? dot(np, L->vertex(i)) == R(c) : dot(np, L->vertex(i)) < R(c)));
        }
      }
    }
  }
  BOOST_TEST(polytopes >= 10);
}

// Max-volume's exact stage compares values as unreduced fractions and breaks ties by vertex index
// (the canonical order is the lexicographic one): on convex polygons in the plane d3 = 0 every
// candidate's value is 0, so every vertex ties and the least vertex must win, on the lazy form
// (homogeneous coordinates scaled by random factors of either sign) as on the exact set.
BOOST_AUTO_TEST_CASE(max_volume_ties_go_to_the_least_vertex) {
  Rng rng(28003);
  for (int trial = 0; trial < 20; ++trial) {
    // A convex polygon: points on the parabola y = x² (x = 1..n, scaled), z = 0, in a random order.
    const int n = 3 + trial % 5;
    R scale(1 + static_cast<long>(rng() % 50), 1 + static_cast<long>(rng() % 50));
    scale.canonicalize();
    std::vector<std::size_t> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::array<mpz_class, 4>> h;
    std::vector<Point3> points;
    for (std::size_t i : order) {
      const long x = static_cast<long>(i) + 1;
      points.push_back({R(x * scale), R(x * x * scale), R(0)});
      const mpz_class g = mpz_class(1 + rng() % 1000) * (rng() % 2 ? 1 : -1);
      const mpz_class w = scale.get_den() * g;
      h.push_back({mpz_class(x * scale.get_num() * g), mpz_class(x * x * scale.get_num() * g), 0, w});
    }
    std::vector<std::size_t> cycle(static_cast<std::size_t>(n));  // the hull's order: by x
    for (std::size_t k = 0; k < order.size(); ++k) cycle[order[k]] = k;
    const LazyConvexSet3 L = LazyConvexSet3::from_homogeneous(ConvexKind3::polygon, std::move(h), {cycle});
    const MapEstimate3 lazy = max_volume(L);
    BOOST_TEST(L.exact_vertices() == 1u);  // only the winner made exact
    const ConvexSet3 E = L.exact();
    BOOST_REQUIRE(lazy.exact.has_value());
    BOOST_TEST((*lazy.exact == *std::min_element(points.begin(), points.end())));
    BOOST_TEST((*lazy.exact == E.vertices.front()));
    same_estimate(lazy, max_volume(E));
  }
}

BOOST_AUTO_TEST_SUITE_END()
