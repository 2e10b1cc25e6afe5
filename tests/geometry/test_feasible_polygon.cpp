// The symbolic feasible set and its certified enclosures (feasible_polygon.h, enclosure.h):
// exactness against the unfiltered reference clipper, enclosures that contain the exact
// vertices in order, exact membership, and midpoint–radius arithmetic that encloses exact results.
#include "../test_support.h"
#include "feasible_set_reference.h"

#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/intersection.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <functional>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
Rational exact(double x) { return rational_from_double(x); }
bool encloses(const Enclosure& e, const Rational& x) { return exact(e.lo()) <= x && x <= exact(e.hi()); }
// A long double as an exact rational: its 64-bit significand and exponent.
Rational exact_long(long double x) {
  int e = 0;
  const long double m = std::frexp(x, &e);  // x = m·2^e, |m| in [0.5, 1): m = k/2^64 exactly
  const auto k = static_cast<unsigned long long>(std::ldexp(std::fabs(m), 64));
  Rational r(mpz_class(std::to_string(k)));
  if (e - 64 >= 0) r *= Rational(mpz_class(1) << static_cast<unsigned>(e - 64));
  else r /= Rational(mpz_class(1) << static_cast<unsigned>(64 - e));
  return x < 0 ? Rational(-r) : r;
}
bool encloses_long(const LongEnclosure& e, const Rational& x) { return exact_long(e.lo()) <= x && x <= exact_long(e.hi()); }

// A random double in ±[2^-8, 2^8], and a random enclosure around it (radius 0 or up to 2^-20 of it).
double random_double(Rng& rng) {
  std::uniform_real_distribution<double> mant(0.5, 1);
  std::uniform_int_distribution<int> ex(-8, 8), sign(0, 1);
  return std::ldexp(mant(rng), ex(rng)) * (sign(rng) ? -1 : 1);
}
Enclosure random_enclosure(Rng& rng) {
  const double m = random_double(rng);
  std::uniform_int_distribution<int> kind(0, 2);
  const int k = kind(rng);
  return {m, k == 0 ? 0.0 : std::fabs(m) * std::ldexp(std::uniform_real_distribution<double>(0, 1)(rng), k == 1 ? -50 : -20)};
}
// A member of e: its ends, its midpoint or a random rational between.
Rational member(Rng& rng, const Enclosure& e) {
  const Rational m = exact(e.mid), r = exact(e.rad);
  switch (std::uniform_int_distribution<int>(0, 3)(rng)) {
    case 0: return Rational(m - r);
    case 1: return Rational(m + r);
    case 2: return m;
    default: return Rational(m + r * test::random_rational(rng, -1000, 1000, 1) / 1000);
  }
}
}  // namespace

BOOST_AUTO_TEST_SUITE(feasible_polygon_and_enclosures)

// Every operation encloses the exact result of the operation on any members of its operands.
BOOST_AUTO_TEST_CASE(midpoint_radius_operations_enclose_exact_results) {
  Rng rng(36);
  for (int trial = 0; trial < 20000; ++trial) {
    const Enclosure a = random_enclosure(rng), b = random_enclosure(rng);
    const Rational x = member(rng, a), y = member(rng, b);
    BOOST_TEST(encloses(a + b, Rational(x + y)));
    BOOST_TEST(encloses(a - b, Rational(x - y)));
    BOOST_TEST(encloses(a * b, Rational(x * y)));
    BOOST_TEST(encloses(a / b, Rational(x / y)));
    BOOST_TEST(encloses(-a, Rational(-x)));
    // √: lo² <= x <= hi² for x >= 0.
    const Enclosure pa{std::fabs(a.mid), a.rad};
    const Rational px = abs(member(rng, pa));
    const Enclosure s = sqrt(pa);
    BOOST_TEST((std::max(0.0, s.lo()) * 1.0 >= 0));
    BOOST_TEST(exact(std::max(0.0, s.lo())) * exact(std::max(0.0, s.lo())) <= px);
    BOOST_TEST(exact(s.hi()) * exact(s.hi()) >= px);
  }
  // Long chains keep enclosing (radii grow, never miss): a random expression of 30 steps.
  for (int trial = 0; trial < 500; ++trial) {
    Enclosure e = random_enclosure(rng);
    Rational x = member(rng, e);
    for (int step = 0; step < 30; ++step) {
      const Enclosure b = random_enclosure(rng);
      const Rational y = member(rng, b);
      switch (step % 4) {
        case 0: e = e + b, x += y; break;
        case 1: e = e * b, x *= y; break;
        case 2: e = e - b, x -= y; break;
        default: e = e / b, x /= y; break;
      }
      BOOST_TEST(encloses(e, x));
    }
  }
  // Division by an enclosure of 0 is unbounded, never a wrong finite answer.
  BOOST_TEST(std::isinf((Enclosure::exact(1) / Enclosure{0, 1e-300}).rad));
  BOOST_TEST(Enclosure::between(1, 2).lo() <= 1);
  BOOST_TEST(Enclosure::between(1, 2).hi() >= 2);
}

namespace {
// The checks every scene gets: the exact set equals the reference; when enclosed, the
// enclosures contain the exact vertices in counter-clockwise order, the edges' normals have the
// exact signs, and membership agrees with the exact set on vertices, edge midpoints and random maps.
ConvexKind check_scene(Rng& rng, const ConvexSet2& G, const std::vector<Point2>& image, int& enclosed) {
  const FeasiblePolygon P = feasible_polygon(CanonicalConstraints(G), image);
  const ConvexSet2& F = P.exact();
  BOOST_TEST(F == test::reference::feasible_set_reference(G, image));
  BOOST_TEST(P.kind() == F.kind);
  BOOST_TEST(P.enclosed() == !P.vertices().empty());
  if (P.enclosed()) {
    ++enclosed;
    BOOST_TEST(F.kind == ConvexKind::polygon);
    const std::size_t n = F.vertices.size();
    BOOST_REQUIRE(P.vertices().size() == n);
    BOOST_REQUIRE(P.edges().size() == n);
    std::size_t start = n;
    for (std::size_t j = 0; j < n && start == n; ++j)
      if (encloses(P.vertices()[0].x, F.vertices[j].x) && encloses(P.vertices()[0].y, F.vertices[j].y)) start = j;
    BOOST_REQUIRE(start < n);
    for (std::size_t i = 0; i < n; ++i) {
      const Point2& v = F.vertices[(start + i) % n];
      const Point2& w = F.vertices[(start + i + 1) % n];
      BOOST_TEST(encloses(P.vertices()[i].x, v.x));
      BOOST_TEST(encloses(P.vertices()[i].y, v.y));
      const ApproximateLine& l = P.edges()[i];  // outward normal of the CCW edge v → w
      BOOST_TEST((l.a > 0) - (l.a < 0) == sgn(Rational(w.y - v.y)));
      BOOST_TEST((l.b > 0) - (l.b < 0) == sgn(Rational(v.x - w.x)));
    }
    // The extended-precision enclosures (x87 platforms): the same vertices, in the same order.
    const auto& ext = P.extended_vertices();
    if (!ext.empty()) {
      BOOST_REQUIRE(ext.size() == n);
      for (std::size_t i = 0; i < n; ++i) {
        const Point2& v = F.vertices[(start + i) % n];
        BOOST_TEST(encloses_long(ext[i].x, v.x));
        BOOST_TEST(encloses_long(ext[i].y, v.y));
        BOOST_TEST(ext[i].x.rad <= 0x1p-60L * std::fabs(ext[i].x.mid) + 1e-300L);
      }
    }
  }
  std::vector<Point2> probes = F.vertices;
  for (std::size_t i = 0; i < F.vertices.size(); ++i) {
    const Point2& v = F.vertices[i];
    const Point2& w = F.vertices[(i + 1) % F.vertices.size()];
    probes.push_back({Rational((v.x + w.x) / 2), Rational((v.y + w.y) / 2)});
  }
  for (int s = 0; s < 20; ++s) probes.push_back(test::random_points(rng, 1, 0, 4, 7)[0]);
  for (const Point2& m : probes) BOOST_TEST(P.contains(m) == contains(F, m), m);
  return F.kind;
}
}  // namespace

// Random scenes (the true map in F), grids with repeated and collinear vertices (every kind),
// degenerate canonical gamuts (the box start) and image colours with a zero channel.
BOOST_AUTO_TEST_CASE(symbolic_feasible_set_is_exact_and_its_enclosures_contain_it) {
  Rng rng(1996);
  int enclosed = 0, kinds[4] = {};
  for (int trial = 0; trial < 600; ++trial) {
    const bool grid = trial % 2;
    const auto pts = test::random_points(rng, grid ? 1 + trial % 9 : 3 + trial % 20, 1, 4, grid ? 2 + trial % 3 : 50);
    const ConvexSet2 G = convex_hull(pts);
    const Point2 d{test::random_rational(rng, 1, 6, grid ? 2 : 40), test::random_rational(rng, 1, 6, grid ? 2 : 40)};
    std::vector<Point2> image;
    for (int i = 0; i < 1 + trial % 7; ++i) {
      const Point2& p = pts[std::uniform_int_distribution<std::size_t>(0, pts.size() - 1)(rng)];
      image.push_back(trial % 3 ? Point2{Rational(p.x / d.x), Rational(p.y / d.y)} : test::random_points(rng, 1, 1, 4, 2)[0]);
    }
    if (trial % 11 == 0) image.push_back({0, Rational(1, 2)});  // a zero channel
    const ConvexKind k = check_scene(rng, G, image, enclosed);
    if (G.kind == ConvexKind::polygon) ++kinds[static_cast<int>(k)];
  }
  // Segments and points from a polygonal G_c: a square [1, 2]² scaled by (s, t), with images
  // whose feasible sets touch along an edge ({(1,1), (2,1)}) or at a corner (and (1,2)).
  for (int trial = 0; trial < 40; ++trial) {
    const Rational sx = test::random_rational(rng, 1, 9, 7), sy = test::random_rational(rng, 1, 9, 7);
    const ConvexSet2 G = convex_hull({{sx, sy}, {Rational(2 * sx), sy}, {Rational(2 * sx), Rational(2 * sy)}, {sx, Rational(2 * sy)}});
    std::vector<Point2> image{{1, 1}, {2, 1}};
    if (trial % 2) image.push_back({1, 2});
    const ConvexKind k = check_scene(rng, G, image, enclosed);
    BOOST_TEST((k == (trial % 2 ? ConvexKind::point : ConvexKind::segment)));
    ++kinds[static_cast<int>(k)];
  }
  BOOST_TEST(enclosed > 150);  // the fast description is the common case
  for (int k = 0; k < 4; ++k) BOOST_TEST(kinds[k] > 5, "kind " << k << ": " << kinds[k]);  // G_c a polygon: every kind of F
}

// A map constraint C carried by CanonicalConstraints gives F ∩ C in the same clipping: equal to
// intersection(F, C) for polygons, segments, points and empty constraints, and its enclosures
// and membership are those of the smaller set.
BOOST_AUTO_TEST_CASE(map_constraint_gives_the_intersection) {
  Rng rng(1996 * 2);
  int enclosed = 0, kinds[4] = {};
  for (int trial = 0; trial < 300; ++trial) {
    const auto pts = test::random_points(rng, 3 + trial % 15, 1, 4, 2 + trial % 40);
    const ConvexSet2 G = convex_hull(pts);
    const Point2 d{test::random_rational(rng, 1, 6, 20), test::random_rational(rng, 1, 6, 20)};
    std::vector<Point2> image;
    for (int i = 0; i < 1 + trial % 5; ++i) {
      const Point2& p = pts[std::uniform_int_distribution<std::size_t>(0, pts.size() - 1)(rng)];
      image.push_back({Rational(p.x / d.x), Rational(p.y / d.y)});
    }
    // C: random hulls of 1–6 points around the true map (so F ∩ C is often neither F nor C).
    std::vector<Point2> c;
    for (int i = 0; i < 1 + trial % 6; ++i)
      c.push_back({Rational(d.x + test::random_rational(rng, -8, 8, 9) / 4), Rational(d.y + test::random_rational(rng, -8, 8, 9) / 4)});
    const ConvexSet2 C = trial % 17 == 0 ? ConvexSet2{} : convex_hull(c);
    const FeasiblePolygon P = feasible_polygon(CanonicalConstraints(G, C), image);
    const ConvexSet2 expected = intersection(feasible_set(G, image), C);
    BOOST_TEST(P.exact() == expected);
    BOOST_TEST(P.kind() == expected.kind);
    ++kinds[static_cast<int>(expected.kind)];
    if (P.enclosed()) {
      ++enclosed;
      for (const Point2& v : expected.vertices) {
        bool found = false;
        for (const EnclosedVertex& e : P.vertices()) found = found || (encloses(e.x, v.x) && encloses(e.y, v.y));
        BOOST_TEST(found);
      }
    }
    for (int s = 0; s < 10; ++s) {
      const Point2 m{Rational(d.x + test::random_rational(rng, -8, 8, 9) / 4), Rational(d.y + test::random_rational(rng, -8, 8, 9) / 4)};
      BOOST_TEST(P.contains(m) == contains(expected, m));
    }
  }
  BOOST_TEST(enclosed > 50);
  for (int k = 0; k < 4; ++k) BOOST_TEST(kinds[k] > 3, "kind " << k << ": " << kinds[k]);
}

// Found in review: a G_c given with a collinear (or repeated) vertex, not in canonical form, has
// consecutive parallel edges with no meet; the clipping must not start from them.
BOOST_AUTO_TEST_CASE(non_canonical_canonical_gamut_and_the_default_object) {
  Rng rng(4);
  int enclosed = 0;
  const ConvexSet2 collinear{ConvexKind::polygon, {{1, 1}, {2, 1}, {3, 1}, {3, 3}, {1, 3}}};
  const ConvexSet2 repeated{ConvexKind::polygon, {{1, 1}, {3, 1}, {3, 1}, {3, 3}, {1, 3}}};
  for (const ConvexSet2& G : {collinear, repeated})
    for (const std::vector<Point2>& image : {std::vector<Point2>{{1, 1}}, std::vector<Point2>{{1, 1}, {Rational(3, 2), 1}}}) {
      const FeasiblePolygon P = feasible_polygon(CanonicalConstraints(G), image);
      BOOST_TEST(P.exact() == test::reference::feasible_set_reference(G, image));
      check_scene(rng, G, image, enclosed);
    }
  const FeasiblePolygon none;
  BOOST_TEST(none.kind() == ConvexKind::empty);
  BOOST_TEST(!none.enclosed());
  BOOST_TEST(!none.contains({1, 1}));
  BOOST_TEST(none.exact() == ConvexSet2{});
}

BOOST_AUTO_TEST_SUITE_END()
