#pragma once
// A convex polytope cut from a box by closed half-spaces with integer coefficients, every
// decision exact and most of them settled by a double filter with a proven error bound
// (docs/derivations.md §4.6): the full-dimensional route of Forsyth's CRULE feasible set.
// Internal to gmcc::geometry.

#include <gmcc/geometry/lazy_convex_set_3.h>
#include <gmcc/numerics/dw_enclosure.h>

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace gmcc::internal {

// The closed half-space a·x <= b, integer coefficients.
struct IntegerPlane3 {
  mpz_class a[3];
  mpz_class b;
};

// A plane a·x <= b as double-word enclosures of a_k·2^-E and b·2^-E (E its largest coefficient's
// bit length: a positive scaling, the same plane): what the final vertices' truncated coordinates
// are decided from (internal/plane_meets.h).
using WidePlane = std::array<numerics::DWEnclosure, 4>;

// How many sign decisions each stage settled (the double filter, else exact integers).
struct ClipCounts {
  long filtered = 0;  // settled by the double filter
  long exact = 0;     // needed the exact integer evaluation
  long incident = 0;  // settled by the facets' incidences with their polytope's vertices (ClipFacets::on)
};

// What clip_polytope found: a 3-dimensional polytope or a point (in `set`, canonical form, its
// vertices made exact only on request: lazy_convex_set_3.h; a point when a half-space left one
// vertex on it and the others strictly outside, and that vertex satisfies every other row), the
// empty set,
// or a lower-dimensional non-empty set (`flat`: some half-space left no vertex strictly inside;
// its exact form is for another route, the LP one).
struct ClippedPolytope {
  enum class Outcome { polytope, empty, flat } outcome = Outcome::empty;
  LazyConvexSet3 set;
};

// A plane's filter copy: a_k·2^-E and b·2^-E (E the largest binary exponent among them), each
// truncated to 53 bits (relative error below 2u; the power-of-2 scaling keeps every sign);
// nothing when a non-zero coefficient falls below 2^-150 of the largest (docs/derivations.md §4.6).
std::optional<std::array<double, 4>> plane_filter(const IntegerPlane3& p);

// Half-spaces a·x <= b prepared once for many clips: exact, with their filter copies (each
// coefficient scaled by a common power of 2 and truncated to double, docs/derivations.md §4.6).
struct ClipFacets {
  std::vector<IntegerPlane3> planes;
  std::vector<std::array<double, 4>> filters;  // a0, a1, a2, b scaled; valid where usable
  std::vector<char> usable;
  std::vector<std::optional<WidePlane>> wide;  // double-word copies (plane_meets.h), where in range
  // When the half-spaces' points `vertices` are given (clip_facets): on[f] marks those on plane f,
  // a bitset in words of 64 (every such point is inside every half-space); empty otherwise. It
  // settles a row's side at a vertex made of three rows of the same image point without
  // arithmetic (docs/derivations.md §4.6, "Rows of one point").
  std::vector<std::vector<std::uint64_t>> on;
};
// \throws std::invalid_argument when a point of `vertices` is outside a half-space.
ClipFacets clip_facets(std::vector<IntegerPlane3> planes, const std::vector<Point3>& vertices = {});

// The intersection of the box 0 <= x_k <= box[k] (box[k] > 0) with the half-spaces
// (a ⊙ p)·x <= b for every point p of `points` (point after point) and every facet a·x <= b.
// Vertices are kept as triples of planes through them and faces as cycles of vertices
// counter-clockwise seen from outside; each half-space removes the vertices strictly outside it,
// cuts the edges that cross it and closes the cut with a new facet. A half-space's exact
// coefficients are built only when a decision or a final vertex needs them, exact homogeneous
// coordinates only for the final vertices (and lowest terms only when asked, LazyConvexSet3). `counts`, when given, adds the decisions per stage.
ClippedPolytope clip_polytope(const Point3& box, const ClipFacets& facets, const std::vector<Point3>& points,
                              ClipCounts* counts = nullptr);
// One group of rows for clip_polytope: (a ⊙ p)·x <= b for every point p and facet a·x <= b.
// `owner`, when given, keeps *facets alive (shares its ownership): then the final vertices' rows of
// this group are made exact only when a vertex's homogeneous coordinates are asked (PlaneMeets),
// from the facet and the point's integers, which the result keeps; without it, when the result
// is made.
struct ClipGroup {
  const ClipFacets* facets;
  const std::vector<Point3>* points;
  std::shared_ptr<const void> owner = nullptr;
};
// The box cut by the rows of every group at once (several gamut types' constraints on one map,
// feasible_set_3d.h): the same clip, the groups' rows one after another in the fixed order.
ClippedPolytope clip_polytope(const Point3& box, const std::vector<ClipGroup>& groups,
                              ClipCounts* counts = nullptr);
// The same for explicit half-spaces (points = {(1, 1, 1)}).
ClippedPolytope clip_polytope(const Point3& box, const std::vector<IntegerPlane3>& planes,
                              ClipCounts* counts = nullptr);

}  // namespace gmcc::internal
