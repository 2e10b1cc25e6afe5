#pragma once
// The feasible set by exact clipping with every predicate in GMP integers and no filter: the
// implementation gmcc shipped before its filtered predicates (git 706ae94), kept as the reference
// the filtered one must equal exactly (tests/geometry/test_feasible_set.cpp).

#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>

#include <algorithm>
#include <vector>

namespace gmcc::test::reference {

struct HalfPlane {
  Rational a, b, c;
};

inline std::vector<HalfPlane> half_planes(const ConvexSet2& set) {
  std::vector<HalfPlane> out;
  const auto& v = set.vertices;
  auto both_ways = [&out](const Rational& a, const Rational& b, const Rational& c) {
    out.push_back({a, b, c});
    out.push_back({Rational(-a), Rational(-b), Rational(-c)});
  };
  switch (set.kind) {
    case ConvexKind::empty: break;
    case ConvexKind::point:
      both_ways(1, 0, v[0].x);
      both_ways(0, 1, v[0].y);
      break;
    case ConvexKind::segment: {
      const Rational dx = v[1].x - v[0].x, dy = v[1].y - v[0].y;
      both_ways(dy, Rational(-dx), Rational(dy * v[0].x - dx * v[0].y));  // the supporting line
      out.push_back({dx, dy, Rational(dx * v[1].x + dy * v[1].y)});       // not beyond v[1]
      out.push_back({Rational(-dx), Rational(-dy), Rational(-(dx * v[0].x + dy * v[0].y))});
      break;
    }
    case ConvexKind::polygon:
      for (std::size_t i = 0; i < v.size(); ++i) {
        const Point2& p = v[i];
        const Point2& q = v[(i + 1) % v.size()];
        const Rational a = q.y - p.y, b = p.x - q.x;  // outward normal of a CCW edge
        out.push_back({a, b, Rational(a * p.x + b * p.y)});
      }
      break;
  }
  return out;
}



// Exact clipping in homogeneous integer coordinates. A line (a, b, c) means a·x + b·y <= c with
// coprime integer coefficients; a vertex is (X, Y, W), W > 0, the point (X/W, Y/W). Every new
// vertex is the intersection of two *input* lines (the edge's and the clip line), so coordinate
// sizes stay bounded by the inputs' instead of growing clip after clip, and side tests are
// integer arithmetic with no gcd (docs/derivations.md §4.3: keep constructions shallow).
struct Line {
  mpz_class a, b, c;
};
struct Vertex {
  mpz_class x, y, w;
  std::size_t out;  // index of the line carrying the edge from this vertex to the next
};

inline Line integer_line(const HalfPlane& h) {
  mpz_class l;
  mpz_lcm(l.get_mpz_t(), h.a.get_den_mpz_t(), h.b.get_den_mpz_t());
  mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), h.c.get_den_mpz_t());
  Line line{h.a.get_num() * (l / h.a.get_den()), h.b.get_num() * (l / h.b.get_den()),
            h.c.get_num() * (l / h.c.get_den())};
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), line.a.get_mpz_t(), line.b.get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), line.c.get_mpz_t());
  if (g > 1) line.a /= g, line.b /= g, line.c /= g;
  return line;
}

// x = (X/W, Y/W) with W the lcm of the denominators: integers, no gcd per operation after.
struct HomogeneousPoint {
  mpz_class x, y, w;
};
inline HomogeneousPoint homogeneous(const Point2& p) {
  HomogeneousPoint h;
  mpz_lcm(h.w.get_mpz_t(), p.x.get_den_mpz_t(), p.y.get_den_mpz_t());
  h.x = p.x.get_num() * (h.w / p.x.get_den());
  h.y = p.y.get_num() * (h.w / p.y.get_den());
  return h;
}

// m ⊙ q ∈ {a·x + b·y <= c}  ⟺  (a·X)·m1 + (b·Y)·m2 <= c·W for q = (X/W, Y/W), W > 0.
inline Line scaled_line(const Line& g, const HomogeneousPoint& q) { return {g.a * q.x, g.b * q.y, g.c * q.w}; }

// The sign of a·x + b·y − c at v (W > 0).
inline int side(const Line& h, const Vertex& v) { return sgn(h.a * v.x + h.b * v.y - h.c * v.w); }

// The intersection of two non-parallel lines (Cramer), with W > 0.
inline Vertex meet(const Line& p, const Line& q, std::size_t out) {
  Vertex v{p.c * q.b - q.c * p.b, p.a * q.c - q.a * p.c, p.a * q.b - q.a * p.b, out};
  if (sgn(v.w) < 0) v.x = -v.x, v.y = -v.y, v.w = -v.w;
  return v;
}

// Sutherland–Hodgman against line `h` (index hi), tracking each output vertex's outgoing line.
inline std::vector<Vertex> clip(const std::vector<Vertex>& cycle, const std::vector<Line>& lines, std::size_t hi) {
  const Line& h = lines[hi];
  const std::size_t n = cycle.size();
  std::vector<int> s(n);
  bool all_inside = true;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = side(h, cycle[i]);
    all_inside = all_inside && s[i] <= 0;
  }
  if (all_inside) return cycle;
  std::vector<Vertex> out;
  out.reserve(n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const std::size_t edge = cycle[i].out;
    if (s[i] <= 0) {
      Vertex v = cycle[i];
      // Leaving the half-plane from a point on its line: the boundary follows h from here.
      if (s[i] == 0 && s[j] > 0) v.out = hi;
      out.push_back(std::move(v));
    }
    if (s[i] * s[j] < 0)  // a strict crossing: exiting continues along h, entering along the edge
      out.push_back(meet(lines[edge], h, s[i] < 0 ? hi : edge));
  }
  return out;
}

// Drop repeated and collinear vertices in homogeneous coordinates (integer determinants, no
// gcd), so that only the final vertices are turned into reduced rationals.
inline bool same_point(const Vertex& p, const Vertex& q) { return p.x * q.w == q.x * p.w && p.y * q.w == q.y * p.w; }
inline int turn(const Vertex& p, const Vertex& q, const Vertex& r) {  // sign of det[p; q; r] (W's > 0)
  return sgn(p.x * (q.y * r.w - r.y * q.w) - p.y * (q.x * r.w - r.x * q.w) + p.w * (q.x * r.y - r.x * q.y));
}
inline std::vector<Vertex> reduced(std::vector<Vertex> cycle) {
  std::vector<Vertex> v;
  for (Vertex& p : cycle)
    if (v.empty() || !same_point(v.back(), p)) v.push_back(std::move(p));
  while (v.size() > 1 && same_point(v.back(), v.front())) v.pop_back();
  if (v.size() < 3) return v;
  std::vector<Vertex> out;
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (turn(v[(i + n - 1) % n], v[i], v[(i + 1) % n]) != 0) out.push_back(v[i]);
  // All collinear: keep the cycle for canonical_convex_set to take the extreme points of.
  return out.size() >= 3 ? out : v;
}
inline std::vector<Point2> to_points(const std::vector<Vertex>& cycle) {
  std::vector<Point2> points;
  points.reserve(cycle.size());
  for (const Vertex& v : cycle) {
    Rational x(v.x, v.w), y(v.y, v.w);
    x.canonicalize();
    y.canonicalize();
    points.push_back({std::move(x), std::move(y)});
  }
  return points;
}

inline ConvexSet2 feasible_set_reference(const ConvexSet2& canonical, const std::vector<Point2>& image) {
  if (canonical.kind == ConvexKind::empty)
    throw std::invalid_argument("feasible_set: the canonical gamut is empty");
  if (image.empty()) throw std::invalid_argument("feasible_set: no image chromaticities");
  for (const Point2& q : image)
    if (sgn(q.x) < 0 || sgn(q.y) < 0)
      throw std::invalid_argument("feasible_set: an image chromaticity is negative");

  // Only the image hull's vertices constrain F (interior colours add implied constraints).
  const ConvexSet2 image_hull = convex_hull(image);
  const auto& qs = image_hull.vertices;

  auto max_of = [](const std::vector<Point2>& ps, Rational Point2::*c) {
    Rational m = ps.front().*c;
    for (const Point2& p : ps) m = std::max(m, p.*c);
    return m;
  };
  const Rational q1 = max_of(qs, &Point2::x), q2 = max_of(qs, &Point2::y);
  if (sgn(q1) == 0)
    throw UnboundedFeasibleSet("every image colour has r = 0: the map's red component is "
                               "unconstrained and the feasible set is unbounded");
  if (sgn(q2) == 0)
    throw UnboundedFeasibleSet("every image colour has g = 0: the map's green component is "
                               "unconstrained and the feasible set is unbounded");

  // The box [0, X/Q1] × [0, Y/Q2] contains F: for q with q1 = Q1 > 0, m1·Q1 is the first
  // coordinate of a point of G_c, so 0 <= m1·Q1 <= X (likewise m2). Clip it to F.
  const Rational x_max = max_of(canonical.vertices, &Point2::x) / q1;
  const Rational y_max = max_of(canonical.vertices, &Point2::y) / q2;
  std::vector<Line> lines{integer_line({0, -1, 0}), integer_line({1, 0, x_max}),
                          integer_line({0, 1, y_max}), integer_line({-1, 0, 0})};
  std::vector<Vertex> cycle{meet(lines[3], lines[0], 0), meet(lines[0], lines[1], 1),
                            meet(lines[1], lines[2], 2), meet(lines[2], lines[3], 3)};

  std::vector<Line> gamut;
  for (const HalfPlane& h : half_planes(canonical)) gamut.push_back(integer_line(h));
  for (const Point2& q : qs) {
    const HomogeneousPoint hq = homogeneous(q);
    for (const Line& g : gamut) {
      lines.push_back(scaled_line(g, hq));
      cycle = clip(cycle, lines, lines.size() - 1);
      if (cycle.empty()) return {};
    }
  }
  return canonical_convex_set(to_points(reduced(std::move(cycle))));
}

}  // namespace gmcc::test::reference
