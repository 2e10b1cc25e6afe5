#pragma once
// The exact pieces of Forsyth's CRULE in 3-D that need CGAL (feasible_set_3d.cpp, the library's
// 3-D CGAL translation unit), behind plain interfaces: the canonical gamut's half-spaces, an
// exact 3-D hull's vertices, and the LP route for F3 (docs/math.md §1b "The exact LP"), which
// the prepared route (feasible_set_3d_prepared.cpp) keeps for the degenerate kinds and which the
// tests' oracle (tests/support/cgal_references.h, feasible_set_3d_reference) is built on.
// Internal to gmcc::geometry.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/convex_set_3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace gmcc::internal {

// The closed half-space a·x <= b, normalised so the first non-zero |a_k| is 1 (a unique key).
struct HalfSpace3 {
  Point3 a;
  Rational b;
};

// Whether x is an integer in [0, 2^16) (a pixel value): where the image hull's filter planes are
// exact in double (feasible_set_3d_prepared.cpp) and its predicates exact in 64-bit integers
// (small_integer_hull.h).
inline bool small_integer(double x) { return x >= 0 && x < 0x1p16 && x == std::floor(x); }

// The points sorted (lexicographically), without repeats.
std::vector<Point3> sorted_unique(std::vector<Point3> p);

// std::invalid_argument naming the `what` colours (canonical, image) when there are none or a
// channel is negative: feasible_set_3d's input checks. Defined with the prepared route.
void check_colours(const std::vector<Colour>& cs, const char* what);

// The dimension of the affine hull of a non-empty point set: 0 to 3.
int affine_dimension(const std::vector<Point3>& points);

// conv(points) as closed half-spaces, any dimension (an equality as a pair of opposite
// half-spaces); sorted, without repeats. \pre points non-empty, sorted, without repeats.
std::vector<HalfSpace3> hull_half_spaces_3(const std::vector<Point3>& points);

// conv(points) of points spanning 3-D: its facets as hull_half_spaces_3 gives them and its
// vertices as extreme_points_3 does, from one hull. \pre points sorted, without repeats, spanning
// 3-D.
struct HullFacets3 {
  std::vector<HalfSpace3> half_spaces;  // sorted, without repeats
  std::vector<Point3> vertices;         // sorted
};
HullFacets3 hull_facets_and_vertices_3(const std::vector<Point3>& points);

// The vertices of conv(points) (CGAL::convex_hull_3 over Epeck), sorted; all of `points` when
// they are flat. \pre points non-empty, sorted, without repeats.
std::vector<Point3> extreme_points_3(const std::vector<Point3>& points);
// The indices (into `points`, among `candidates`) of the distinct vertices of conv(candidates),
// in increasing lexicographic order of the points; every distinct candidate when they are flat.
// Points are doubles taken exactly (CGAL's Epick: exact predicates on double input).
std::vector<std::size_t> extreme_point_indices_3(const std::vector<std::array<double, 3>>& points,
                                                 const std::vector<std::size_t>& candidates);
// The triangles of conv(points[i], i in `indices`) as index triples (into `points`), each
// counter-clockwise seen from outside; empty when those points span fewer than 3 dimensions.
// Doubles taken exactly (Epick's exact predicates; the triangles' corners are input points).
std::vector<std::array<std::size_t, 3>> hull_triangles_3(const std::vector<std::array<double, 3>>& points,
                                                        const std::vector<std::size_t>& indices);

// One gamut type's rows for the LP route: its canonical half-spaces, X (the largest canonical
// channels) and image points (any superset of the image hull's vertices).
struct LpPart {
  const std::vector<HalfSpace3>* canonical;
  const Point3* canonical_max;
  const std::vector<Point3>* image;
};
// F3 by the exact LP route over every part's rows at once: rows (a ⊙ p)·d <= b for every
// canonical half-space and image point p, the box 0 <= d_k <= X_k/P_k (each part's, so their
// intersection), the max-slack LP for the equalities, then CGAL::halfspace_intersection_3 or the
// lower-dimensional constructions. \pre parts non-empty; each image non-empty with every P_k > 0.
ConvexSet3 feasible_set_3d_lp(const std::vector<LpPart>& parts);

}  // namespace gmcc::internal
