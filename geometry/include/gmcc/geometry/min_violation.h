#pragma once
/// \file min_violation.h
/// A recovery policy for an empty feasible set (docs/math.md §1): the maps that violate the gamut
/// constraints least, under a stated measure — a Chebyshev ("minimax") solution of the
/// infeasible system of Forsyth's (1990) constraints, computed as an exact linear program.

#include <gmcc/geometry/convex_set.h>

#include <optional>
#include <vector>

namespace gmcc {

/// The least violation and the maps that attain it.
struct MinViolation {
  /// t* = min over maps m >= 0 (m ∈ constraint, when given) of V(m), exact, where
  ///   V(m) = max over image chromaticities q of δ(m ⊙ q, G_c),
  ///   δ(x, G) = the Chebyshev (L∞) distance from x to G when x ∉ G, and minus the Chebyshev
  ///             distance from x to the boundary of G when x ∈ G,
  /// in chromaticity units (r/b, g/b). t* > 0 exactly when F [∩ constraint] is empty.
  Rational violation;
  /// G_c ⊕ t*·[−1, 1]² (for t* < 0 the erosion): the gamut every m ⊙ q of a minimiser reaches.
  ConvexSet2 canonical;
  /// The minimisers {m : V(m) = t*} [∩ constraint]: non-empty, usually a point.
  ConvexSet2 feasible;
};

/// Chebyshev least-violation maps.
///
/// With G_c = ⋂_e {n_e·x <= k_e} over its edges and its four bounding-box half-planes
/// (supporting half-planes whose normals include the axes), G_c ⊕ t·[−1, 1]² =
/// ⋂_e {n_e·x <= k_e + t·‖n_e‖₁} (the Minkowski sum of two convex sets has the union of their
/// edge normals), so V(m) <= t ⟺ (n_e ⊙ q)·m − ‖n_e‖₁·t <= k_e for every image-hull vertex q
/// and every e. Minimising t over (m, t) with m >= 0 (and m in the constraint set) is a linear
/// program in three variables with rational data, solved exactly (CGAL's QP solver); the
/// minimisers are then the exact clip of those half-planes at t = t*.
/// \param canonical G_c, non-empty (any kind). \param image as feasible_set.
/// \param constraint optional hard constraint on m (e.g. illumination_constraint).
/// \throws as feasible_set.
/// Complexity: one LP with k·(m + 4) rows, then O(k·m·|result|) clipping.
MinViolation min_violation(const ConvexSet2& canonical, const std::vector<Point2>& image,
                           const std::optional<ConvexSet2>& constraint = {});

/// V(m) for one map, exactly, by the same half-plane formula (the measure min_violation
/// minimises). \pre canonical non-empty, image non-empty. O(k·m).
Rational gamut_violation(const ConvexSet2& canonical, const std::vector<Point2>& image,
                         const Point2& m);

}  // namespace gmcc
