// The library's 3-D CGAL translation unit (docs/derivations.md §4.4, §4.5): exact LP (CGAL QP
// solver), exact 3-D hulls and half-space intersection. Heavy includes stay here, behind plain
// interfaces.
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>

#include "internal/half_plane.h"
#include "internal/linear_program.h"
#include "internal/vector3.h"

#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpz.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <type_traits>

namespace gmcc {
namespace internal {
namespace {
mpz_class to_mpz(const CGAL::Gmpz& z) { return mpz_class(z.mpz()); }
CGAL::Gmpz to_gmpz(const mpz_class& z) { return CGAL::Gmpz(z.get_mpz_t()); }

// The integer row k·(a, b) for k the lcm of the denominators: same half-space, integer data.
std::vector<mpz_class> integer_row(const std::vector<Rational>& a, const Rational* b) {
  mpz_class l = 1;
  for (const Rational& x : a) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  if (b) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), b->get_den_mpz_t());
  std::vector<mpz_class> out;
  for (const Rational& x : a) out.push_back(mpz_class(x.get_num() * (l / x.get_den())));
  if (b) out.push_back(mpz_class(b->get_num() * (l / b->get_den())));
  return out;
}
}  // namespace

namespace {
// One exact simplex run (Bland's rule) on the rows `take` of `lp`; the certificate is indexed like
// `take`.
LpSolution solve_rows(const LinearProgram& lp, const std::vector<std::size_t>& take) {
  using Program = CGAL::Quadratic_program<CGAL::Gmpz>;
  const int n = static_cast<int>(lp.variables);
  Program qp(CGAL::SMALLER, false, 0, false, 0);  // rows <=, variables free
  for (std::size_t t = 0; t < take.size(); ++t) {
    const std::vector<mpz_class> r = integer_row(lp.rows[take[t]], &lp.rhs[take[t]]);
    for (int j = 0; j < n; ++j)
      if (sgn(r[j]) != 0) qp.set_a(j, static_cast<int>(t), to_gmpz(r[j]));
    qp.set_b(static_cast<int>(t), to_gmpz(r[n]));
  }
  // A positive multiple of c has the same minimisers; the value is recomputed exactly below.
  const std::vector<mpz_class> c = integer_row(lp.objective, nullptr);
  for (int j = 0; j < n; ++j)
    if (sgn(c[j]) != 0) qp.set_c(j, to_gmpz(c[j]));
  // Make every variable known to the program even when no row or objective term mentions it.
  for (int j = 0; j < n; ++j) qp.set_l(j, false, 0), qp.set_u(j, false, 0);

  CGAL::Quadratic_program_options options;
  options.set_pricing_strategy(CGAL::QP_BLAND);  // no cycling: a finite number of pivots
  const CGAL::Quadratic_program_solution<CGAL::Gmpz> s =
      CGAL::solve_linear_program(qp, CGAL::Gmpz(), options);
  LpSolution out;
  if (s.is_infeasible()) return out;
  if (s.is_unbounded()) {
    out.status = LpStatus::unbounded;
    return out;
  }
  out.status = LpStatus::optimal;
  auto v = s.variable_values_begin();
  for (int j = 0; j < n; ++j, ++v) {
    Rational x(to_mpz(v->numerator()), to_mpz(v->denominator()));
    x.canonicalize();
    out.x.push_back(x);
  }
  out.value = 0;
  for (int j = 0; j < n; ++j) out.value += lp.objective[j] * out.x[j];
  for (auto it = s.optimality_certificate_numerators_begin();
       it != s.optimality_certificate_numerators_end(); ++it)
    out.tight_in_every_optimum.push_back(CGAL::sign(*it) != CGAL::ZERO);
  out.tight_in_every_optimum.resize(take.size(), false);
  return out;
}
}  // namespace

LpSolution solve_linear_program(const LinearProgram& lp) {
  if (lp.objective.size() != lp.variables || lp.rows.size() != lp.rhs.size())
    throw std::invalid_argument("solve_linear_program: inconsistent sizes");
  for (const std::vector<Rational>& r : lp.rows)
    if (r.size() != lp.variables) throw std::invalid_argument("solve_linear_program: row of the wrong length");
  auto every_row = [&lp] {
    std::vector<std::size_t> all(lp.rows.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    LpSolution s = solve_rows(lp, all);
    s.rows_taken = std::move(all);
    return s;
  };
  if (lp.initial.empty()) return every_row();

  std::vector<bool> taken(lp.rows.size(), false);
  std::vector<std::size_t> take;
  for (std::size_t i : lp.initial) {
    if (i >= lp.rows.size()) throw std::invalid_argument("solve_linear_program: initial row out of range");
    if (!taken[i]) taken[i] = true, take.push_back(i);
  }
  constexpr std::size_t per_round = 64;
  for (;;) {
    LpSolution s = solve_rows(lp, take);
    // Infeasible on a subset: infeasible. Unbounded on a subset says nothing: every row at once.
    if (s.status == LpStatus::infeasible) return s;
    if (s.status == LpStatus::unbounded) return every_row();
    std::vector<std::pair<Rational, std::size_t>> violated;
    for (std::size_t i = 0; i < lp.rows.size(); ++i) {
      if (taken[i]) continue;
      Rational excess = -lp.rhs[i];
      for (std::size_t j = 0; j < lp.variables; ++j)
        if (sgn(lp.rows[i][j]) != 0) excess += lp.rows[i][j] * s.x[j];
      if (sgn(excess) > 0) violated.emplace_back(std::move(excess), i);
    }
    if (violated.empty()) {  // optimal for every row; rows never taken have zero multipliers
      std::vector<bool> tight(lp.rows.size(), false);
      for (std::size_t t = 0; t < take.size(); ++t) tight[take[t]] = s.tight_in_every_optimum[t];
      s.tight_in_every_optimum = std::move(tight);
      s.rows_taken = std::move(take);
      return s;
    }
    const std::size_t k = std::min(per_round, violated.size());
    std::partial_sort(violated.begin(), violated.begin() + static_cast<std::ptrdiff_t>(k), violated.end(),
                      [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
    for (std::size_t t = 0; t < k; ++t) taken[violated[t].second] = true, take.push_back(violated[t].second);
  }
}

}  // namespace internal
}  // namespace gmcc

// ---- Forsyth's CRULE feasible set in 3-D ----------------------------------------------------

namespace gmcc {
namespace {
using internal::coord;
using internal::cross;
using internal::dot;
using internal::is_zero;
using internal::sub;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using KPoint3 = Kernel::Point_3;
static_assert(std::is_same<Kernel::FT::Exact_type, mpq_class>::value,
              "gmcc expects CGAL built with CGAL_USE_GMPXX (link CGAL::CGAL)");

/// The closed half-space a·x <= b, normalised so the first non-zero |a_k| is 1 (a unique key).
struct HalfSpace {
  Point3 a;
  Rational b;
};
bool operator<(const HalfSpace& h, const HalfSpace& g) {
  if (h.a != g.a) return h.a < g.a;
  return h.b < g.b;
}
bool operator==(const HalfSpace& h, const HalfSpace& g) { return h.a == g.a && h.b == g.b; }
HalfSpace normalised(Point3 a, Rational b) {
  const Rational& first = sgn(a.x) != 0 ? a.x : sgn(a.y) != 0 ? a.y : a.z;
  const Rational s = 1 / abs(first);
  return {internal::scale(a, s), Rational(b * s)};
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

std::vector<Point3> sorted_unique(std::vector<Point3> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  return p;
}

/// The vertices of the 3-D hull of a full-dimensional point set (CGAL::convex_hull_3, exact).
CGAL::Polyhedron_3<Kernel> hull_3(const std::vector<Point3>& pts) {
  std::vector<KPoint3> in;
  for (const Point3& p : pts) in.push_back(kernel_point(p));
  CGAL::Polyhedron_3<Kernel> poly;
  CGAL::convex_hull_3(in.begin(), in.end(), poly);
  return poly;
}

/// conv(pts) as closed half-spaces, any dimension (equalities as opposite pairs).
std::vector<HalfSpace> hull_half_spaces(const std::vector<Point3>& pts) {
  const std::vector<Point3> f = affine_frame(pts);
  std::vector<HalfSpace> out;
  auto both_ways = [&out](const Point3& a, const Rational& b) {
    out.push_back(normalised(a, b));
    out.push_back(normalised(internal::scale(a, -1), Rational(-b)));
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
    out.push_back(normalised(internal::scale(u, -1), Rational(-lo)));
  } else if (f.size() == 3) {
    const Point3 n = cross(sub(f[1], f[0]), sub(f[2], f[0]));
    both_ways(n, dot(n, f[0]));
    const int k = internal::largest_coordinate(n);
    std::vector<Point2> flat;
    for (const Point3& p : pts) flat.push_back(drop(p, k));
    const int i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
    for (const internal::HalfPlane& h : internal::half_planes(convex_hull(flat))) {
      Point3 a{0, 0, 0};
      coord(a, i) = h.a, coord(a, j) = h.b;
      out.push_back(normalised(a, h.c));
    }
  } else {
    Point3 inside = internal::add(internal::add(f[0], f[1]), internal::add(f[2], f[3]));
    inside = internal::scale(inside, Rational(1, 4));
    const CGAL::Polyhedron_3<Kernel> poly = hull_3(pts);
    for (auto fc = poly.facets_begin(); fc != poly.facets_end(); ++fc) {
      auto h = fc->halfedge();
      const Point3 p = exact_point(h->vertex()->point());
      const Point3 q = exact_point(h->next()->vertex()->point());
      const Point3 r = exact_point(h->next()->next()->vertex()->point());
      Point3 n = cross(sub(q, p), sub(r, p));
      Rational b = dot(n, p);
      if (dot(n, inside) > b) n = internal::scale(n, -1), b = -b;
      out.push_back(normalised(n, b));
    }
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

std::vector<Point3> colours_to_points(const std::vector<Colour>& cs, const char* what) {
  if (cs.empty()) throw std::invalid_argument(std::string("feasible_set_3d: no ") + what + " colours");
  std::vector<Point3> p;
  for (const Colour& c : cs) {
    if (sgn(c.r) < 0 || sgn(c.g) < 0 || sgn(c.b) < 0)
      throw std::invalid_argument(std::string("feasible_set_3d: a negative ") + what + " channel");
    p.push_back({c.r, c.g, c.b});
  }
  return p;
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
    const int k = internal::largest_coordinate(h.a);
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

ConvexSet3 feasible_set_3d(const std::vector<Colour>& canonical_colours,
                           const std::vector<Colour>& image_colours, CanonicalBlack black) {
  std::vector<Point3> canonical = colours_to_points(canonical_colours, "canonical");
  if (black == CanonicalBlack::include) canonical.push_back({0, 0, 0});
  canonical = sorted_unique(canonical);
  const std::vector<Point3> image = extreme_points(sorted_unique(colours_to_points(image_colours, "image")));

  Point3 X{0, 0, 0}, P{0, 0, 0};
  for (const Point3& c : canonical)
    for (int k = 0; k < 3; ++k) coord(X, k) = std::max(coord(X, k), coord(c, k));
  for (const Point3& p : image)
    for (int k = 0; k < 3; ++k) coord(P, k) = std::max(coord(P, k), coord(p, k));
  for (int k = 0; k < 3; ++k)
    if (sgn(coord(P, k)) == 0)
      throw UnboundedFeasibleSet(std::string("every image colour has ") + "rgb"[k] +
                                 " = 0: that map component is unconstrained and the feasible "
                                 "set is unbounded");

  // d ⊙ p ∈ {a·x <= b}  ⟺  (a ⊙ p)·d <= b; plus the implied box 0 <= d_k <= X_k/P_k.
  std::vector<HalfSpace> rows;
  for (const HalfSpace& h : hull_half_spaces(canonical))
    for (const Point3& p : image) {
      const Point3 a = internal::hadamard(h.a, p);
      if (!is_zero(a)) rows.push_back(normalised(a, h.b));
      else if (sgn(h.b) < 0) return {};  // 0 <= b fails: no map at all
    }
  for (int k = 0; k < 3; ++k) {
    rows.push_back(normalised(internal::scale(axis(k), -1), 0));
    rows.push_back(normalised(axis(k), Rational(coord(X, k) / coord(P, k))));
  }
  dedupe(rows);

  // Max-slack LP; rows found tight on all of F3 become equalities until the slack is > 0.
  std::vector<bool> equality(rows.size(), false);
  std::vector<bool> warm(rows.size(), false);  // rows an earlier round's constraint generation took
  std::vector<Point3> basis;                   // a basis of the equalities' normals
  Point3 inner;
  for (;;) {
    internal::LinearProgram lp;
    lp.variables = 4;
    lp.objective = {0, 0, 0, -1};
    std::vector<std::size_t> source;  // LP row → constraint row, for the inequalities
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const HalfSpace& h = rows[i];
      if (equality[i]) {
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
    if (s.status == internal::LpStatus::infeasible) return {};
    if (s.status != internal::LpStatus::optimal)
      throw std::logic_error("feasible_set_3d: the slack LP is unbounded: a bug");
    const Rational& slack = s.x[3];
    if (sgn(slack) < 0) return {};
    inner = {s.x[0], s.x[1], s.x[2]};
    if (sgn(slack) > 0) break;
    bool grew = false;
    for (std::size_t r = 0; r < source.size(); ++r)
      if (source[r] < rows.size() && s.tight_in_every_optimum[r]) equality[source[r]] = true, grew = true;
    if (!grew) throw std::logic_error("feasible_set_3d: no implicit equality found: a bug");
    for (std::size_t r : s.rows_taken)
      if (source[r] < rows.size()) warm[source[r]] = true;
    // Every row whose normal is in the span of the equalities' normals and that holds with
    // equality at `inner` (a point of F3) holds with equality on all of F3 (a = Σλ_i·a_i gives
    // a·y = Σλ_i·b_i = a·inner = b on the equalities' flat): so when F3 is a point, every row
    // through it at once instead of a few per round (docs/math.md §1b "The exact LP").
    basis.clear();
    for (std::size_t i = 0; i < rows.size() && basis.size() < 3; ++i)
      if (equality[i] && independent_of(basis, rows[i].a)) basis.push_back(rows[i].a);
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (!equality[i] && dot(rows[i].a, inner) == rows[i].b && !independent_of(basis, rows[i].a))
        equality[i] = true;
  }
  // `basis` spans the equalities' normals: the rows just added lie in its span, and the round that
  // ends the loop adds none. Its size is their rank.

  if (basis.size() == 3) return canonical_convex_set_3(ConvexKind3::point, {inner}, {});
  if (basis.size() == 2) {
    const Point3 u = cross(basis[0], basis[1]);
    std::optional<Rational> lo, hi;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (equality[i]) continue;
      const Rational au = dot(rows[i].a, u);
      if (sgn(au) == 0) continue;
      const Rational t = (rows[i].b - dot(rows[i].a, inner)) / au;  // a·(inner + t·u) <= b
      if (sgn(au) > 0) hi = hi ? std::min(*hi, t) : t;
      else lo = lo ? std::max(*lo, t) : t;
    }
    if (!lo || !hi) throw std::logic_error("feasible_set_3d: unbounded segment: a bug");
    return canonical_convex_set_3(
        ConvexKind3::segment,
        {internal::add(inner, internal::scale(u, *lo)), internal::add(inner, internal::scale(u, *hi))}, {});
  }
  if (basis.size() == 1) {
    // In the plane n·d = c, write d_k through the other two coordinates and clip in 2-D.
    const Point3 n = basis[0];
    const Rational c = dot(n, inner);
    const int k = internal::largest_coordinate(n), i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
    const Rational& nk = coord(n, k);
    std::vector<Point2> cycle{{0, 0},
                              {Rational(coord(X, i) / coord(P, i)), 0},
                              {Rational(coord(X, i) / coord(P, i)), Rational(coord(X, j) / coord(P, j))},
                              {0, Rational(coord(X, j) / coord(P, j))}};
    for (std::size_t r = 0; r < rows.size() && !cycle.empty(); ++r) {
      if (equality[r]) continue;
      const Point3& a = rows[r].a;
      const Rational f = coord(a, k) / nk;
      cycle = internal::clip(cycle, {Rational(coord(a, i) - f * coord(n, i)),
                                     Rational(coord(a, j) - f * coord(n, j)),
                                     Rational(rows[r].b - f * c)});
    }
    const ConvexSet2 flat = canonical_convex_set(std::move(cycle));
    if (flat.kind != ConvexKind::polygon)
      throw std::logic_error("feasible_set_3d: a positive-slack plane section is not a polygon: a bug");
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

  // Full-dimensional: CGAL's dual half-space intersection around the strictly interior point.
  std::vector<Kernel::Plane_3> planes;
  for (const HalfSpace& h : rows)
    planes.emplace_back(Kernel::FT(h.a.x), Kernel::FT(h.a.y), Kernel::FT(h.a.z), Kernel::FT(-h.b));
  CGAL::Surface_mesh<KPoint3> mesh;
  CGAL::halfspace_intersection_3(planes.begin(), planes.end(), mesh,
                                 boost::optional<KPoint3>(kernel_point(inner)));
  std::vector<Point3> v;
  for (const auto& vi : mesh.vertices()) v.push_back(exact_point(mesh.point(vi)));
  v = sorted_unique(std::move(v));
  std::vector<std::vector<std::size_t>> f = facets(v, rows);
  return canonical_convex_set_3(ConvexKind3::polytope, std::move(v), std::move(f));
}

}  // namespace gmcc
