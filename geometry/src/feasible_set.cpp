#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>

#include "internal/half_plane.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace gmcc {
namespace {

// Exact clipping in homogeneous integer coordinates, with filtered predicates. A line (a, b, c)
// means a·x + b·y <= c with integer coefficients. A vertex is kept *symbolically*, as the pair of
// input lines it is the intersection of (MATH §3b, item 4: every vertex is the meet of two input
// lines, so constructions never nest). Every decision is the sign of a small determinant of line
// coefficients: it is first evaluated in double from rounded coefficients with a rigorous error
// bound, and only when |value| does not exceed the bound in exact integer arithmetic (GMP), from
// exact lines built on demand. Exact coordinates are constructed only for the final vertices.
struct Line {
  mpz_class a, b, c;
};
// A positive multiple s·(a, b, c) of an exact line with each coefficient rounded: within a
// relative 6u of s·a, s·b, s·c (u = 2^-53; see ApproxLine construction below for the count).
struct ApproxLine {
  double a, b, c;
};

// u = 2^-53, the unit roundoff of double.
constexpr double u = 0x1p-53;
// Magnitudes allowed in filtered evaluation: every non-zero coefficient in [2^-300, 2^300], so
// that products of up to three stay normal (no underflow or overflow) and the error bounds
// below, which are relative, hold. Inputs outside this range take the exact path.
constexpr double filter_min = 0x1p-300, filter_max = 0x1p300;
bool in_filter_range(double x) { return x == 0 || (std::fabs(x) >= filter_min && std::fabs(x) <= filter_max); }

Line integer_line(const internal::HalfPlane& h) {
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

// An integer line scaled by 2^-E (E its largest binary exponent) and truncated to doubles:
// mpz_get_d_2exp truncates to 53 bits, a relative error below 2^-52 = 2u; the scaling is exact.
// False (no filter) when a coefficient would fall below 2^-150 relative to the largest.
bool approx_line(const Line& l, ApproxLine& out) {
  long e[3];
  const double m[3] = {mpz_get_d_2exp(&e[0], l.a.get_mpz_t()), mpz_get_d_2exp(&e[1], l.b.get_mpz_t()),
                       mpz_get_d_2exp(&e[2], l.c.get_mpz_t())};
  long top = 0;
  bool any = false;
  for (int k = 0; k < 3; ++k)
    if (m[k] != 0) top = any ? std::max(top, e[k]) : e[k], any = true;
  double r[3];
  for (int k = 0; k < 3; ++k) {
    if (m[k] == 0) {
      r[k] = 0;
      continue;
    }
    if (e[k] - top < -150) return false;
    r[k] = std::ldexp(m[k], static_cast<int>(e[k] - top));
  }
  out = {r[0], r[1], r[2]};
  return true;
}

// x = (X/W, Y/W) with W the lcm of the denominators: integers, no gcd per operation after.
struct HomogeneousPoint {
  mpz_class x, y, w;
};
HomogeneousPoint homogeneous(const Point2& p) {
  HomogeneousPoint h;
  mpz_lcm(h.w.get_mpz_t(), p.x.get_den_mpz_t(), p.y.get_den_mpz_t());
  h.x = p.x.get_num() * (h.w / p.x.get_den());
  h.y = p.y.get_num() * (h.w / p.y.get_den());
  return h;
}

// A rational truncated to double (mpq_get_d: relative error below 2^-52 = 2u in the normal
// range), or nothing when it is outside [2^-140, 2^140] (checked from its size before
// converting, since mpq_get_d's behaviour out of range is unspecified).
std::optional<double> approx(const Rational& q) {
  if (sgn(q) == 0) return 0.0;
  const long bits = static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2)) -
                    static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 2));
  if (bits < -138 || bits > 138) return std::nullopt;
  return mpq_get_d(q.get_mpq_t());
}

// The sign of orientation(a, b, c) = (b−a)×(c−a) of exact points, filtered: from coordinates
// truncated to double (relative error below 2u each) each difference is within 3.01u of
// |b_x| + |a_x| (and so on), each product within 6.1u of (|b_x|+|a_x|)(|c_y|+|a_y|), and the last
// product and difference round by u each: 12u of the computed magnitudes covers it.
int orientation_sign(const Point2& a, const Point2& b, const Point2& c, const std::array<double, 2>& fa,
                     const std::array<double, 2>& fb, const std::array<double, 2>& fc, bool filtered) {
  if (filtered) {
    const double l = (fb[0] - fa[0]) * (fc[1] - fa[1]), r = (fb[1] - fa[1]) * (fc[0] - fa[0]);
    const double mag = (std::fabs(fb[0]) + std::fabs(fa[0])) * (std::fabs(fc[1]) + std::fabs(fa[1])) +
                       (std::fabs(fb[1]) + std::fabs(fa[1])) * (std::fabs(fc[0]) + std::fabs(fa[0]));
    const double d = l - r, bound = 12 * u * mag;
    if (d > bound) return 1;
    if (d < -bound) return -1;
  }
  return sgn(orientation(a, b, c));
}

// The image hull's vertices (extreme points, counter-clockwise): Andrew's monotone chain with the
// lexicographic order compared exactly (mpq_cmp: no gcd) and orientations filtered. Image hulls
// are small (a scene's colours), so this beats building exact-kernel points for CGAL.
std::vector<Point2> image_hull_vertices(const std::vector<Point2>& image) {
  std::vector<const Point2*> p;
  p.reserve(image.size());
  for (const Point2& q : image) p.push_back(&q);
  std::sort(p.begin(), p.end(), [](const Point2* a, const Point2* b) { return *a < *b; });
  p.erase(std::unique(p.begin(), p.end(), [](const Point2* a, const Point2* b) { return *a == *b; }), p.end());
  if (p.size() < 3) {
    std::vector<Point2> out;
    for (const Point2* q : p) out.push_back(*q);
    return out;
  }
  bool filtered = true;
  std::vector<std::array<double, 2>> f(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto x = approx(p[i]->x), y = approx(p[i]->y);
    filtered = filtered && x && y;
    f[i] = {x.value_or(0), y.value_or(0)};
  }
  std::vector<std::size_t> h(2 * p.size());
  std::size_t k = 0;
  auto turn = [&](std::size_t a, std::size_t b, std::size_t c) {
    return orientation_sign(*p[a], *p[b], *p[c], f[a], f[b], f[c], filtered);
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  std::vector<Point2> out;
  out.reserve(k - 1);
  for (std::size_t i = 0; i + 1 < k; ++i) out.push_back(*p[h[i]]);
  return out;  // all collinear: the two extreme points
}

}  // namespace

// G_c's half-planes as exact integer lines and their filters, and the bounds the box needs.
struct CanonicalConstraints::Impl {
  std::vector<Line> lines;
  std::vector<ApproxLine> approx;
  bool filtered = true;  // every approximation is in the filter's range
  Rational x_max, y_max;
};

CanonicalConstraints::CanonicalConstraints(const ConvexSet2& canonical) {
  if (canonical.kind == ConvexKind::empty)
    throw std::invalid_argument("feasible_set: the canonical gamut is empty");
  auto impl = std::make_shared<Impl>();
  Impl& g = *impl;
  for (const internal::HalfPlane& h : internal::half_planes(canonical)) {
    g.lines.push_back(integer_line(h));
    ApproxLine a{};
    g.filtered = g.filtered && approx_line(g.lines.back(), a);
    g.approx.push_back(a);
  }
  g.x_max = canonical.vertices.front().x, g.y_max = canonical.vertices.front().y;
  for (const Point2& p : canonical.vertices) g.x_max = std::max(g.x_max, p.x), g.y_max = std::max(g.y_max, p.y);
  impl_ = std::move(impl);
}

namespace {

// One clipping run: the lines met so far (approximate always, exact on demand) and the
// predicates on vertices given as pairs of lines.
class Clipper {
 public:
  struct Vertex {
    std::size_t p, q;  // the vertex is the meet of lines p and q (not parallel)
    int w_sign;        // the sign of det[(a_p, b_p); (a_q, b_q)], the homogeneous weight
    std::size_t out;   // the line carrying the edge from this vertex to the next
  };

  Clipper(const CanonicalConstraints::Impl& g, const std::vector<Point2>& qs) : g_(g), qs_(qs), hq_(qs.size()) {
    filtered_ = g.filtered;
    for (const Point2& q : qs) {
      const auto x = approx(q.x), y = approx(q.y);
      filtered_ = filtered_ && x && y;
      q_approx_.push_back({x.value_or(0), y.value_or(0)});
    }
  }

  // A line given exactly (the box's sides).
  std::size_t add_exact(Line l) {
    ApproxLine a{};
    filtered_ = filtered_ && approx_line(l, a) && in_range(a);
    lines_.push_back({a, std::move(l), npos, npos});
    return lines_.size() - 1;
  }
  // The line (n_e ⊙ q)·m <= k_e of canonical half-plane e and image vertex k. Its approximation
  // is (a_e·q1, b_e·q2, c_e) from the truncated q and the scaled, truncated gamut line: three
  // relative errors below 2u, 2u and u (the product's rounding) give less than 5.01u, within the
  // 6u every approximate line is allowed. It is the exact line (a_e·X, b_e·Y, c_e·W) times
  // 2^-E/W > 0 up to those errors.
  std::size_t add_scaled(std::size_t e, std::size_t k) {
    const ApproxLine& ge = g_.approx[e];
    const ApproxLine a{ge.a * q_approx_[k][0], ge.b * q_approx_[k][1], ge.c};
    filtered_ = filtered_ && in_range(a);
    lines_.push_back({a, std::nullopt, e, k});
    return lines_.size() - 1;
  }

  Vertex vertex(std::size_t p, std::size_t q, std::size_t out) { return {p, q, weight_sign(p, q), out}; }

  // The sign of a·x + b·y − c at vertex v for line h (v's weight taken positive).
  int side(std::size_t h, const Vertex& v) { return side_raw(v.p, v.q, h) * v.w_sign; }

  bool same_point(const Vertex& v, const Vertex& w) { return side(w.p, v) == 0 && side(w.q, v) == 0; }

  // True when the cycle (no repeats) turns strictly left at every vertex: each next vertex lies
  // strictly inside the line carrying the edge into the current one.
  bool strictly_convex(const std::vector<Vertex>& v) {
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n; ++i)
      if (side(v[(i + n - 1) % n].out, v[(i + 1) % n]) >= 0) return false;
    return true;
  }

  // The exact vertex, reduced.
  Point2 point(const Vertex& v) {
    const Line& p = exact(v.p);
    const Line& q = exact(v.q);
    mpz_class x = p.c * q.b - q.c * p.b, y = p.a * q.c - q.a * p.c, w = p.a * q.b - q.a * p.b;
    if (sgn(w) < 0) x = -x, y = -y, w = -w;
    Rational rx(x, w), ry(y, w);
    rx.canonicalize();
    ry.canonicalize();
    return {std::move(rx), std::move(ry)};
  }

 private:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  struct Entry {
    ApproxLine approx;
    std::optional<Line> exact;
    std::size_t gamut_edge, image_vertex;  // its source, when not given exactly
  };

  static bool in_range(const ApproxLine& a) { return in_filter_range(a.a) && in_filter_range(a.b) && in_filter_range(a.c); }

  const Line& exact(std::size_t i) {
    Entry& l = lines_[i];
    if (!l.exact) {
      if (!hq_[l.image_vertex]) hq_[l.image_vertex] = homogeneous(qs_[l.image_vertex]);
      const HomogeneousPoint& q = *hq_[l.image_vertex];
      const Line& g = g_.lines[l.gamut_edge];
      // m ⊙ q ∈ {a·x + b·y <= c}  ⟺  (a·X)·m1 + (b·Y)·m2 <= c·W for q = (X/W, Y/W), W > 0.
      l.exact = Line{g.a * q.x, g.b * q.y, g.c * q.w};
    }
    return *l.exact;
  }

  // sign det[(a_p, b_p); (a_q, b_q)]. Each coefficient is within a relative 6u of a positive
  // multiple of the exact one (row by row, which keeps the sign), so each product is within
  // (1+6u)² − 1 < 12.01u; evaluating a·b − c·d adds at most 2.01u of |ab| + |cd| (two rounded
  // products and a rounded difference). 16u of the computed magnitude covers both.
  int weight_sign(std::size_t i, std::size_t j) {
    if (filtered_) {
      const ApproxLine &p = lines_[i].approx, &q = lines_[j].approx;
      const double l = p.a * q.b, r = q.a * p.b;
      const double w = l - r, bound = 16 * u * (std::fabs(l) + std::fabs(r));
      if (w > bound) return 1;
      if (w < -bound) return -1;
    }
    const Line &p = exact(i), &q = exact(j);
    return sgn(mpz_class(p.a * q.b - q.a * p.b));
  }

  // sign of h_a·(p_c q_b − q_c p_b) + h_b·(p_a q_c − q_a p_c) − h_c·(p_a q_b − q_a p_b): the side of
  // the unnormalised meet of p and q, a 3×3 determinant. Filter: each of its six triple products
  // is within (1+6u)³ − 1 < 18.01u of the exact (scaled) one, and the evaluation below rounds each
  // term at most six times (γ6 < 6.01u), for at most 24.1u of the exact magnitude sum, which is at
  // most (1+6u)³(1+4u) times the computed one: 32u of the computed magnitude covers it.
  int side_raw(std::size_t pi, std::size_t qi, std::size_t hi) {
    if (filtered_) {
      const ApproxLine &p = lines_[pi].approx, &q = lines_[qi].approx, &h = lines_[hi].approx;
      const double x1 = p.c * q.b, x2 = q.c * p.b, y1 = p.a * q.c, y2 = q.a * p.c, w1 = p.a * q.b, w2 = q.a * p.b;
      const double s = h.a * (x1 - x2) + h.b * (y1 - y2) - h.c * (w1 - w2);
      const double mag = std::fabs(h.a) * (std::fabs(x1) + std::fabs(x2)) +
                         std::fabs(h.b) * (std::fabs(y1) + std::fabs(y2)) +
                         std::fabs(h.c) * (std::fabs(w1) + std::fabs(w2));
      const double bound = 32 * u * mag;
      if (s > bound) return 1;
      if (s < -bound) return -1;
      if (mag == 0) return 0;  // every term has an exactly zero factor (no underflow in range)
    }
    const Line &p = exact(pi), &q = exact(qi), &h = exact(hi);
    return sgn(mpz_class(h.a * (p.c * q.b - q.c * p.b) + h.b * (p.a * q.c - q.a * p.c) -
                         h.c * (p.a * q.b - q.a * p.b)));
  }

  const CanonicalConstraints::Impl& g_;
  const std::vector<Point2>& qs_;
  std::vector<std::optional<HomogeneousPoint>> hq_;
  std::vector<std::array<double, 2>> q_approx_;
  std::vector<Entry> lines_;
  bool filtered_ = true;
};

using Vertex = Clipper::Vertex;

// Sutherland–Hodgman against line `hi`, tracking each output vertex's outgoing line. `out` and
// `s` are reused buffers.
void clip(Clipper& c, const std::vector<Vertex>& cycle, std::size_t hi, std::vector<Vertex>& out,
          std::vector<int>& s) {
  const std::size_t n = cycle.size();
  s.resize(n);
  out.clear();
  bool all_inside = true;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = c.side(hi, cycle[i]);
    all_inside = all_inside && s[i] <= 0;
  }
  if (all_inside) {
    out = cycle;
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const std::size_t edge = cycle[i].out;
    if (s[i] <= 0) {
      Vertex v = cycle[i];
      // Leaving the half-plane from a point on its line: the boundary follows h from here.
      if (s[i] == 0 && s[j] > 0) v.out = hi;
      out.push_back(v);
    }
    if (s[i] * s[j] < 0)  // a strict crossing: exiting continues along h, entering along the edge
      out.push_back(c.vertex(edge, hi, s[i] < 0 ? hi : edge));
  }
}

// Drop repeated and collinear vertices. Repeats: v equals w iff v lies on both lines meeting in
// w. Collinear: consecutive p, q, r with p != q are collinear iff r lies on the line carrying the
// edge p → q (p.out), so a repeat hands its outgoing line to the vertex it merges into.
std::vector<Vertex> reduced(Clipper& c, const std::vector<Vertex>& cycle) {
  std::vector<Vertex> v;
  v.reserve(cycle.size());
  for (const Vertex& p : cycle) {
    if (!v.empty() && c.same_point(v.back(), p))
      v.back().out = p.out;
    else
      v.push_back(p);
  }
  while (v.size() > 1 && c.same_point(v.back(), v.front())) v.pop_back();
  if (v.size() < 3) return v;
  std::vector<Vertex> out;
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (c.side(v[(i + n - 1) % n].out, v[(i + 1) % n]) != 0) out.push_back(v[i]);
  // All collinear: keep the cycle for canonical_convex_set to take the extreme points of.
  return out.size() >= 3 ? out : v;
}

}  // namespace

ConvexSet2 feasible_set(const CanonicalConstraints& canonical, const std::vector<Point2>& image) {
  if (image.empty()) throw std::invalid_argument("feasible_set: no image chromaticities");
  for (const Point2& q : image)
    if (sgn(q.x) < 0 || sgn(q.y) < 0)
      throw std::invalid_argument("feasible_set: an image chromaticity is negative");
  const CanonicalConstraints::Impl& g = *canonical.impl_;

  // Only the image hull's vertices constrain F (interior colours add implied constraints).
  const std::vector<Point2> qs = image_hull_vertices(image);

  auto max_of = [](const std::vector<Point2>& ps, Rational Point2::*c) {
    const Rational* m = &(ps.front().*c);
    for (const Point2& p : ps) m = std::max(m, &(p.*c), [](auto a, auto b) { return *a < *b; });
    return *m;
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
  Clipper c(g, qs);
  const std::size_t bottom = c.add_exact(integer_line({0, -1, 0}));
  const std::size_t right = c.add_exact(integer_line({1, 0, Rational(g.x_max / q1)}));
  const std::size_t top = c.add_exact(integer_line({0, 1, Rational(g.y_max / q2)}));
  const std::size_t left = c.add_exact(integer_line({-1, 0, 0}));
  std::vector<Vertex> cycle{c.vertex(left, bottom, bottom), c.vertex(bottom, right, right),
                            c.vertex(right, top, top), c.vertex(top, left, left)};
  std::vector<Vertex> next;
  std::vector<int> sides;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    for (std::size_t e = 0; e < g.lines.size(); ++e) {
      clip(c, cycle, c.add_scaled(e, k), next, sides);
      cycle.swap(next);
      if (cycle.empty()) return {};
    }
  }
  const std::vector<Vertex> v = reduced(c, cycle);
  std::vector<Point2> points;
  points.reserve(v.size());
  for (const Vertex& p : v) points.push_back(c.point(p));
  if (v.size() < 3 || !c.strictly_convex(v)) return canonical_convex_set(std::move(points));
  // Already strictly convex and counter-clockwise: only the canonical start is left to do.
  ConvexSet2 F;
  F.kind = ConvexKind::polygon;
  std::rotate(points.begin(), std::min_element(points.begin(), points.end()), points.end());
  F.vertices = std::move(points);
  return F;
}

ConvexSet2 feasible_set(const ConvexSet2& canonical, const std::vector<Point2>& image) {
  return feasible_set(CanonicalConstraints(canonical), image);
}

}  // namespace gmcc
