// The convex pass of feasible_polygon (issue 13: near-linear clipping of a strictly convex cycle
// by a convex polygon's edges, docs/performance-history.md) against the Sutherland–Hodgman route it
// replaced, on seeded scenes: many-vertex canonical gamuts on convex curves, random small ones,
// degenerate ones (segments, points, image colours with a zero channel, coincident colours,
// F a segment, a point or empty), with and without a map constraint. Both routes must give the
// same exact set, kind and enclosed description.
#include "../test_support.h"
#include "feasible_set_reference.h"

#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/intersection.h>

#include "internal/feasible_polygon_route.h"

#include <boost/test/unit_test.hpp>

#include <optional>
#include <string>

using namespace gmcc;
using gmcc::test::Rng;

namespace {

Rational exact(double x) { return rational_from_double(x); }
bool encloses(const Enclosure& e, const Rational& x) { return exact(e.lo()) <= x && x <= exact(e.hi()); }

// n points (x0 + s·t, y0 + s·t²), t = i/n: every one a vertex of their hull.
std::vector<Point2> parabola(int n, const Rational& x0, const Rational& y0, const Rational& s) {
  std::vector<Point2> p;
  for (int i = 0; i < n; ++i) {
    const Rational t(i, n);
    p.push_back({Rational(x0 + s * t), Rational(y0 + s * t * t)});
  }
  return p;
}
// n rational points on the circle of centre c and radius r: ((1 − t²)/(1 + t²), 2t/(1 + t²)) for
// t = k/d, k = −2d … 2d − 1 (most of the circle, denser on one side).
std::vector<Point2> circle(int n, const Point2& c, const Rational& r) {
  std::vector<Point2> p;
  const int d = std::max(1, n / 4);
  for (int k = -2 * d; k < 2 * d; ++k) {
    const Rational t(k, d), w = 1 + t * t;
    p.push_back({Rational(c.x + r * (1 - t * t) / w), Rational(c.y + r * 2 * t / w)});
  }
  return p;
}
// A nearly flat convex chain: the parabola squashed by eps (its hull keeps every point).
std::vector<Point2> sliver(int n, const Rational& eps) {
  std::vector<Point2> p;
  for (int i = 0; i < n; ++i) {
    const Rational t(i, n);
    p.push_back({Rational(1 + t), Rational(1 + eps * t * t)});
  }
  return p;
}

// A many-vertex gamut with an edge on each of the rays y = x and y = x/2: (1, 1), (2, 1), (4, 2),
// n − 1 points on the arc (4 − 2t, 2 + t(1 − t)), (2, 2). Since G ⊘ q maps the ray y = x to
// y = (q1/q2)·x, an image colour with q1/q2 = 1/2 puts G ⊘ q against G along y = x/2: F is a
// segment or a point there, reached in the middle of a many-vertex family.
ConvexSet2 wedge(int n) {
  std::vector<Point2> p{{1, 1}, {2, 1}, {4, 2}};
  for (int i = 1; i < n; ++i) {
    const Rational t(i, n);
    p.push_back({Rational(4 - 2 * t), Rational(2 + t * (1 - t))});
  }
  p.push_back({2, 2});
  return convex_hull(p);
}

struct Tally {
  int scenes = 0, enclosed = 0, constrained = 0, unbounded = 0, kinds[4] = {};
  int many_vertices = 0;  // scenes whose G_c has at least 100 vertices
};

std::optional<FeasiblePolygon> run(const CanonicalConstraints& cc, const std::vector<Point2>& image,
                                   internal::Clipping route) {
  try {
    return internal::feasible_polygon(cc, image, route);
  } catch (const UnboundedFeasibleSet&) {
    return std::nullopt;
  }
}

// Both routes on one scene: the same exact set and kind, the same enclosed description (vertex
// and edge counts), enclosures that contain the exact vertices in counter-clockwise order, and
// the same membership answers. Small unconstrained scenes are also checked against the
// unfiltered reference clipper.
void compare_routes(Rng& rng, const ConvexSet2& G, const std::optional<ConvexSet2>& C,
                    const std::vector<Point2>& image, Tally& tally) {
  const CanonicalConstraints cc = C ? CanonicalConstraints(G, *C) : CanonicalConstraints(G);
  const auto fast = run(cc, image, internal::Clipping::convex_pass);
  const auto slow = run(cc, image, internal::Clipping::line_by_line);
  ++tally.scenes;
  tally.constrained += C.has_value();
  tally.many_vertices += G.vertices.size() >= 100;
  BOOST_REQUIRE(fast.has_value() == slow.has_value());
  if (!fast) {
    ++tally.unbounded;
    return;
  }
  const ConvexSet2& F = fast->exact();
  BOOST_TEST(F == slow->exact(), "G_c " << G.vertices.size() << " vertices, " << image.size() << " colours");
  BOOST_TEST(fast->kind() == slow->kind());
  BOOST_TEST(fast->kind() == F.kind);
  BOOST_TEST(fast->enclosed() == slow->enclosed());
  BOOST_TEST(fast->vertices().size() == slow->vertices().size());
  BOOST_TEST(fast->edges().size() == slow->edges().size());
  ++tally.kinds[static_cast<int>(F.kind)];
  if (!C && G.vertices.size() <= 40) BOOST_TEST(F == test::reference::feasible_set_reference(G, image));
  if (fast->enclosed()) {
    ++tally.enclosed;
    const std::size_t n = F.vertices.size();
    BOOST_REQUIRE(fast->vertices().size() == n);
    std::size_t start = n;
    for (std::size_t j = 0; j < n && start == n; ++j)
      if (encloses(fast->vertices()[0].x, F.vertices[j].x) && encloses(fast->vertices()[0].y, F.vertices[j].y))
        start = j;
    BOOST_REQUIRE(start < n);
    for (std::size_t i = 0; i < n; ++i) {
      const Point2& v = F.vertices[(start + i) % n];
      const Point2& w = F.vertices[(start + i + 1) % n];
      BOOST_TEST(encloses(fast->vertices()[i].x, v.x));
      BOOST_TEST(encloses(fast->vertices()[i].y, v.y));
      const ApproximateLine& l = fast->edges()[i];  // outward normal of the CCW edge v → w
      BOOST_TEST((l.a > 0) - (l.a < 0) == sgn(Rational(w.y - v.y)));
      BOOST_TEST((l.b > 0) - (l.b < 0) == sgn(Rational(v.x - w.x)));
    }
  }
  std::vector<Point2> probes;
  for (std::size_t i = 0; i < F.vertices.size() && i < 8; ++i) probes.push_back(F.vertices[i]);
  for (int s = 0; s < 4; ++s) probes.push_back(test::random_points(rng, 1, 0, 4, 7)[0]);
  for (const Point2& m : probes) BOOST_TEST(fast->contains(m) == contains(F, m));
}

// Image colours for a true map d: gamut points divided by d (so d is feasible), sometimes moved
// off (F smaller or empty), repeated, or with a zero channel.
std::vector<Point2> image_for(Rng& rng, const std::vector<Point2>& pts, const Point2& d, int trial) {
  std::vector<Point2> image;
  std::uniform_int_distribution<std::size_t> pick(0, pts.size() - 1);
  for (int i = 0; i < 1 + trial % 6; ++i) {
    const Point2& p = pts[pick(rng)];
    Point2 q{Rational(p.x / d.x), Rational(p.y / d.y)};
    if (trial % 5 == 1) q.x *= Rational(1000 + (i % 3), 1000);  // a little outside: F shrinks, may empty
    if (trial % 7 == 2) q.y *= Rational(999, 1000);
    image.push_back(q);
  }
  if (trial % 4 == 3) image.push_back(image.front());                 // coincident colours
  if (trial % 9 == 4) image.push_back({0, Rational(1, 2)});           // r = 0
  if (trial % 11 == 5) image.push_back({Rational(2, 3), 0});          // g = 0
  if (trial % 23 == 6) image.push_back({0, 0});                       // both: F empty or unchanged
  if (trial % 29 == 7) image = {{0, Rational(1, 3)}, {0, 1}};         // r = 0 everywhere: unbounded
  return image;
}

// A map constraint around d: none, a random hull of 1–6 points (a point, a segment or a small
// polygon), a many-vertex polygon on a circle, or empty.
std::optional<ConvexSet2> constraint_for(Rng& rng, const Point2& d, int trial) {
  switch (trial % 5) {
    case 0:
    case 1: return std::nullopt;
    case 2:
    case 3: {
      std::vector<Point2> c;
      for (int i = 0; i < 1 + trial % 6; ++i)
        c.push_back({Rational(d.x + test::random_rational(rng, -8, 8, 9) / 40),
                     Rational(d.y + test::random_rational(rng, -8, 8, 9) / 40)});
      return convex_hull(c);
    }
    default:
      if (trial % 3 == 0) return ConvexSet2{};
      return convex_hull(circle(60, d, test::random_rational(rng, 1, 9, 7) / 50));
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(feasible_polygon_routes)

// Many-vertex canonical gamuts on convex curves (parabola, circle, sliver), with images near a
// true map: the cases the convex pass exists for, in every kind of outcome.
BOOST_AUTO_TEST_CASE(convex_pass_equals_line_by_line_on_many_vertex_gamuts) {
  Rng rng(13);
  Tally tally;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = trial < 3 ? 1000 : 20 + static_cast<int>(rng() % 300);
    std::vector<Point2> pts;
    switch (trial % 3) {
      case 0: pts = parabola(n, 1, 1, test::random_rational(rng, 1, 5, 3)); break;
      case 1: pts = circle(n, {3, 3}, test::random_rational(rng, 1, 5, 3) / 2); break;
      default: pts = sliver(n, Rational(1, mpz_class(10) << (trial % 40))); break;
    }
    const ConvexSet2 G = convex_hull(pts);
    const Point2 d{test::random_rational(rng, 1, 6, 40), test::random_rational(rng, 1, 6, 40)};
    compare_routes(rng, G, constraint_for(rng, d, trial), image_for(rng, pts, d, trial), tally);
  }
  // The reproducer, small: the parabola and colours (1, 1), (1.001, 1), (1, 1.001).
  const ConvexSet2 G = convex_hull(parabola(2000, 1, 1, 1));
  compare_routes(rng, G, std::nullopt, {{1, 1}, {Rational(1001, 1000), 1}, {1, Rational(1001, 1000)}}, tally);
  // The wedge: G ⊘ (1/3, 2/3) meets G in the segment (3, 3/2)–(4, 2), G ⊘ (1/4, 1/2) in the
  // point (4, 2), G ⊘ (1/5, 2/5) nowhere; a third colour or a constraint may cut further.
  for (int trial = 0; trial < 12; ++trial) {
    const ConvexSet2 W = wedge(trial < 6 ? 300 : 40);
    const Point2 q = trial % 3 == 0 ? Point2{Rational(1, 3), Rational(2, 3)}
                     : trial % 3 == 1 ? Point2{Rational(1, 4), Rational(1, 2)}
                                      : Point2{Rational(1, 5), Rational(2, 5)};
    std::vector<Point2> image{{1, 1}, q};
    if (trial % 4 == 3) image.push_back({Rational(9, 10), Rational(19, 20)});
    const std::optional<ConvexSet2> C =
        trial % 5 == 4 ? std::optional<ConvexSet2>(convex_hull(circle(40, {Rational(7, 2), Rational(7, 4)}, Rational(1, 3))))
                       : std::nullopt;
    compare_routes(rng, W, C, image, tally);
    if (image.size() == 2 && !C) {
      const ConvexSet2 expected = trial % 3 == 0   ? ConvexSet2{ConvexKind::segment, {{3, Rational(3, 2)}, {4, 2}}}
                                  : trial % 3 == 1 ? ConvexSet2{ConvexKind::point, {{4, 2}}}
                                                   : ConvexSet2{};
      BOOST_TEST(internal::feasible_polygon(CanonicalConstraints(W), image, internal::Clipping::convex_pass).exact() ==
                 expected);
    }
  }
  BOOST_TEST(tally.many_vertices > 35);
  BOOST_TEST(tally.enclosed > 15);
  BOOST_TEST(tally.constrained > 15);
  for (int k = 0; k < 4; ++k) BOOST_TEST(tally.kinds[k] > 3, "kind " << k << ": " << tally.kinds[k]);
}

// Random small gamuts (grids with repeated and collinear points, so every kind of G_c and of F)
// and the constructions that force F to a segment or a point, with and without a constraint.
BOOST_AUTO_TEST_CASE(convex_pass_equals_line_by_line_on_small_and_degenerate_scenes) {
  Rng rng(1313);
  Tally tally;
  for (int trial = 0; trial < 400; ++trial) {
    const bool grid = trial % 2;
    const auto pts = test::random_points(rng, grid ? 1 + trial % 9 : 3 + trial % 25, 1, 4, grid ? 2 + trial % 3 : 50);
    const ConvexSet2 G = convex_hull(pts);
    const Point2 d{test::random_rational(rng, 1, 6, grid ? 2 : 40), test::random_rational(rng, 1, 6, grid ? 2 : 40)};
    compare_routes(rng, G, constraint_for(rng, d, trial / 2), image_for(rng, pts, d, trial / 2), tally);
  }
  // A square [1, 2]² scaled by (s, t) with images whose feasible sets touch along an edge (F a
  // segment) or at a corner (F a point): the convex pass degenerates mid-polygon and hands over.
  for (int trial = 0; trial < 40; ++trial) {
    const Rational sx = test::random_rational(rng, 1, 9, 7), sy = test::random_rational(rng, 1, 9, 7);
    const ConvexSet2 G = convex_hull({{sx, sy}, {Rational(2 * sx), sy}, {Rational(2 * sx), Rational(2 * sy)}, {sx, Rational(2 * sy)}});
    std::vector<Point2> image{{1, 1}, {2, 1}};
    if (trial % 2) image.push_back({1, 2});
    const Point2 d{Rational(sx), Rational(sy)};
    compare_routes(rng, G, constraint_for(rng, d, trial), image, tally);
  }
  BOOST_TEST(tally.unbounded > 3);
  BOOST_TEST(tally.enclosed > 60);
  for (int k = 0; k < 4; ++k) BOOST_TEST(tally.kinds[k] > 10, "kind " << k << ": " << tally.kinds[k]);
}

BOOST_AUTO_TEST_SUITE_END()
