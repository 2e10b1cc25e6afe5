#pragma once
/// \file feasible_polygon.h
/// The feasible set F of perspective diagonal maps (Finlayson & Hordley 1999 eqs. 7–9 in
/// perspective; Finlayson 1996) kept as the clipping leaves it: every vertex the meet of two
/// input lines. Its exact vertices are built only when asked for; certified floating-point
/// enclosures of them cost a few flops each. This is what lets an experiment evaluate thousands
/// of feasible sets at nearly the speed of doubles without giving up exactness
/// (docs/performance-history.md): decisions are exact, values are enclosed, and the exact set is one
/// call away.

#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/feasible_set.h>

#include <array>
#include <memory>
#include <vector>

namespace gmcc {
namespace internal {
struct FeasiblePolygonState;  // the clipped cycle and what is built from it (geometry's sources)
}  // namespace internal

/// A vertex of F as certified enclosures of its two coordinates.
struct EnclosedVertex {
  /// the vertex's coordinates m1 = d1/d3 and m2 = d2/d3, each mid ± rad
  ///@{
  Enclosure x, y;
  ///@}
};
/// The same in x87 extended precision, within a relative 2^-61 of the coordinate.
struct LongEnclosedVertex {
  /// the vertex's coordinates m1, m2, each mid ± rad in long double
  ///@{
  LongEnclosure x, y;
  ///@}
};

/// An approximate line a·x + b·y <= c: each coefficient within a relative 6·2^-53 of the same
/// positive multiple of the exact line (so the signs of a, b and c are exact).
struct ApproximateLine {
  /// the coefficients of a·x + b·y <= c (x = m1, y = m2), rounded as above
  ///@{
  double a, b, c;
  ///@}
};

/// F as a clipped cycle of input lines; default-constructed, the empty set. Its exact form and
/// exact lines are built on first use and cached in state that copies share: an object and its
/// copies must not be used by two threads at once (objects built by separate calls may).
class FeasiblePolygon {
 public:
  /// The kind of F (exact: decided by the clipping's exact predicates).
  ConvexKind kind() const;
  /// True when kind() is polygon and every vertex has a certified enclosure; then vertices()
  /// and edges() describe F, counter-clockwise, from an unspecified start.
  bool enclosed() const;
  /// Certified enclosures of F's vertices (empty unless enclosed()).
  const std::vector<EnclosedVertex>& vertices() const;
  /// The same vertices in extended precision, each within a relative 2^-61 however
  /// ill-conditioned its meet: the Cramer numerators in exact integers, then one division. Built
  /// on first use (a few µs), for thin sets where vertices() are not tight enough. Needs x87 long
  /// double with 64-bit GMP limbs at full precision; empty otherwise, or unless enclosed().
  const std::vector<LongEnclosedVertex>& extended_vertices() const;
  /// edges()[i] carries the edge from vertex i to vertex i+1 (empty unless enclosed()).
  const std::vector<ApproximateLine>& edges() const;
  /// F exactly, as feasible_set returns it (built on the first call).
  const ConvexSet2& exact() const;
  /// m ∈ F, decided exactly (a filtered side test per edge, exact arithmetic only when the
  /// filter cannot decide). Complexity O(|F|).
  bool contains(const Point2& m) const;

 private:
  internal::FeasiblePolygonState& state() const;
  std::shared_ptr<internal::FeasiblePolygonState> state_;
  friend struct internal::FeasiblePolygonAccess;
};

/// F for a prepared canonical gamut and an image (Finlayson & Hordley 1999 §2, eqs. 7–9): the
/// same clipping, decisions and preconditions as feasible_set, which is feasible_polygon(…)
/// .exact(). \throws as feasible_set.
FeasiblePolygon feasible_polygon(const CanonicalConstraints& canonical, const std::vector<Point2>& image);

/// The same for image chromaticities given by address, without copying them: for experiments
/// that draw scenes from one list of colours. The pointed-to colours must outlive the result
/// (its exact() and contains() may read them again).
FeasiblePolygon feasible_polygon(const CanonicalConstraints& canonical, const std::vector<const Point2*>& image);

}  // namespace gmcc
