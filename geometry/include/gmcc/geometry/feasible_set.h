#pragma once
/// \file feasible_set.h
/// The feasible set of perspective diagonal maps (Forsyth 1990; Finlayson 1996, "Color in
/// perspective"; Finlayson & Hordley 1999 eqs. 7–9 in perspective):
///   F = { m : (m1·q1, m2·q2) ∈ G_c for every image chromaticity q } = ⋂_q (G_c ⊘ q).

#include <gmcc/geometry/convex_set.h>

#include <memory>
#include <stdexcept>
#include <vector>

namespace gmcc {

class FeasiblePolygon;
namespace internal {
struct CanonicalLines;         // the prepared lines (geometry's sources, not an interface)
struct FeasiblePolygonAccess;  // how the clipping reaches them
}  // namespace internal

/// Thrown when the image leaves a map component unconstrained (every image chromaticity has
/// r = 0, or every one has g = 0): F is then an unbounded set and no rule can select from it.
struct UnboundedFeasibleSet : std::domain_error {
  using std::domain_error::domain_error;
};

/// G_c prepared once for many feasible sets (an experiment's scenes): its half-planes as exact
/// integer lines with their floating-point filters. Immutable, so one object may serve many
/// threads.
class CanonicalConstraints {
 public:
  /// \throws std::invalid_argument if `canonical` is empty.
  explicit CanonicalConstraints(const ConvexSet2& canonical);
  /// The same, with the feasible maps further restricted to `map_constraint` (any kind; e.g.
  /// Finlayson's illumination constraint, illumination_constraint.h): feasible_set and
  /// feasible_polygon then give F ∩ C, clipped in the same pass (equal to intersection(F, C)).
  CanonicalConstraints(const ConvexSet2& canonical, const ConvexSet2& map_constraint);

 private:
  std::shared_ptr<const internal::CanonicalLines> lines_;
  friend struct internal::FeasiblePolygonAccess;
};

/// F, exactly, with its kind (polygon, segment, point or empty).
///
/// Only the vertices of the image hull constrain F, so the image hull is taken first. G_c is
/// written as half-planes n_e·x <= k_e (a degenerate G_c as pairs of opposite half-planes), and
/// each image vertex q gives the half-planes (n_e ⊙ q)·m <= k_e. These are clipped, in exact
/// rational arithmetic, from the box [0, max x / max q1] × [0, max y / max q2], which they
/// imply (Sutherland–Hodgman on closed half-planes: degenerate results are kept, not lost), or
/// from G_c ⊘ q for one image vertex q > 0 when G_c is a polygon. While the clipped cycle is
/// strictly convex, each image vertex's m half-planes, whose normals turn counter-clockwise, are
/// taken in one pass around the cycle that removes only the vertices outside each line; a
/// degenerate cycle (a segment or a point) is clipped line by line. Same set either way.
///
/// \param canonical  G_c, non-empty (any kind).
/// \param image      image chromaticities, non-empty, components >= 0.
/// \throws std::invalid_argument on empty inputs or negative components;
///         UnboundedFeasibleSet as documented above.
/// Every decision (which side of a line a vertex lies on, whether two vertices coincide) is the
/// sign of a determinant of input-line coefficients, decided in double with a rigorous error
/// bound and in exact integers only when the bound does not settle it; vertices are kept as pairs
/// of input lines and constructed exactly only at the end (docs/performance-history.md). The result is
/// the same exact set either way.
/// Complexity O(k·(m + n)) for k image-hull vertices, m canonical edges and n ≤ k·m the largest
/// intermediate cycle (docs/performance-history.md, "Many-vertex canonical gamuts (issue 13)"), after
/// the image hull.
ConvexSet2 feasible_set(const ConvexSet2& canonical, const std::vector<Point2>& image);

/// The same, with G_c prepared once.
ConvexSet2 feasible_set(const CanonicalConstraints& canonical, const std::vector<Point2>& image);

}  // namespace gmcc
