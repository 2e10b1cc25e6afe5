// Forsyth's CRULE feasible set in 3-D from a prepared canonical gamut (docs/math.md §1b "The
// prepared route", docs/derivations.md §4.6): image hull first, then the filtered exact clip of
// polytope_clip.cpp; the CGAL pieces and the LP route are behind internal/crule_exact.h.
#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/geometry/colour_hull_sieve.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_ray_3d.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/geometry/illumination_cone_3d.h>
#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/numerics/rational_to_float.h>
#include <gmcc/numerics/filtered_sign.h>

#include "internal/crule_exact.h"
#include "internal/lazy_rows.h"
#include "internal/polytope_clip.h"
#include "internal/shifted_sieve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

namespace gmcc {
namespace internal {

struct CanonicalPlanes3 {
  int dimension = 0;
  std::vector<HalfSpace3> half_spaces;   // exact, for the LP route
  ClipFacets integer;                    // the same with integer coefficients (dimension 3)
  Point3 max{0, 0, 0};                   // X: the largest canonical channels
};

struct FeasibleSet3Access {
  static const CanonicalPlanes3& planes(const CanonicalConstraints3& c) { return *c.planes_; }
  // What keeps planes(c) alive (ClipGroup::owner).
  static std::shared_ptr<const void> owner(const CanonicalConstraints3& c) { return c.planes_; }
};

std::vector<Point3> sorted_unique(std::vector<Point3> p) {
  // Sorted by index, then permuted in place by swaps: moving a Rational allocates (gmpxx's
  // mpq_class move constructor initialises the source), swapping does not.
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
  for (std::size_t k = 0; k < order.size(); ++k) {  // p[k] = the old p[order[k]]
    std::size_t j = order[k];
    while (j < k) j = order[j];  // where the old p[order[k]] was moved to
    if (j != k) p[k].x.swap(p[j].x), p[k].y.swap(p[j].y), p[k].z.swap(p[j].z);
  }
  p.erase(std::unique(p.begin(), p.end()), p.end());
  return p;
}

void check_colours(const std::vector<Colour>& cs, const char* what) {
  if (cs.empty()) throw std::invalid_argument(std::string("feasible_set_3d: no ") + what + " colours");
  for (const Colour& c : cs)
    if (sgn(c.r) < 0 || sgn(c.g) < 0 || sgn(c.b) < 0)
      throw std::invalid_argument(std::string("feasible_set_3d: a negative ") + what + " channel");
}

namespace {

// (a·L, b·L) with L the lcm of the denominators of a and b: the same half-space, integers.
IntegerPlane3 integer_plane(const HalfSpace3& h) {
  const mpz_class l = lcm_of_denominators_of(h.a.x, h.a.y, h.a.z, h.b);
  IntegerPlane3 p{{times_lcm(h.a.x, l), times_lcm(h.a.y, l), times_lcm(h.a.z, l)}, times_lcm(h.b, l)};
  // Divided by the coefficients' gcd (once per gamut): every row and vertex built from it is
  // smaller.
  divide_by_content_of(p.a[0], p.a[1], p.a[2], p.b);
  return p;
}

// --- The image hull, filtered (docs/math.md §1b "The prepared route") --------------------------

// Below this many colours the image hull is left to CGAL's exact hull directly.
constexpr std::size_t prefilter_from = 64;
constexpr double u = numerics::unit_roundoff;

// Whether every channel is an integer in [0, 2^16) (pixel values): then planes through three
// such points have integer coefficients below 2^33 and offsets below 2^51 in magnitude, and a
// point's signed distance below 2^52: all exact in double.
bool small_integers(const std::vector<std::array<double, 3>>& d) {
  for (const auto& c : d)
    for (double x : c)
      if (!small_integer(x)) return false;
  return true;
}

// The indices of the colours extreme along the 26 directions (colour_hull_sieve.h), increasing.
std::vector<std::size_t> extreme_indices(const std::vector<std::array<double, 3>>& d) {
  ExtremeColours extremes;
  for (std::size_t i = 0; i < d.size(); ++i) extremes.add(i, d[i]);
  return extremes.indices();
}

// The indices of colours not strictly inside Q = conv(d[i], i in `extreme`), exactly, for small
// integer colours (ColourHullSieve). When Q is flat every index is kept.
// (On 64 × 64 photographs about 2,600 colours leave ~630 for the exact hull; a second round with
// a Q from 98 directions cost as much as it saved.)
std::vector<std::size_t> outside_small_hull(const std::vector<std::array<double, 3>>& d,
                                            const std::vector<std::size_t>& extreme) {
  std::vector<std::array<double, 3>> corners;
  for (std::size_t i : extreme) corners.push_back(d[i]);
  const ColourHullSieve sieve(corners);
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < d.size(); ++i)
    if (!sieve.strictly_inside(d[i])) out.push_back(i);
  return out;
}

// The colours that may be vertices of their hull, by index: a handful of extreme colours (the
// largest along 26 directions in double) span a polytope Q ⊆ hull; a colour certified strictly
// inside every facet of Q by a double filter is no vertex and is dropped; all others are kept.
// `d` holds each colour's channels as doubles within 2u relative of the exact ones (exact for
// double input, and then `doubles_exact`), `exact(i)` the exact colour. Small integer colours
// take outside_small_hull.
template <class Exact>
std::vector<std::size_t> hull_candidate_indices(const std::vector<std::array<double, 3>>& d, Exact exact,
                                                bool doubles_exact) {
  const std::vector<std::size_t> extreme = extreme_indices(d);
  if (doubles_exact && small_integers(d)) return outside_small_hull(d, extreme);
  std::vector<Point3> q;
  for (std::size_t i : extreme) q.push_back(exact(i));
  q = sorted_unique(std::move(q));
  std::vector<std::array<double, 4>> facets;
  if (affine_dimension(q) == 3)
    for (const HalfSpace3& h : hull_half_spaces_3(q)) {
      // Scaled as the clip's planes (plane_filter): relative error below 2u, coefficients in
      // [2^-150, 1] or 0; if a facet does not fit, Q certifies nothing and every colour is kept.
      const std::optional<std::array<double, 4>> f = plane_filter(integer_plane(h));
      if (!f) {
        facets.clear();
        break;
      }
      facets.push_back(*f);
    }
  // Each facet copy f moved outwards by 16u of each coefficient's magnitude (16u·|f_k| is exact:
  // a power of 2 times a normal double): g_k = fl(f_k + 16u|f_k|), h = fl(f_3 − 16u|f_3|). For a
  // colour with channels >= 0, fl(g·d − h) < 0 certifies s = a·p − b < 0 with one dot product
  // (docs/derivations.md §4.6, the image-hull prefilter: the shift is at least 14.9u·T, the
  // evaluation's and the inputs' errors at most 8.1u·T, T = Σ|f_k|·d_k + |f_3|).
  std::vector<std::array<double, 4>> shifted;
  for (const std::array<double, 4>& f : facets)
    shifted.push_back({f[0] + 16 * u * std::fabs(f[0]), f[1] + 16 * u * std::fabs(f[1]),
                       f[2] + 16 * u * std::fabs(f[2]), f[3] - 16 * u * std::fabs(f[3])});
  // Colours with magnitudes where the relative bound holds and channels >= 0 (shifted_sieve.h).
  return not_certified_inside(shifted, d);
}

std::vector<Point3> hull_candidates(const std::vector<Colour>& image) {
  std::vector<std::array<double, 3>> d(image.size());
  for (std::size_t i = 0; i < image.size(); ++i)  // mpq_get_d truncates: relative error below 2u
    d[i] = {mpq_get_d(image[i].r.get_mpq_t()), mpq_get_d(image[i].g.get_mpq_t()),
            mpq_get_d(image[i].b.get_mpq_t())};
  const auto exact = [&](std::size_t i) { return Point3{image[i].r, image[i].g, image[i].b}; };
  bool integers = true;  // then the truncated doubles are the channels (below 2^53)
  for (std::size_t i = 0; i < image.size() && integers; ++i)
    integers = image[i].r.get_den() == 1 && image[i].g.get_den() == 1 && image[i].b.get_den() == 1;
  std::vector<Point3> out;
  for (std::size_t i : hull_candidate_indices(d, exact, integers)) out.push_back(exact(i));
  return out;
}

// Throws UnboundedFeasibleSet when a channel of P, the image's largest channels, is 0 (that map
// component is unconstrained).
void require_bounded(const Point3& P) {
  for (int k = 0; k < 3; ++k)
    if (sgn(coord(P, k)) == 0)
      throw UnboundedFeasibleSet(std::string("every image colour has ") + "rgb"[k] +
                                 " = 0: that map component is unconstrained and the feasible "
                                 "set is unbounded");
}

// The box 0 <= d_k <= X_k/P_k of one type (X its canonical gamut's largest channels, P its image's)
// met with `box`, the smallest over the types so far. \throws as require_bounded.
void shrink_box(std::optional<Point3>& box, const CanonicalPlanes3& c, const Point3& P) {
  require_bounded(P);
  const Point3 b{Rational(c.max.x / P.x), Rational(c.max.y / P.y), Rational(c.max.z / P.z)};
  if (!box) box = b;
  else
    for (int k = 0; k < 3; ++k) coord(*box, k) = std::min(coord(*box, k), coord(b, k));
}

// Below this many colours every distinct colour is kept: a colour that is no hull vertex gives
// only rows implied by the others (F3 is the same set), and the clip dismisses each such row in
// one box test or one pass over the vertices, which costs less than an exact hull.
constexpr std::size_t hull_from = 32;

// The image points that matter: the vertices of their hull (all of them when it is flat), or
// every distinct colour of a small image or of one whose colours are its hull's vertices already.
std::vector<Point3> image_points(const std::vector<Colour>& image, bool hull_vertices) {
  check_colours(image, "image");
  std::vector<Point3> p;
  if (hull_vertices) {
    p.reserve(image.size());
    for (const Colour& c : image) p.push_back({c.r, c.g, c.b});
    return sorted_unique(std::move(p));
  }
  if (image.size() >= prefilter_from) p = hull_candidates(image);
  else {
    p.reserve(image.size());
    for (const Colour& c : image) p.push_back({c.r, c.g, c.b});
  }
  p = sorted_unique(std::move(p));
  return image.size() < hull_from ? p : extreme_points_3(p);
}

// The extreme points of sorted, distinct, flat points (affinely at most 2-dimensional): the one
// point, a segment's ends (lexicographic order is monotone along a line), or the vertices of the
// exact 2-D hull of a projection onto a coordinate plane that keeps the points' plane 2-dimensional
// (then the projection is one to one on that plane). Sorted.
std::vector<Point3> flat_extreme_points(const std::vector<Point3>& p) {
  const int dimension = affine_dimension(p);
  if (dimension <= 0) return p;
  if (dimension == 1) return {p.front(), p.back()};
  for (int drop = 2; drop >= 0; --drop) {
    std::map<Point2, const Point3*> back;
    std::vector<Point2> projected;
    for (const Point3& q : p) {
      const Point2 x = drop == 0 ? Point2{q.y, q.z} : drop == 1 ? Point2{q.x, q.z} : Point2{q.x, q.y};
      projected.push_back(x);
      back.emplace(x, &q);
    }
    const ConvexSet2 hull = convex_hull(projected);
    if (hull.kind != ConvexKind::polygon) continue;
    std::vector<Point3> out;
    for (const Point2& v : hull.vertices) out.push_back(*back.at(v));
    return sorted_unique(std::move(out));
  }
  return p;  // not reached: a plane projects onto some coordinate plane one to one
}

// The hull's vertices always (colour_hull_vertices): the same filter, then the exact hull; flat
// colours' own extreme points.
std::vector<Point3> hull_vertices(const std::vector<Colour>& colours) {
  if (colours.empty()) throw std::invalid_argument("colour_hull_vertices: no colours");
  for (const Colour& c : colours)
    if (sgn(c.r) < 0 || sgn(c.g) < 0 || sgn(c.b) < 0)
      throw std::invalid_argument("colour_hull_vertices: a negative channel");
  std::vector<Point3> p;
  if (colours.size() >= prefilter_from) p = hull_candidates(colours);
  else
    for (const Colour& c : colours) p.push_back({c.r, c.g, c.b});
  p = extreme_points_3(sorted_unique(std::move(p)));
  return affine_dimension(p) < 3 ? flat_extreme_points(p) : p;
}

}  // namespace
}  // namespace internal

CanonicalConstraints3::CanonicalConstraints3(const std::vector<Colour>& canonical, CanonicalBlack black) {
  internal::check_colours(canonical, "canonical");
  auto c = std::make_shared<internal::CanonicalPlanes3>();
  std::vector<Point3> pts;
  for (const Colour& x : canonical) pts.push_back({x.r, x.g, x.b});
  if (black == CanonicalBlack::include) pts.push_back({0, 0, 0});
  pts = internal::sorted_unique(std::move(pts));
  for (const Point3& p : pts) {
    c->max.x = std::max(c->max.x, p.x);
    c->max.y = std::max(c->max.y, p.y);
    c->max.z = std::max(c->max.z, p.z);
  }
  c->dimension = internal::affine_dimension(pts);
  if (c->dimension == 3) {
    // The facets and the vertices from one hull.
    internal::HullFacets3 hull = internal::hull_facets_and_vertices_3(pts);
    c->half_spaces = std::move(hull.half_spaces);
    std::vector<internal::IntegerPlane3> planes;
    for (const internal::HalfSpace3& h : c->half_spaces) planes.push_back(internal::integer_plane(h));
    // With G_c3's vertices: the rows of one image point then settle some sides without arithmetic.
    c->integer = internal::clip_facets(std::move(planes), hull.vertices);
  } else {
    c->half_spaces = internal::hull_half_spaces_3(pts);
  }
  planes_ = std::move(c);
}

int CanonicalConstraints3::dimension() const { return planes_->dimension; }
std::size_t CanonicalConstraints3::half_spaces() const { return planes_->half_spaces.size(); }

ConvexSet3 feasible_set_3d(const CanonicalConstraints3& canonical, const std::vector<Colour>& image) {
  return feasible_set_3d(std::vector<GamutConstraint3>{{&canonical, &image}});
}

ConvexSet3 feasible_set_3d(const std::vector<GamutConstraint3>& constraints) {
  return feasible_set_3d_lazy(constraints).exact();
}

LazyConvexSet3 feasible_set_3d_lazy(const std::vector<GamutConstraint3>& constraints) {
  if (constraints.empty()) throw std::invalid_argument("feasible_set_3d: no gamut constraint");
  std::vector<std::vector<Point3>> points;
  std::optional<Point3> box;  // the smallest X_k/P_k over the types
  bool all_full = true;       // every G_c3 3-dimensional: the filtered clip applies
  for (const GamutConstraint3& g : constraints) {
    const internal::CanonicalPlanes3& c = internal::FeasibleSet3Access::planes(*g.canonical);
    points.push_back(internal::image_points(*g.image, g.hull_vertices));
    Point3 P{0, 0, 0};
    for (const Point3& p : points.back()) P.x = std::max(P.x, p.x), P.y = std::max(P.y, p.y), P.z = std::max(P.z, p.z);
    internal::shrink_box(box, c, P);
    all_full = all_full && c.dimension == 3;
  }
  if (all_full) {
    std::vector<internal::ClipGroup> groups;
    for (std::size_t i = 0; i < constraints.size(); ++i)
      groups.push_back({&internal::FeasibleSet3Access::planes(*constraints[i].canonical).integer, &points[i],
                        internal::FeasibleSet3Access::owner(*constraints[i].canonical)});
    std::size_t rows = 0;
    for (const internal::ClipGroup& g : groups) rows += g.facets->planes.size() * g.points->size();
    // Many rows (edge colours at large σ: ~1000 hull points): generated lazily, the same set.
    internal::ClippedPolytope r = rows >= internal::lazy_rows_from ? internal::clip_polytope_lazy_rows(*box, groups)
                                                                   : internal::clip_polytope(*box, groups);
    if (r.outcome == internal::ClippedPolytope::Outcome::polytope) return std::move(r.set);
    if (r.outcome == internal::ClippedPolytope::Outcome::empty) return LazyConvexSet3();
  }
  std::vector<internal::LpPart> parts;
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const internal::CanonicalPlanes3& c = internal::FeasibleSet3Access::planes(*constraints[i].canonical);
    parts.push_back({&c.half_spaces, &c.max, &points[i]});
  }
  return LazyConvexSet3(internal::feasible_set_3d_lp(parts));
}

namespace {

// The feasible t > 0 of rows t·k <= b, as fractions compared by cross-multiplication (every
// denominator > 0): the least upper bound and the greatest lower bound seen, and whether a row
// already refused every t > 0.
struct RayInterval {
  mpz_class hi_num, hi_den;  // hi_den = 0: no upper bound yet
  mpz_class lo_num = 0, lo_den = 1;  // t > lo (strict while lo = 0, the ray's origin)
  bool lo_strict = true;
  bool empty = false;

  // t·k <= b.
  void add(const mpz_class& k, const mpz_class& b) {
    const int sk = sgn(k);
    if (sk == 0) {
      empty = empty || sgn(b) < 0;
    } else if (sk > 0) {  // t <= b/k
      if (sgn(b) <= 0) empty = true;
      else if (sgn(hi_den) == 0 || b * hi_den < hi_num * k) hi_num = b, hi_den = k;
    } else if (sgn(b) < 0) {  // t >= b/k = (-b)/(-k) > 0
      const mpz_class n = -b, d = -k;
      if (n * lo_den > lo_num * d || (lo_strict && n * lo_den == lo_num * d))
        lo_num = n, lo_den = d, lo_strict = false;
    }  // k < 0 and b >= 0: every t > 0
  }
  bool meets() const {
    if (empty) return false;
    if (sgn(hi_den) == 0) return true;
    const mpz_class l = lo_num * hi_den, h = hi_num * lo_den;
    return lo_strict ? l < h : l <= h;
  }
};

}  // namespace

bool feasible_set_3d_meets_ray(const std::vector<GamutConstraint3>& constraints, const Point3& d) {
  if (constraints.empty()) throw std::invalid_argument("feasible_set_3d_meets_ray: no gamut constraint");
  if (sgn(d.x) <= 0 || sgn(d.y) <= 0 || sgn(d.z) <= 0)
    throw std::invalid_argument("feasible_set_3d_meets_ray: the map needs every component > 0");
  // D: a positive integer multiple of d (the same ray).
  const mpz_class ld = lcm_of_denominators_of(d.x, d.y, d.z);
  const mpz_class D[3] = {times_lcm(d.x, ld), times_lcm(d.y, ld), times_lcm(d.z, ld)};
  RayInterval t;
  // Without a row b < 0 (every canonical gamut holds black, say) no t > 0 has a lower bound, so
  // the rows with b > 0 (upper bounds, all positive) cannot empty the interval: only the rows
  // through the origin (b = 0) are read, k <= 0 on each.
  bool lower_bounds = false;
  for (const GamutConstraint3& g : constraints)
    for (const internal::HalfSpace3& h : internal::FeasibleSet3Access::planes(*g.canonical).half_spaces)
      lower_bounds = lower_bounds || sgn(h.b) < 0;
  for (const GamutConstraint3& g : constraints) {
    const internal::CanonicalPlanes3& c = internal::FeasibleSet3Access::planes(*g.canonical);
    const std::vector<Point3> points = internal::image_points(*g.image, g.hull_vertices);
    Point3 P{0, 0, 0};  // as feasible_set_3d: every colour 0 in a channel leaves F3 unbounded
    for (const Point3& p : points) P.x = std::max(P.x, p.x), P.y = std::max(P.y, p.y), P.z = std::max(P.z, p.z);
    internal::require_bounded(P);
    std::vector<internal::IntegerPlane3> own;  // the prepared integer planes exist in 3-D only
    if (c.dimension != 3)
      for (const internal::HalfSpace3& h : c.half_spaces) own.push_back(internal::integer_plane(h));
    const std::vector<internal::IntegerPlane3>& planes = c.dimension == 3 ? c.integer.planes : own;
    for (const Point3& p : points) {
      // The row (a ⊙ p)·(t·d) <= b times L·ld (L the lcm of p's denominators): t·(a·q) <= L·ld·b
      // with q = (L·p) ⊙ D, integers.
      const mpz_class L = lcm_of_denominators_of(p.x, p.y, p.z);
      const mpz_class q[3] = {times_lcm(p.x, L) * D[0], times_lcm(p.y, L) * D[1], times_lcm(p.z, L) * D[2]};
      const mpz_class scale = L * ld;
      for (const internal::IntegerPlane3& h : planes) {
        if (!lower_bounds && sgn(h.b) > 0) continue;
        const mpz_class k = h.a[0] * q[0] + h.a[1] * q[1] + h.a[2] * q[2];
        t.add(k, h.b * scale);
        if (t.empty) return false;
      }
    }
  }
  return t.meets();
}

Point3 feasible_set_3d_box(const std::vector<GamutConstraint3>& constraints) {
  if (constraints.empty()) throw std::invalid_argument("feasible_set_3d: no gamut constraint");
  std::optional<Point3> box;
  for (const GamutConstraint3& g : constraints) {
    internal::check_colours(*g.image, "image");
    const internal::CanonicalPlanes3& c = internal::FeasibleSet3Access::planes(*g.canonical);
    Point3 P{0, 0, 0};
    for (const Colour& p : *g.image) P.x = std::max(P.x, p.r), P.y = std::max(P.y, p.g), P.z = std::max(P.z, p.b);
    internal::shrink_box(box, c, P);
  }
  return *box;
}

std::vector<std::size_t> colour_hull_vertex_indices(const std::vector<std::array<double, 3>>& colours) {
  if (colours.empty()) throw std::invalid_argument("colour_hull_vertex_indices: no colours");
  for (const auto& c : colours)
    for (double x : c)
      if (!(x >= 0) || !std::isfinite(x))
        throw std::invalid_argument("colour_hull_vertex_indices: a channel that is negative or not finite");
  const auto exact = [&](std::size_t i) {
    return Point3{Rational(colours[i][0]), Rational(colours[i][1]), Rational(colours[i][2])};
  };
  std::vector<std::size_t> candidates;
  if (colours.size() >= internal::prefilter_from) {
    candidates = internal::hull_candidate_indices(colours, exact, true);
  } else {
    candidates.resize(colours.size());
    for (std::size_t i = 0; i < colours.size(); ++i) candidates[i] = i;
  }
  std::vector<std::size_t> out = internal::extreme_point_indices_3(colours, candidates);
  std::vector<Point3> points;
  for (std::size_t i : out) points.push_back(exact(i));
  if (internal::affine_dimension(points) == 3) return out;
  // Flat colours: their own extreme points (as colour_hull_vertices), by index.
  const std::vector<Point3> extreme = internal::flat_extreme_points(internal::sorted_unique(points));
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < out.size(); ++k)
    if (std::binary_search(extreme.begin(), extreme.end(), points[k])) kept.push_back(out[k]);
  return kept;
}

std::vector<Colour> colour_hull_vertices(const std::vector<Colour>& colours) {
  std::vector<Colour> out;
  for (Point3& p : internal::hull_vertices(colours)) out.push_back({std::move(p.x), std::move(p.y), std::move(p.z)});
  return out;
}

ConvexSet3 feasible_set_3d(const std::vector<Colour>& canonical, const std::vector<Colour>& image,
                           CanonicalBlack black) {
  return feasible_set_3d(CanonicalConstraints3(canonical, black), image);
}

}  // namespace gmcc
