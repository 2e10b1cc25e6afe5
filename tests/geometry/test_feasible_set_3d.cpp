// Forsyth's CRULE feasible set in 3-D: hand cases (cubes, every degenerate kind) and random
// scenes checked against an independent brute-force route in this file — canonical hull facets
// by trying every triple, F3's vertices by solving every triple of constraint planes (Cramer),
// its volume and centroid by the divergence theorem over faces ordered here — all exact.
#include "../test_support.h"

#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>

using namespace gmcc;
using gmcc::test::Rng;
using R = Rational;

namespace gmcc {
inline std::ostream& operator<<(std::ostream& os, ConvexKind3 k) { return os << to_string(k); }
inline std::ostream& operator<<(std::ostream& os, const Point3& p) {
  return os << "(" << to_string(p.x) << ", " << to_string(p.y) << ", " << to_string(p.z) << ")";
}
}  // namespace gmcc

namespace {

struct Plane {
  Point3 a;
  R b;  // a·x <= b
};

// Supporting planes of conv(S) through three of its points (S full-dimensional): brute force.
std::vector<Plane> brute_force_facets(const std::vector<Point3>& s) {
  std::vector<Plane> out;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j)
      for (std::size_t k = j + 1; k < s.size(); ++k) {
        Point3 n = cross(sub(s[j], s[i]), sub(s[k], s[i]));
        if (is_zero(n)) continue;
        R b = dot(n, s[i]);
        int above = 0, below = 0;
        for (const Point3& p : s) {
          const int c = sgn(R(dot(n, p) - b));
          above += c > 0, below += c < 0;
        }
        if (above && below) continue;
        if (above) n = {R(-n.x), R(-n.y), R(-n.z)}, b = -b;
        out.push_back({n, b});
      }
  return out;
}
bool in_hull(const std::vector<Plane>& facets, const Point3& x) {
  for (const Plane& f : facets)
    if (dot(f.a, x) > f.b) return false;
  return true;
}
// The definition: d ⊙ p ∈ G for every image colour p.
bool feasible(const std::vector<Plane>& G, const std::vector<Point3>& image, const Point3& d) {
  for (const Point3& p : image)
    if (!in_hull(G, hadamard(d, p))) return false;
  return true;
}
// F3's vertices by brute force: every triple of constraint planes with a unique feasible point.
std::vector<Point3> brute_force_vertices(const std::vector<Plane>& G, const std::vector<Point3>& image) {
  std::vector<Plane> rows;
  for (const Point3& p : image)
    for (const Plane& f : G) rows.push_back({hadamard(f.a, p), f.b});
  std::vector<Point3> out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j)
      for (std::size_t k = j + 1; k < rows.size(); ++k) {
        const Point3 &a = rows[i].a, &b = rows[j].a, &c = rows[k].a;
        const R det = dot(a, cross(b, c));
        if (sgn(det) == 0) continue;
        // Cramer: x = (b_i (b×c) + b_j (c×a) + b_k (a×b)) / det.
        const Point3 bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
        const Point3 x{R((rows[i].b * bc.x + rows[j].b * ca.x + rows[k].b * ab.x) / det),
                       R((rows[i].b * bc.y + rows[j].b * ca.y + rows[k].b * ab.y) / det),
                       R((rows[i].b * bc.z + rows[j].b * ca.z + rows[k].b * ab.z) / det)};
        if (feasible(G, image, x)) out.push_back(x);
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}
// Volume and first moment by the divergence theorem (cones from the origin over the faces),
// each face = the vertices on one constraint plane, ordered by angle around their mean.
std::pair<R, Point3> divergence_volume_moment(const std::vector<Point3>& v, const std::vector<Plane>& planes) {
  R six = 0;
  Point3 m{0, 0, 0};
  std::vector<std::vector<Point3>> seen;
  for (const Plane& p : planes) {
    std::vector<Point3> on;
    for (const Point3& x : v)
      if (dot(p.a, x) == p.b) on.push_back(x);
    if (on.size() < 3 || std::find(seen.begin(), seen.end(), on) != seen.end()) continue;
    seen.push_back(on);
    Point3 c{0, 0, 0};
    for (const Point3& x : on) c = {R(c.x + x.x), R(c.y + x.y), R(c.z + x.z)};
    c = {R(c.x / on.size()), R(c.y / on.size()), R(c.z / on.size())};
    // Angular order about the outward normal a: u = on[0] − c, w = a × u span the plane.
    const Point3 u = sub(on[0], c), w = cross(p.a, u);
    auto half = [&](const Point3& x) {  // 0 for angles in [0, π), 1 for [π, 2π)
      const R su = dot(sub(x, c), u), sw = dot(sub(x, c), w);
      return sgn(sw) > 0 || (sgn(sw) == 0 && sgn(su) > 0) ? 0 : 1;
    };
    std::sort(on.begin(), on.end(), [&](const Point3& x, const Point3& y) {
      const int hx = half(x), hy = half(y);
      if (hx != hy) return hx < hy;
      return sgn(dot(cross(sub(x, c), sub(y, c)), p.a)) > 0;
    });
    for (std::size_t i = 1; i + 1 < on.size(); ++i) {
      const R d = dot(on[0], cross(on[i], on[i + 1]));
      six += d;
      m = {R(m.x + d * (on[0].x + on[i].x + on[i + 1].x)), R(m.y + d * (on[0].y + on[i].y + on[i + 1].y)),
           R(m.z + d * (on[0].z + on[i].z + on[i + 1].z))};
    }
  }
  return {R(six / 6), Point3{R(m.x / 24), R(m.y / 24), R(m.z / 24)}};
}
std::vector<Colour> colours(const std::vector<Point3>& p) {
  std::vector<Colour> c;
  for (const Point3& x : p) c.push_back({x.x, x.y, x.z});
  return c;
}
const std::vector<Point3> cube{{1, 1, 1}, {2, 1, 1}, {1, 2, 1}, {2, 2, 1},
                               {1, 1, 2}, {2, 1, 2}, {1, 2, 2}, {2, 2, 2}};
std::vector<Point3> cube_sorted() {
  std::vector<Point3> c = cube;
  std::sort(c.begin(), c.end());
  return c;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(feasible_set_3d_crule)

BOOST_AUTO_TEST_CASE(cube_by_hand_every_kind) {
  const auto C = colours(cube);
  const auto X = CanonicalBlack::exclude;
  // White image colour: F3 = G itself, the cube [1, 2]³.
  const ConvexSet3 F = feasible_set_3d(C, {{1, 1, 1}}, X);
  BOOST_TEST(F.kind == ConvexKind3::polytope);
  BOOST_TEST(F.vertices == cube_sorted());
  BOOST_TEST(F.faces.size() == 6u);
  for (const auto& f : F.faces) BOOST_TEST(f.size() == 4u);
  BOOST_TEST(volume(F) == 1);
  BOOST_TEST((centroid(F) == Point3{R(3, 2), R(3, 2), R(3, 2)}));
  // A brighter image: the cube [1/2, 1]³, volume 1/8.
  const ConvexSet3 half = feasible_set_3d(C, {{2, 2, 2}}, X);
  BOOST_TEST(volume(half) == R(1, 8));
  BOOST_TEST((half.vertices.front() == Point3{R(1, 2), R(1, 2), R(1, 2)}));
  // Red twice as wide as the gamut allows once: d1 = 1, a square.
  const ConvexSet3 square = feasible_set_3d(C, {{1, 1, 1}, {2, 1, 1}}, X);
  BOOST_TEST(square.kind == ConvexKind3::polygon);
  BOOST_TEST(square.vertices.size() == 4u);
  BOOST_TEST((centroid(square) == Point3{1, R(3, 2), R(3, 2)}));
  BOOST_TEST(volume(square) == 0);
  // Red and green pinned: a segment; all three: a point; too wide: empty.
  const ConvexSet3 seg = feasible_set_3d(C, {{1, 1, 1}, {2, 2, 1}}, X);
  BOOST_TEST(seg.kind == ConvexKind3::segment);
  BOOST_TEST((seg.vertices == std::vector<Point3>{{1, 1, 1}, {1, 1, 2}}));
  const ConvexSet3 pt = feasible_set_3d(C, {{1, 1, 1}, {2, 2, 2}}, X);
  BOOST_TEST(pt.kind == ConvexKind3::point);
  BOOST_TEST((pt.vertices == std::vector<Point3>{{1, 1, 1}}));
  BOOST_TEST(feasible_set_3d(C, {{1, 1, 1}, {4, 1, 1}}, X).kind == ConvexKind3::empty);
  // With black the same image can always be darkened to fit: never empty. G's colours have
  // channel ratios in [1/2, 2], so (4·d1, d2, d3) and d both in G force d2 = d3 = 2·d1 <= 1.
  const ConvexSet3 dark = feasible_set_3d(C, {{1, 1, 1}, {4, 1, 1}});
  BOOST_TEST(dark.kind == ConvexKind3::segment);
  BOOST_TEST((dark.vertices == std::vector<Point3>{{0, 0, 0}, {R(1, 2), 1, 1}}));
  BOOST_CHECK_THROW(feasible_set_3d(C, {{0, 1, 1}}), UnboundedFeasibleSet);
  BOOST_CHECK_THROW(feasible_set_3d({}, {{1, 1, 1}}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(degenerate_canonical_gamuts) {
  // One canonical colour: without black a point, with black the segment from 0.
  BOOST_TEST((feasible_set_3d({{2, 3, 4}}, {{1, 1, 1}}, CanonicalBlack::exclude).vertices ==
              std::vector<Point3>{{2, 3, 4}}));
  const ConvexSet3 s = feasible_set_3d({{2, 3, 4}}, {{1, 2, 4}});
  BOOST_TEST(s.kind == ConvexKind3::segment);
  BOOST_TEST((s.vertices == std::vector<Point3>{{0, 0, 0}, {2, R(3, 2), 1}}));
  // Coplanar canonical colours (a square in b = 1) and black: a pyramid; without black a square.
  const std::vector<Colour> flat{{1, 1, 1}, {2, 1, 1}, {2, 2, 1}, {1, 2, 1}};
  const ConvexSet3 pyramid = feasible_set_3d(flat, {{1, 1, 1}});
  BOOST_TEST(pyramid.kind == ConvexKind3::polytope);
  BOOST_TEST(pyramid.vertices.size() == 5u);
  BOOST_TEST(volume(pyramid) == R(1, 3));  // base 1, height 1
  const ConvexSet3 sq = feasible_set_3d(flat, {{1, 1, 1}}, CanonicalBlack::exclude);
  BOOST_TEST(sq.kind == ConvexKind3::polygon);
  BOOST_TEST((centroid(sq) == Point3{R(3, 2), R(3, 2), 1}));
}

BOOST_AUTO_TEST_CASE(random_scenes_against_brute_force) {
  Rng rng(1990);
  int polytopes = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Point3> canonical;
    for (int i = 0; i < 5 + trial % 5; ++i) canonical.push_back(test::random_point3(rng, 1, 20, 4));
    const bool black = trial % 2 == 0;
    std::vector<Point3> g = canonical;
    if (black) g.push_back({0, 0, 0});
    const std::vector<Plane> G = brute_force_facets(g);
    const Point3 d = test::random_point3(rng, 1, 8, 3);
    std::vector<Point3> image;
    for (int i = 0; i < 1 + trial % 4; ++i)
      image.push_back(test::divided(canonical[static_cast<std::size_t>(i * 3 + trial) % canonical.size()], d));
    const ConvexSet3 F = feasible_set_3d(colours(canonical), colours(image),
                                         black ? CanonicalBlack::include : CanonicalBlack::exclude);
    BOOST_TEST(contains(F, d));  // noise-free: the true map is feasible
    for (const Point3& v : F.vertices) BOOST_TEST(feasible(G, image, v));  // exact containment
    if (F.kind != ConvexKind3::polytope) continue;
    ++polytopes;
    BOOST_TEST(F.vertices == brute_force_vertices(G, image));
    std::vector<Plane> rows;
    for (const Point3& p : image)
      for (const Plane& f : G) rows.push_back({hadamard(f.a, p), f.b});
    const auto [vol, moment] = divergence_volume_moment(F.vertices, rows);
    BOOST_TEST(volume(F) == vol);
    BOOST_TEST(sgn(vol) > 0);
    const Point3 c = centroid(F);
    BOOST_TEST((Point3{R(c.x * vol), R(c.y * vol), R(c.z * vol)} == moment));
    // Maximality: maps around F are in F exactly when the definition says so.
    for (int s = 0; s < 30; ++s) {
      const Point3 m{R(d.x * test::random_rational(rng, 1, 40, 20)),
                     R(d.y * test::random_rational(rng, 1, 40, 20)),
                     R(d.z * test::random_rational(rng, 1, 40, 20))};
      BOOST_TEST(contains(F, m) == feasible(G, image, m));
    }
  }
  BOOST_TEST(polytopes > 15);
}

BOOST_AUTO_TEST_SUITE_END()
