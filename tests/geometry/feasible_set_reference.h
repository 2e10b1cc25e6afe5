#pragma once
// The feasible set by exact clipping with every predicate in GMP integers and no filter: the
// implementation gmcc shipped before its filtered predicates (git 706ae94), kept as the reference
// the filtered one must equal exactly (tests/geometry/test_feasible_set.cpp). Its constraints are
// derived here from orientation and dot products and integerised without reduction, not taken from
// the library's half_planes and integer_line, so that a bug there cannot hide in both.

#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>

#include <algorithm>
#include <vector>

namespace gmcc::test::reference {

// Exact clipping in homogeneous integer coordinates. A line (a, b, c) means a·x + b·y <= c with
// integer coefficients; a vertex is (X, Y, W), W > 0, the point (X/W, Y/W). Every new
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

// The constraint f(m) = alpha·m1 + beta·m2 + gamma >= 0 as an integer line a·x + b·y <= c:
// multiplied by the product of the three denominators (no lcm, no gcd: the library reduces its
// lines, this oracle does not), then negated into the <= form.
inline Line line_from_form(const Rational& alpha, const Rational& beta, const Rational& gamma) {
  const mpz_class d = alpha.get_den() * beta.get_den() * gamma.get_den();
  return {-(alpha.get_num() * (d / alpha.get_den())), -(beta.get_num() * (d / beta.get_den())),
          gamma.get_num() * (d / gamma.get_den())};
}

// The affine forms whose non-negativity at p = (m1·q1, m2·q2) says p ∈ G_c, derived from
// orientation and dot products (not from the library's half_planes): a CCW polygon's interior is
// left of every edge, orient(v_i, v_i+1, p) >= 0; a segment [a, b] is orient(a, b, p) = 0 with
// (p − a)·(b − a) >= 0 and (p − b)·(a − b) >= 0; a point g is p − g = 0. Each form is written as
// (alpha, beta, gamma) in m for the given q.
inline std::vector<Line> constraints_for(const ConvexSet2& g, const Point2& q) {
  std::vector<Line> out;
  auto orient_form = [&](const Point2& a, const Point2& b, int sign) {
    // (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x) with p = (m1·q.x, m2·q.y).
    const Rational dx = b.x - a.x, dy = b.y - a.y;
    out.push_back(line_from_form(Rational(-sign * dy * q.x), Rational(sign * dx * q.y),
                                 Rational(sign * (dy * a.x - dx * a.y))));
  };
  auto dot_form = [&](const Point2& a, const Point2& b) {  // (p − a)·(b − a) >= 0
    const Rational dx = b.x - a.x, dy = b.y - a.y;
    out.push_back(line_from_form(Rational(dx * q.x), Rational(dy * q.y), Rational(-(dx * a.x + dy * a.y))));
  };
  const auto& v = g.vertices;
  switch (g.kind) {
    case ConvexKind::empty: break;
    case ConvexKind::point:
      out.push_back(line_from_form(q.x, 0, Rational(-v[0].x)));   // m1·q1 − g.x >= 0
      out.push_back(line_from_form(Rational(-q.x), 0, v[0].x));   // g.x − m1·q1 >= 0
      out.push_back(line_from_form(0, q.y, Rational(-v[0].y)));
      out.push_back(line_from_form(0, Rational(-q.y), v[0].y));
      break;
    case ConvexKind::segment:
      orient_form(v[0], v[1], 1);
      orient_form(v[0], v[1], -1);
      dot_form(v[0], v[1]);
      dot_form(v[1], v[0]);
      break;
    case ConvexKind::polygon:
      for (std::size_t i = 0; i < v.size(); ++i) orient_form(v[i], v[(i + 1) % v.size()], 1);
      break;
  }
  return out;
}

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
  // Sutherland & Hodgman's own form (1974): each edge S → P in turn, a strict crossing of h
  // between S and P first (leaving the half-plane, the boundary continues along h; entering, along
  // the edge S → P), then P itself when inside. The same cycle as a walk from each vertex to the
  // next, started one edge earlier.
  std::vector<Vertex> out;
  out.reserve(n + 1);
  for (std::size_t k = 0; k < n; ++k) {
    const Vertex& S = cycle[(k + n - 1) % n];
    const int sS = s[(k + n - 1) % n], sP = s[k], sNext = s[(k + 1) % n];
    if ((sS < 0 && sP > 0) || (sS > 0 && sP < 0)) out.push_back(meet(lines[S.out], h, sS < 0 ? hi : S.out));
    if (sP > 0) continue;
    Vertex P = cycle[k];
    if (sP == 0 && sNext > 0) P.out = hi;  // on h, and the boundary leaves along h
    out.push_back(std::move(P));
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
  std::vector<Line> lines{line_from_form(0, 1, 0), line_from_form(-1, 0, x_max), line_from_form(0, -1, y_max),
                          line_from_form(1, 0, 0)};  // m2 >= 0, m1 <= x_max, m2 <= y_max, m1 >= 0
  std::vector<Vertex> cycle{meet(lines[3], lines[0], 0), meet(lines[0], lines[1], 1),
                            meet(lines[1], lines[2], 2), meet(lines[2], lines[3], 3)};
  for (const Point2& q : qs)
    for (Line& l : constraints_for(canonical, q)) {
      lines.push_back(std::move(l));
      cycle = clip(cycle, lines, lines.size() - 1);
      if (cycle.empty()) return {};
    }
  return canonical_convex_set(to_points(reduced(std::move(cycle))));
}

}  // namespace gmcc::test::reference
