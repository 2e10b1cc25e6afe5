// The library's 3-D CGAL translation unit (docs/derivations.md §4.4, §4.5): exact 3-D hulls and
// half-space intersection for Forsyth's CRULE feasible set. Heavy includes stay here, behind plain
// interfaces; the exact LP it solves is linear_program.cpp.
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/numerics/internal_check.h>

#include "internal/crule_exact.h"
#include "internal/half_plane.h"
#include "internal/homogeneous_plane.h"
#include "internal/linear_program.h"
#include "internal/small_integer_hull.h"

#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Extreme_points_traits_adapter_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <type_traits>


// ---- Forsyth's CRULE feasible set in 3-D ----------------------------------------------------

namespace gmcc {
namespace internal {
bool operator<(const HalfSpace3& h, const HalfSpace3& g) {
  if (h.a != g.a) return h.a < g.a;
  return h.b < g.b;
}
bool operator==(const HalfSpace3& h, const HalfSpace3& g) { return h.a == g.a && h.b == g.b; }
}  // namespace internal
namespace {
using internal::sorted_unique;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using KPoint3 = Kernel::Point_3;
static_assert(std::is_same<Kernel::FT::Exact_type, mpq_class>::value,
              "gmcc expects CGAL built with CGAL_USE_GMPXX (link CGAL::CGAL)");

using HalfSpace = internal::HalfSpace3;
HalfSpace normalised(Point3 a, Rational b) {
  const Rational& first = sgn(a.x) != 0 ? a.x : sgn(a.y) != 0 ? a.y : a.z;
  const Rational s = 1 / abs(first);
  return {scale(a, s), Rational(b * s)};
}
void dedupe(std::vector<HalfSpace>& h) {
  std::sort(h.begin(), h.end());
  h.erase(std::unique(h.begin(), h.end()), h.end());
}
Point3 axis(int k) { return {k == 0 ? 1 : 0, k == 1 ? 1 : 0, k == 2 ? 1 : 0}; }
Point3 exact_point(const KPoint3& p) {
  return {CGAL::exact(p.x()), CGAL::exact(p.y()), CGAL::exact(p.z())};
}
KPoint3 kernel_point(const Point3& p) {
  return {Kernel::FT(p.x), Kernel::FT(p.y), Kernel::FT(p.z)};
}
// The two coordinates other than k, in increasing order.
Point2 drop(const Point3& p, int k) {
  return k == 0 ? Point2{p.y, p.z} : k == 1 ? Point2{p.x, p.z} : Point2{p.x, p.y};
}

/// Affinely independent witnesses of a non-empty, deduplicated point set: dim + 1 of them.
std::vector<Point3> affine_frame(const std::vector<Point3>& pts) {
  std::vector<Point3> f{pts[0]};
  for (const Point3& p : pts) {
    if (f.size() == 1 && p != f[0]) f.push_back(p);
    else if (f.size() == 2 && !is_zero(cross(sub(f[1], f[0]), sub(p, f[0])))) f.push_back(p);
    else if (f.size() == 3 &&
             sgn(dot(cross(sub(f[1], f[0]), sub(f[2], f[0])), sub(p, f[0]))) != 0) {
      f.push_back(p);
      break;
    }
  }
  return f;
}

/// The vertices of the 3-D hull of a full-dimensional point set (CGAL::convex_hull_3, exact).
CGAL::Polyhedron_3<Kernel> hull_3(const std::vector<Point3>& pts) {
  std::vector<KPoint3> in;
  for (const Point3& p : pts) in.push_back(kernel_point(p));
  CGAL::Polyhedron_3<Kernel> poly;
  CGAL::convex_hull_3(in.begin(), in.end(), poly);
  return poly;
}

/// The facets of conv(pts), pts spanning 3-D with `f` their affine frame (4 points), appended to
/// `out` (normalised, not yet deduplicated); with `vertices`, the hull's vertices too (the mesh's,
/// each an input point: the extreme points, as extreme_points_3 finds them), unsorted.
void full_dimensional_facets(const std::vector<Point3>& pts, const std::vector<Point3>& f, std::vector<HalfSpace>& out,
                             std::vector<Point3>* vertices) {
  // CGAL's hull over the points' indices; each facet's plane through its first three vertices
  // in integers from their homogeneous forms (internal/homogeneous_plane.h), oriented away from
  // a point strictly inside (the frame's centroid, 4·inside in homogeneous form).
  std::vector<KPoint3> in;
  for (const Point3& p : pts) in.push_back(kernel_point(p));
  std::vector<std::size_t> index(pts.size());
  std::iota(index.begin(), index.end(), std::size_t(0));
  CGAL::Surface_mesh<std::size_t> mesh;
  CGAL::convex_hull_3(index.begin(), index.end(), mesh,
                      CGAL::make_extreme_points_traits_adapter(CGAL::make_property_map(in)));
  std::vector<std::optional<std::array<mpz_class, 4>>> homogeneous(pts.size());
  auto h = [&](std::size_t i) -> const std::array<mpz_class, 4>& {
    if (!homogeneous[i]) homogeneous[i] = homogeneous_integers(pts[i]);
    return *homogeneous[i];
  };
  // 4 × the centroid, as (I, L): inside = I/(4L).
  const std::array<mpz_class, 4> in4 = homogeneous_integers(add(add(f[0], f[1]), add(f[2], f[3])));
  for (const auto fc : mesh.faces()) {
    std::array<std::size_t, 3> v{};
    std::size_t n = 0;
    for (const auto x : CGAL::vertices_around_face(mesh.halfedge(fc), mesh))
      if (n < 3) v[n++] = mesh.point(x);
    auto [a, b] = internal::plane_through(h(v[0]), h(v[1]), h(v[2]));
    // outward when a·I <= 4L·b (strictly: the frame spans 3-D).
    const mpz_class lhs = a[0] * in4[0] + a[1] * in4[1] + a[2] * in4[2], rhs = 4 * in4[3] * b;
    if (lhs > rhs)
      for (mpz_class* x : {&a[0], &a[1], &a[2], &b}) *x = -*x;
    out.push_back(normalised({Rational(a[0]), Rational(a[1]), Rational(a[2])}, Rational(b)));
  }
  if (vertices)
    for (const auto x : mesh.vertices()) vertices->push_back(pts[mesh.point(x)]);
}

/// conv(pts) as closed half-spaces, any dimension (equalities as opposite pairs).
std::vector<HalfSpace> hull_half_spaces(const std::vector<Point3>& pts) {
  const std::vector<Point3> f = affine_frame(pts);
  std::vector<HalfSpace> out;
  auto both_ways = [&out](const Point3& a, const Rational& b) {
    out.push_back(normalised(a, b));
    out.push_back(normalised(scale(a, -1), Rational(-b)));
  };
  if (f.size() == 1) {
    for (int k = 0; k < 3; ++k) both_ways(axis(k), coord(f[0], k));
  } else if (f.size() == 2) {
    const Point3 u = sub(f[1], f[0]);
    Point3 n1;
    for (int k = 0; k < 3; ++k)
      if (!is_zero(n1 = cross(u, axis(k)))) break;
    const Point3 n2 = cross(u, n1);
    both_ways(n1, dot(n1, f[0]));
    both_ways(n2, dot(n2, f[0]));
    Rational lo = dot(u, pts[0]), hi = lo;
    for (const Point3& p : pts) lo = std::min(lo, dot(u, p)), hi = std::max(hi, dot(u, p));
    out.push_back(normalised(u, hi));
    out.push_back(normalised(scale(u, -1), Rational(-lo)));
  } else if (f.size() == 3) {
    const Point3 n = cross(sub(f[1], f[0]), sub(f[2], f[0]));
    both_ways(n, dot(n, f[0]));
    const int k = largest_coordinate(n);
    std::vector<Point2> flat;
    for (const Point3& p : pts) flat.push_back(drop(p, k));
    const int i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
    for (const internal::HalfPlane& h : internal::half_planes(convex_hull(flat))) {
      Point3 a{0, 0, 0};
      coord(a, i) = h.a, coord(a, j) = h.b;
      out.push_back(normalised(a, h.c));
    }
  } else {
    full_dimensional_facets(pts, f, out, nullptr);
  }
  dedupe(out);
  return out;
}

/// The points that matter of a point set: its 3-D hull's vertices, or all of it when it is flat.
std::vector<Point3> extreme_points(const std::vector<Point3>& pts) {
  if (affine_frame(pts).size() < 4) return pts;
  const CGAL::Polyhedron_3<Kernel> poly = hull_3(pts);
  std::vector<Point3> out;
  for (auto v = poly.vertices_begin(); v != poly.vertices_end(); ++v)
    out.push_back(exact_point(v->point()));
  return sorted_unique(out);
}

/// Facets of the polytope with vertices `v` cut out by `rows`: every row plane through >= 3
/// vertices, its vertices counter-clockwise seen from outside (the 2-D hull of their projection).
std::vector<std::vector<std::size_t>> facets(const std::vector<Point3>& v,
                                             const std::vector<HalfSpace>& rows) {
  std::vector<std::vector<std::size_t>> out;
  for (const HalfSpace& h : rows) {
    std::vector<std::size_t> on;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (dot(h.a, v[i]) == h.b) on.push_back(i);
    if (on.size() < 3) continue;
    const int k = largest_coordinate(h.a);
    std::vector<Point2> flat;
    for (std::size_t i : on) flat.push_back(drop(v[i], k));
    std::vector<std::size_t> cycle;
    for (const Point2& p : convex_hull(flat).vertices)
      cycle.push_back(on[std::find(flat.begin(), flat.end(), p) - flat.begin()]);
    // CCW in the kept coordinates is CCW seen from +e_k, except for k = 1 (e_x × e_z = −e_y).
    if ((sgn(coord(h.a, k)) > 0) != (k != 1)) std::reverse(cycle.begin(), cycle.end());
    std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
    out.push_back(std::move(cycle));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}
/// Whether `a` is outside the span of `basis` (0–3 linearly independent vectors), exactly.
bool independent_of(const std::vector<Point3>& basis, const Point3& a) {
  if (basis.empty()) return !is_zero(a);
  if (basis.size() == 1) return !is_zero(cross(basis[0], a));
  if (basis.size() == 2) return sgn(dot(cross(basis[0], basis[1]), a)) != 0;
  return false;
}
}  // namespace

namespace {

// The CRULE program's rows: d ⊙ p ∈ {a·x <= b} ⟺ (a ⊙ p)·d <= b for each canonical facet and
// image hull vertex p, plus the implied box 0 <= d_k <= X_k/P_k (`box_max`); nothing when a row
// with a zero normal fails (0 <= b), i.e. no map at all.
struct Rows {
  std::vector<HalfSpace> rows;
  Point3 box_max;
};
std::optional<Rows> crule_rows(const std::vector<HalfSpace>& canonical, const Point3& X,
                               const std::vector<Point3>& image) {
  Point3 P{0, 0, 0};
  for (const Point3& p : image)
    for (int k = 0; k < 3; ++k) coord(P, k) = std::max(coord(P, k), coord(p, k));
  for (int k = 0; k < 3; ++k)
    if (sgn(coord(P, k)) == 0)
      throw UnboundedFeasibleSet(std::string("every image colour has ") + "rgb"[k] +
                                 " = 0: that map component is unconstrained and the feasible "
                                 "set is unbounded");
  Rows out;
  for (const HalfSpace& h : canonical)
    for (const Point3& p : image) {
      const Point3 a = hadamard(h.a, p);
      if (!is_zero(a)) out.rows.push_back(normalised(a, h.b));
      else if (sgn(h.b) < 0) return std::nullopt;
    }
  for (int k = 0; k < 3; ++k) {
    coord(out.box_max, k) = coord(X, k) / coord(P, k);
    out.rows.push_back(normalised(scale(axis(k), -1), 0));
    out.rows.push_back(normalised(axis(k), coord(out.box_max, k)));
  }
  dedupe(out.rows);
  return out;
}

// F3's affine hull: which rows hold with equality on all of F3, a basis of their normals (its
// size is their rank, 3 − dim F3), and a point of F3 strictly inside every other row.
struct AffineHull {
  std::vector<bool> equality;
  std::vector<Point3> basis;
  Point3 inner;
};

// The max-slack LP: maximise s subject to a·d + s <= b on the inequalities (s <= 1); rows found
// tight on all of F3 become equalities until the slack is > 0 (docs/math.md §1b "The exact LP").
// Nothing when F3 is empty.
std::optional<AffineHull> affine_hull(const std::vector<HalfSpace>& rows) {
  AffineHull f{std::vector<bool>(rows.size(), false), {}, {}};
  std::vector<bool> warm(rows.size(), false);  // rows an earlier round's constraint generation took
  for (;;) {
    internal::LinearProgram lp;
    lp.variables = 4;
    lp.objective = {0, 0, 0, -1};
    std::vector<std::size_t> source;  // LP row → constraint row, for the inequalities
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const HalfSpace& h = rows[i];
      if (f.equality[i]) {
        lp.rows.push_back({h.a.x, h.a.y, h.a.z, 0}), lp.rhs.push_back(h.b);
        lp.rows.push_back({Rational(-h.a.x), Rational(-h.a.y), Rational(-h.a.z), 0});
        lp.rhs.push_back(Rational(-h.b));
        source.push_back(rows.size()), source.push_back(rows.size());
      } else {
        // The box rows (one non-zero coefficient) bound d: the constraint generation starts there.
        const int nonzero = (sgn(h.a.x) != 0) + (sgn(h.a.y) != 0) + (sgn(h.a.z) != 0);
        if (nonzero == 1 || warm[i]) lp.initial.push_back(lp.rows.size());
        lp.rows.push_back({h.a.x, h.a.y, h.a.z, 1}), lp.rhs.push_back(h.b);
        source.push_back(i);
      }
    }
    for (std::size_t r = 0; r < lp.rows.size(); ++r)
      if (source[r] == rows.size()) lp.initial.push_back(r);  // the equalities
    lp.initial.push_back(lp.rows.size());  // slack <= 1
    lp.rows.push_back({0, 0, 0, 1}), lp.rhs.push_back(1);
    source.push_back(rows.size());
    const internal::LpSolution s = internal::solve_linear_program(lp);
    if (s.status == internal::LpStatus::infeasible) return std::nullopt;
    GMCC_CHECK(s.status == internal::LpStatus::optimal, "feasible_set_3d: the slack LP (s <= 1) is bounded");
    const Rational& slack = s.x[3];
    if (sgn(slack) < 0) return std::nullopt;
    f.inner = {s.x[0], s.x[1], s.x[2]};
    if (sgn(slack) > 0) return f;  // `basis` spans the equalities' normals (the last round added none)
    bool grew = false;
    for (std::size_t r = 0; r < source.size(); ++r)
      if (source[r] < rows.size() && s.tight_in_every_optimum[r]) f.equality[source[r]] = true, grew = true;
    GMCC_CHECK(grew, "feasible_set_3d: a zero optimal slack shows an implicit equality");
    for (std::size_t r : s.rows_taken)
      if (source[r] < rows.size()) warm[source[r]] = true;
    // Every row whose normal is in the span of the equalities' normals and that holds with
    // equality at `inner` (a point of F3) holds with equality on all of F3 (a = Σλ_i·a_i gives
    // a·y = Σλ_i·b_i = a·inner = b on the equalities' flat): so when F3 is a point, every row
    // through it at once instead of a few per round (docs/math.md §1b "The exact LP").
    f.basis.clear();
    for (std::size_t i = 0; i < rows.size() && f.basis.size() < 3; ++i)
      if (f.equality[i] && independent_of(f.basis, rows[i].a)) f.basis.push_back(rows[i].a);
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (!f.equality[i] && dot(rows[i].a, f.inner) == rows[i].b && !independent_of(f.basis, rows[i].a))
        f.equality[i] = true;
  }
}

// F3 on a line (rank 2): inner + t·u over the interval the other rows leave.
ConvexSet3 segment_of(const std::vector<HalfSpace>& rows, const AffineHull& f) {
  const Point3 u = cross(f.basis[0], f.basis[1]);
  std::optional<Rational> lo, hi;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (f.equality[i]) continue;
    const Rational au = dot(rows[i].a, u);
    if (sgn(au) == 0) continue;
    const Rational t = (rows[i].b - dot(rows[i].a, f.inner)) / au;  // a·(inner + t·u) <= b
    if (sgn(au) > 0) hi = hi ? std::min(*hi, t) : t;
    else lo = lo ? std::max(*lo, t) : t;
  }
  GMCC_CHECK(lo && hi, "feasible_set_3d: the box bounds a segment F3");
  return canonical_convex_set_3(
      ConvexKind3::segment,
      {add(f.inner, scale(u, *lo)), add(f.inner, scale(u, *hi))}, {});
}

// F3 in a plane n·d = c (rank 1): d_k written through the other two coordinates and the box
// clipped by every other row in 2-D.
ConvexSet3 polygon_of(const std::vector<HalfSpace>& rows, const AffineHull& f, const Point3& box_max) {
  const Point3 n = f.basis[0];
  const Rational c = dot(n, f.inner);
  const int k = largest_coordinate(n), i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
  const Rational& nk = coord(n, k);
  std::vector<Point2> cycle{{0, 0}, {coord(box_max, i), 0}, {coord(box_max, i), coord(box_max, j)}, {0, coord(box_max, j)}};
  for (std::size_t r = 0; r < rows.size() && !cycle.empty(); ++r) {
    if (f.equality[r]) continue;
    const Point3& a = rows[r].a;
    const Rational g = coord(a, k) / nk;
    cycle = internal::clip(cycle, {Rational(coord(a, i) - g * coord(n, i)), Rational(coord(a, j) - g * coord(n, j)),
                                   Rational(rows[r].b - g * c)});
  }
  const ConvexSet2 flat = canonical_convex_set(std::move(cycle));
  GMCC_CHECK(flat.kind == ConvexKind::polygon, "feasible_set_3d: a positive-slack plane section is a polygon");
  std::vector<Point3> v;
  std::vector<std::size_t> face;
  for (const Point2& p : flat.vertices) {
    Point3 q{0, 0, 0};
    coord(q, i) = p.x, coord(q, j) = p.y;
    coord(q, k) = (c - coord(n, i) * p.x - coord(n, j) * p.y) / nk;
    face.push_back(v.size());
    v.push_back(q);
  }
  return canonical_convex_set_3(ConvexKind3::polygon, std::move(v), {face});
}

// Full-dimensional F3: CGAL's dual half-space intersection around a strictly interior point.
ConvexSet3 polytope_of(const std::vector<HalfSpace>& rows, const Point3& inner) {
  std::vector<Kernel::Plane_3> planes;
  for (const HalfSpace& h : rows)
    planes.emplace_back(Kernel::FT(h.a.x), Kernel::FT(h.a.y), Kernel::FT(h.a.z), Kernel::FT(-h.b));
  CGAL::Surface_mesh<KPoint3> mesh;
  CGAL::halfspace_intersection_3(planes.begin(), planes.end(), mesh, boost::optional<KPoint3>(kernel_point(inner)));
  std::vector<Point3> v;
  for (const auto& vi : mesh.vertices()) v.push_back(exact_point(mesh.point(vi)));
  v = sorted_unique(std::move(v));
  std::vector<std::vector<std::size_t>> f = facets(v, rows);
  return canonical_convex_set_3(ConvexKind3::polytope, std::move(v), std::move(f));
}

}  // namespace

namespace internal {

int affine_dimension(const std::vector<Point3>& points) {
  return static_cast<int>(affine_frame(points).size()) - 1;
}

std::vector<HalfSpace3> hull_half_spaces_3(const std::vector<Point3>& points) {
  return hull_half_spaces(points);
}

HullFacets3 hull_facets_and_vertices_3(const std::vector<Point3>& points) {
  const std::vector<Point3> f = affine_frame(points);
  GMCC_CHECK(f.size() == 4, "hull_facets_and_vertices_3: the points span 3-D");
  HullFacets3 out;
  full_dimensional_facets(points, f, out.half_spaces, &out.vertices);
  dedupe(out.half_spaces);
  out.vertices = sorted_unique(std::move(out.vertices));
  return out;
}

// Points whose coordinates are all doubles exactly (integer pixel colours, samples read as
// doubles) have their hull's vertices found with Epick: its predicates are exact on double input
// (filtered, with an exact fallback), and extreme points need predicates only — the same vertices
// as Epeck's hull at a small part of its cost. Others take Epeck.
std::vector<Point3> extreme_points_3(const std::vector<Point3>& points) {
  using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Fast::Point_3> fast;
  fast.reserve(points.size());
  for (const Point3& p : points) {
    const double x = p.x.get_d(), y = p.y.get_d(), z = p.z.get_d();
    if (Rational(x) != p.x || Rational(y) != p.y || Rational(z) != p.z) return extreme_points(points);
    fast.emplace_back(x, y, z);
  }
  if (affine_frame(points).size() < 4) return points;
  std::vector<Fast::Point_3> extreme;
  CGAL::extreme_points_3(fast, std::back_inserter(extreme));
  std::vector<Point3> out;
  for (const Fast::Point_3& q : extreme) out.push_back({Rational(q.x()), Rational(q.y()), Rational(q.z())});
  return sorted_unique(out);
}

namespace {

using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;

// Whether the points span 3 dimensions, by the kernel's exact predicates on the doubles.
template <class K>
bool full_dimensional(const std::vector<typename K::Point_3>& p) {
  const typename K::Collinear_3 collinear;
  const typename K::Orientation_3 orientation;
  std::size_t i = 1;
  while (i < p.size() && p[i] == p[0]) ++i;
  if (i == p.size()) return false;
  std::size_t j = i + 1;
  while (j < p.size() && collinear(p[0], p[i], p[j])) ++j;
  if (j == p.size()) return false;
  for (std::size_t k = j + 1; k < p.size(); ++k)
    if (orientation(p[0], p[i], p[j], p[k]) != CGAL::COPLANAR) return true;
  return false;
}

// Whether every coordinate of the points is an integer in [0, 2^16) (pixel values): then
// SmallIntegerHullTraits decides every predicate of the hull exactly in 64-bit integers.
bool small_integer_points(const std::vector<std::array<double, 3>>& points, const std::vector<std::size_t>& indices) {
  for (std::size_t i : indices)
    for (double x : points[i])
      if (!small_integer(x)) return false;
  return true;
}

// The extreme points of `fast` (K's points, full-dimensional) by CGAL's hull under `traits`.
template <class K, class Traits>
std::vector<std::array<double, 3>> extreme_points(const std::vector<typename K::Point_3>& fast, const Traits& traits) {
  std::vector<typename K::Point_3> extreme;
  CGAL::extreme_points_3(fast, std::back_inserter(extreme), traits);
  std::vector<std::array<double, 3>> kept;
  for (const typename K::Point_3& q : extreme) kept.push_back({q.x(), q.y(), q.z()});
  return kept;
}

// The triangles of the hull of `fast` (K's points) as indices into `indices`' points; none when
// the points are flat.
template <class K, class Traits>
std::vector<std::array<std::size_t, 3>> triangles(const std::vector<typename K::Point_3>& fast,
                                                  const std::vector<std::size_t>& indices, const Traits& traits) {
  if (!full_dimensional<K>(fast)) return {};
  CGAL::Surface_mesh<typename K::Point_3> mesh;
  CGAL::convex_hull_3(fast.begin(), fast.end(), mesh, traits);
  // The mesh's points are input points: each is found among `indices` by its exact coordinates.
  auto index_of = [&](const typename K::Point_3& q) {
    for (std::size_t k = 0; k < fast.size(); ++k)
      if (fast[k] == q) return indices[k];
    GMCC_CHECK(false, "hull_triangles_3: a hull vertex is an input point");
    return std::size_t(0);
  };
  std::vector<std::array<std::size_t, 3>> out;
  for (const auto f : mesh.faces()) {
    std::array<std::size_t, 3> t{};
    std::size_t n = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      GMCC_CHECK(n < 3, "hull_triangles_3: CGAL's hull is triangulated");
      t[n++] = index_of(mesh.point(v));
    }
    GMCC_CHECK(n == 3, "hull_triangles_3: CGAL's hull is triangulated");
    out.push_back(t);
  }
  return out;
}

template <class K>
std::vector<typename K::Point_3> points_of(const std::vector<std::array<double, 3>>& points,
                                          const std::vector<std::size_t>& indices) {
  std::vector<typename K::Point_3> fast;
  fast.reserve(indices.size());
  for (std::size_t i : indices) fast.emplace_back(points[i][0], points[i][1], points[i][2]);
  return fast;
}

}  // namespace

std::vector<std::size_t> extreme_point_indices_3(const std::vector<std::array<double, 3>>& points,
                                                 const std::vector<std::size_t>& candidates) {
  // The distinct candidates, sorted, with the first index of each.
  std::vector<std::size_t> order(candidates);
  const auto by_point = [&](std::size_t a, std::size_t b) { return points[a] < points[b]; };
  if (!std::is_sorted(order.begin(), order.end(), by_point))  // pixel colours come sorted
    std::sort(order.begin(), order.end(), by_point);
  order.erase(std::unique(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return points[a] == points[b]; }),
              order.end());
  std::vector<std::array<double, 3>> kept;
  if (small_integer_points(points, order)) {
    const auto fast = points_of<SmallIntegerKernel>(points, order);
    if (!full_dimensional<SmallIntegerKernel>(fast)) return order;
    kept = extreme_points<SmallIntegerKernel>(fast, SmallIntegerHullTraits());
  } else {
    const auto fast = points_of<Fast>(points, order);
    if (!full_dimensional<Fast>(fast)) return order;
    kept = extreme_points<Fast>(fast, CGAL::Convex_hull_traits_3<Fast, CGAL::Default, CGAL::Tag_true>());
  }
  std::sort(kept.begin(), kept.end());
  std::vector<std::size_t> out;
  for (std::size_t i : order)
    if (std::binary_search(kept.begin(), kept.end(), points[i])) out.push_back(i);
  return out;
}

std::vector<std::array<std::size_t, 3>> hull_triangles_3(const std::vector<std::array<double, 3>>& points,
                                                        const std::vector<std::size_t>& indices) {
  if (small_integer_points(points, indices))
    return triangles<SmallIntegerKernel>(points_of<SmallIntegerKernel>(points, indices), indices, SmallIntegerHullTraits());
  return triangles<Fast>(points_of<Fast>(points, indices), indices,
                         CGAL::Convex_hull_traits_3<Fast, CGAL::Default, CGAL::Tag_true>());
}

ConvexSet3 feasible_set_3d_lp(const std::vector<LpPart>& parts) {
  GMCC_CHECK(!parts.empty(), "feasible_set_3d_lp: at least one part");
  std::optional<Rows> rows;
  for (const LpPart& part : parts) {
    std::optional<Rows> r = crule_rows(*part.canonical, *part.canonical_max, *part.image);
    if (!r) return {};
    if (!rows) {
      rows = std::move(r);
      continue;
    }
    rows->rows.insert(rows->rows.end(), r->rows.begin(), r->rows.end());
    for (int k = 0; k < 3; ++k) coord(rows->box_max, k) = std::min(coord(rows->box_max, k), coord(r->box_max, k));
  }
  if (parts.size() > 1) dedupe(rows->rows);
  const std::optional<AffineHull> f = affine_hull(rows->rows);
  if (!f) return {};
  switch (f->basis.size()) {
    case 3: return canonical_convex_set_3(ConvexKind3::point, {f->inner}, {});
    case 2: return segment_of(rows->rows, *f);
    case 1: return polygon_of(rows->rows, *f, rows->box_max);
    default: return polytope_of(rows->rows, f->inner);
  }
}

}  // namespace internal
}  // namespace gmcc
