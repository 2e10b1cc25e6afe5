// The projection onto a polygonal cone (cone_distance.h): the exact answer checked by the
// conditions that characterise a projection onto a closed convex cone (Moreau's decomposition:
// p = q + r with q ∈ K, r in K's polar cone, q · r = 0), with K's membership decided by an
// independent route (the exact 2-D hull of the generators' chromaticities); the filtered
// membership test against the exact facet signs, on points placed exactly on facets and rays and
// with generators far beyond the double range's comfortable middle.
#include <gmcc/geometry/cone_distance.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/point3_arithmetic.h>

#include <boost/test/unit_test.hpp>

#include <random>

using namespace gmcc;

namespace {

Rational small(std::mt19937& rng, int lo, int hi) { return Rational(std::uniform_int_distribution<int>(lo, hi)(rng)); }

// The oracle's membership: q = 0, or q in the open half-space z > 0 with its chromaticity
// (x/z, y/z) in the hull of the generators' (all generators have z > 0 here).
bool in_cone_by_hull(const std::vector<Point3>& g, const Point3& q) {
  if (is_zero(q)) return true;
  if (sgn(q.z) <= 0) return false;
  std::vector<Point2> xy;
  for (const Point3& v : g) xy.push_back({Rational(v.x / v.z), Rational(v.y / v.z)});
  return contains(convex_hull(xy), Point2{Rational(q.x / q.z), Rational(q.y / q.z)});
}

// A random pointed cone: the counter-clockwise hull of 1–9 chromaticities, lifted to (x, y, 1)
// and mapped by a random positive diagonal (as a light maps a canonical gamut).
std::vector<Point3> random_cone(std::mt19937& rng) {
  std::vector<Point2> xy;
  const int n = std::uniform_int_distribution<int>(1, 9)(rng);
  for (int i = 0; i < n; ++i) xy.push_back({small(rng, 1, 12), small(rng, 1, 12)});
  const ConvexSet2 hull = convex_hull(xy);
  const Point3 d{small(rng, 1, 7), small(rng, 1, 7), small(rng, 1, 7)};
  std::vector<Point3> g;
  for (const Point2& v : hull.vertices) g.push_back(hadamard({v.x, v.y, Rational(1)}, d));
  return g;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(cone_distance)

BOOST_AUTO_TEST_CASE(projection_satisfies_moreau_decomposition) {
  std::mt19937 rng(1974);
  int inside = 0, on_face = 0, at_apex = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const std::vector<Point3> g = random_cone(rng);
    const PolygonalCone cone(g);
    // Half the points a non-negative combination of the generators (inside, or on a face when
    // some weights are 0), half anywhere.
    Point3 p{small(rng, -20, 40), small(rng, -20, 40), small(rng, -5, 10)};
    if (trial % 2) {
      p = {Rational(0), Rational(0), Rational(0)};
      for (const Point3& v : g) p = add(p, scale(v, small(rng, 0, 3)));
    }
    const ConeProjection pr = project_onto_cone(p, cone);
    const Point3 r = sub(p, pr.nearest);
    BOOST_TEST(in_cone_by_hull(g, pr.nearest));         // q ∈ K
    BOOST_TEST(sgn(dot(r, pr.nearest)) == 0);           // q · r = 0
    for (const Point3& v : g) BOOST_TEST(sgn(dot(r, v)) <= 0);  // r in the polar cone
    BOOST_TEST(pr.squared_distance == dot(r, r));
    const bool member = in_cone_by_hull(g, p);
    BOOST_TEST(member == (sgn(pr.squared_distance) == 0));
    BOOST_TEST(cone.contains(p) == member);
    inside += member;
    at_apex += is_zero(pr.nearest) && !member;
    on_face += !member && !is_zero(pr.nearest);
  }
  // Every kind of answer occurred.
  BOOST_TEST(inside > 100);
  BOOST_TEST(at_apex > 20);
  BOOST_TEST(on_face > 100);
}

BOOST_AUTO_TEST_CASE(membership_filter_decides_boundary_points_exactly) {
  std::mt19937 rng(2006);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<Point3> g = random_cone(rng);
    if (g.size() < 3) continue;
    // Generators scaled far from 1 (the filter's doubles lose nothing in range, but the exact
    // fallback decides the zero signs).
    const Rational big = Rational(mpz_class(1) << 200), tiny = Rational(1, mpz_class(1) << 150);
    for (std::size_t k = 0; k < g.size(); ++k) g[k] = scale(g[k], k % 2 ? big : tiny);
    const PolygonalCone cone(g);
    const std::size_t k = std::uniform_int_distribution<std::size_t>(0, g.size() - 1)(rng);
    const Point3& a = g[k];
    const Point3& b = g[(k + 1) % g.size()];
    const Point3 on_facet = add(scale(a, small(rng, 1, 5) / big), scale(b, small(rng, 1, 5) / big));
    BOOST_TEST(cone.contains(on_facet));
    BOOST_TEST(cone.contains(a));
    BOOST_TEST(sgn(project_onto_cone(on_facet, cone).squared_distance) == 0);
    // Just outside the facet: a tiny step along its outward normal.
    const Point3 n = cross(a, b);
    const Point3 out = sub(on_facet, scale(n, Rational(1, mpz_class(1) << 400) / dot(n, n) * dot(on_facet, on_facet)));
    BOOST_TEST(!cone.contains(out));
    BOOST_TEST(sgn(project_onto_cone(out, cone).squared_distance) > 0);
  }
}

BOOST_AUTO_TEST_CASE(rays_and_wedges) {
  const PolygonalCone ray({Point3{Rational(1), Rational(2), Rational(2)}});
  const ConeProjection a = project_onto_cone({Rational(3), Rational(0), Rational(0)}, ray);
  BOOST_TEST(a.squared_distance == Rational(9) - Rational(1));  // 9 − (p·g)²/|g|² = 9 − 9/9
  BOOST_TEST(project_onto_cone({Rational(-1), Rational(0), Rational(0)}, ray).squared_distance == 1);  // the apex
  BOOST_TEST(ray.contains({Rational(2), Rational(4), Rational(4)}));
  const PolygonalCone wedge({Point3{Rational(1), Rational(0), Rational(1)}, Point3{Rational(0), Rational(1), Rational(1)}});
  // (1, 1, 0) projects onto the wedge's plane x + y − z = 0 at (1/3, 1/3, 2/3) = (g1 + g2)/3.
  const ConeProjection w = project_onto_cone({Rational(1), Rational(1), Rational(0)}, wedge);
  BOOST_TEST(w.squared_distance == Rational(4, 3));
  BOOST_TEST(wedge.contains({Rational(1), Rational(1), Rational(2)}));
  BOOST_TEST(!wedge.contains({Rational(1), Rational(1), Rational(3)}));
  BOOST_CHECK_THROW(PolygonalCone({}), std::invalid_argument);
  BOOST_CHECK_THROW(PolygonalCone({Point3{Rational(0), Rational(0), Rational(0)}}), std::invalid_argument);
  BOOST_CHECK_THROW(PolygonalCone({Point3{Rational(1), Rational(0), Rational(1)}, Point3{Rational(-1), Rational(0), Rational(-1)}}),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
