#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/geometry/min_violation.h>
#include <gmcc/numerics/internal_check.h>

#include "internal/half_plane.h"
#include "internal/linear_program.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace gmcc {
namespace {
using internal::HalfPlane;

// G's edges (half_planes) and its bounding box: supporting half-planes whose normals contain
// the axes, so that offsetting each by t·‖n‖₁ gives exactly G ⊕ t·[−1, 1]².
std::vector<HalfPlane> supporting_half_planes(const ConvexSet2& G) {
  std::vector<HalfPlane> h = internal::half_planes(G);
  Rational x_lo = G.vertices[0].x, x_hi = x_lo, y_lo = G.vertices[0].y, y_hi = y_lo;
  for (const Point2& v : G.vertices) {
    x_lo = std::min(x_lo, v.x), x_hi = std::max(x_hi, v.x);
    y_lo = std::min(y_lo, v.y), y_hi = std::max(y_hi, v.y);
  }
  h.push_back({1, 0, x_hi});
  h.push_back({-1, 0, Rational(-x_lo)});
  h.push_back({0, 1, y_hi});
  h.push_back({0, -1, Rational(-y_lo)});
  return h;
}

Rational l1(const HalfPlane& h) { return Rational(abs(h.a) + abs(h.b)); }

// Image-hull vertices after feasible_set's own checks (empty, negative, unbounded).
std::vector<Point2> image_vertices(const ConvexSet2& canonical, const std::vector<Point2>& image) {
  if (canonical.kind == ConvexKind::empty)
    throw std::invalid_argument("min_violation: the canonical gamut is empty");
  feasible_set(canonical, image);  // validates exactly as feasible_set does
  return convex_hull(image).vertices;
}
// The LP's rows (a·q1)·m1 + (b·q2)·m2 − ‖(a, b)‖₁·t <= c for every image vertex q and half-plane,
// each times the positive L_h·L_q that makes it integral (L_h, L_q the lcms of the plane's and the
// point's denominators): the same half-space, so the same LP, in integers (the rows' products and
// the generation's exact tests without gcds).
void add_rows(internal::LinearProgram& lp, const std::vector<Point2>& qs, const std::vector<HalfPlane>& planes) {
  std::vector<std::array<mpz_class, 4>> zp;  // (A, B, C, |A| + |B|) of each plane
  for (const HalfPlane& h : planes) {
    const mpz_class L = lcm_of_denominators_of(h.a, h.b, h.c);
    const mpz_class A = times_lcm(h.a, L), B = times_lcm(h.b, L);
    zp.push_back({A, B, times_lcm(h.c, L), mpz_class(abs(A) + abs(B))});
  }
  for (const Point2& q : qs) {
    const mpz_class L = lcm_of_denominators_of(q.x, q.y);
    const mpz_class Q1 = times_lcm(q.x, L), Q2 = times_lcm(q.y, L);
    for (const std::array<mpz_class, 4>& h : zp) {
      lp.rows.push_back({Rational(h[0] * Q1), Rational(h[1] * Q2), Rational(-h[3] * L)});
      lp.rhs.push_back(Rational(h[2] * L));
    }
  }
}
}  // namespace

Rational gamut_violation(const ConvexSet2& canonical, const std::vector<Point2>& image,
                         const Point2& m) {
  if (canonical.kind == ConvexKind::empty || image.empty())
    throw std::invalid_argument("gamut_violation: empty input");
  const std::vector<HalfPlane> planes = supporting_half_planes(canonical);
  bool first = true;
  Rational worst;
  for (const Point2& q : image)
    for (const HalfPlane& h : planes) {
      const Rational v = (h.a * m.x * q.x + h.b * m.y * q.y - h.c) / l1(h);
      if (first || v > worst) worst = v, first = false;
    }
  return worst;
}

MinViolation min_violation(const ConvexSet2& canonical, const std::vector<Point2>& image,
                           const std::optional<ConvexSet2>& constraint) {
  const std::vector<Point2> qs = image_vertices(canonical, image);
  const std::vector<HalfPlane> planes = supporting_half_planes(canonical);
  const std::vector<HalfPlane> hard =
      constraint ? internal::half_planes(*constraint) : std::vector<HalfPlane>{};  // rows of the LP
  if (constraint && constraint->kind == ConvexKind::empty)
    throw std::invalid_argument("min_violation: the constraint set is empty");

  // minimise t over (m1, m2, t): (a·q1)·m1 + (b·q2)·m2 − ‖(a, b)‖₁·t <= c; m >= 0; m ∈ C.
  internal::LinearProgram lp;
  lp.variables = 3;
  lp.objective = {0, 0, 1};
  add_rows(lp, qs, planes);
  // Constraint generation starts from the first image vertex's four bounding-box rows (the last
  // four of `planes`), m >= 0 and C: x <= x_hi and −x <= −x_lo give t >= (x_lo − x_hi)/2, so t is
  // bounded below from the first round, and each round's exact solve stays small (starting from
  // all of the first vertex's rows made every round solve over the whole gamut's edges; the
  // solver takes every row if a subset is unbounded: docs/math.md §1b).
  for (std::size_t r = planes.size() - 4; r < planes.size(); ++r) lp.initial.push_back(r);
  lp.rows.push_back({-1, 0, 0}), lp.rhs.push_back(0);
  lp.rows.push_back({0, -1, 0}), lp.rhs.push_back(0);
  for (const HalfPlane& h : hard) lp.rows.push_back({h.a, h.b, 0}), lp.rhs.push_back(h.c);
  for (std::size_t r = qs.size() * planes.size(); r < lp.rows.size(); ++r) lp.initial.push_back(r);
  const internal::LpSolution s = internal::solve_linear_program(lp);
  // t is bounded below by the box half-planes.
  GMCC_CHECK(s.status == internal::LpStatus::optimal, "min_violation: the linear program has an optimum");

  MinViolation out;
  out.violation = s.value;
  const Rational& t = out.violation;

  // The offset gamut G ⊕ t*·[−1, 1]²: for t* > 0 the hull of G's vertices moved to the square's
  // four corners (a Minkowski sum of convex sets is the hull of the sums of their vertices), one
  // exact 2-D hull; for t* <= 0 the erosion, G's offset half-planes clipped from its bounding box.
  std::vector<Point2> g;
  if (sgn(t) > 0) {
    std::vector<Point2> corners;
    for (const Point2& v : canonical.vertices)
      for (int k = 0; k < 4; ++k)
        corners.push_back({k % 2 ? Rational(v.x + t) : Rational(v.x - t), k / 2 ? Rational(v.y + t) : Rational(v.y - t)});
    g = convex_hull(corners).vertices;
  } else {
    Rational x_lo = canonical.vertices[0].x, y_lo = canonical.vertices[0].y;
    Rational x_hi = x_lo, y_hi = y_lo;
    for (const Point2& v : canonical.vertices) {
      x_lo = std::min(x_lo, v.x), y_lo = std::min(y_lo, v.y);
      x_hi = std::max(x_hi, v.x), y_hi = std::max(y_hi, v.y);
    }
    g = {{Rational(x_lo + t), Rational(y_lo + t)},
         {Rational(x_hi - t), Rational(y_lo + t)},
         {Rational(x_hi - t), Rational(y_hi - t)},
         {Rational(x_lo + t), Rational(y_hi - t)}};
    for (const HalfPlane& h : planes) g = internal::clip(g, {h.a, h.b, Rational(h.c + t * l1(h))});
  }
  out.canonical = canonical_convex_set(g);

  // The minimisers are every row at t = t*: the maps m >= 0 taking each image vertex into the
  // offset gamut, i.e. its feasible set (the same half-planes: the offset gamut is their
  // intersection), by feasible_set's filtered route instead of one exact clip per row (a
  // 1394-vertex gamut and 227 image points: 317,000 rows, fuzz/README.md). Only its part in the
  // closed positive quadrant is reached by m ⊙ q with m, q >= 0, and feasible_set takes a gamut
  // there; the hard constraint joins in the same pass.
  for (const HalfPlane& h : {HalfPlane{-1, 0, 0}, HalfPlane{0, -1, 0}}) g = internal::clip(g, h);
  const ConvexSet2 reached = canonical_convex_set(std::move(g));
  GMCC_CHECK(reached.kind != ConvexKind::empty, "min_violation: the offset gamut reaches the quadrant");
  out.feasible = constraint ? feasible_set(CanonicalConstraints(reached, *constraint), qs) : feasible_set(reached, qs);
  GMCC_CHECK(out.feasible.kind != ConvexKind::empty, "min_violation: the optimal t* has a minimiser");
  return out;
}

}  // namespace gmcc
