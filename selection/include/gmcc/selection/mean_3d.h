#pragma once
/// \file mean_3d.h
/// The 3-D mean of Finlayson & Hordley (1999) §3.2 (the paper's contribution): lift F to the
/// plane d3 = 1, take the cone of rays through it from the origin, intersect with the unit ball,
/// take the centroid of that solid and project it back to the plane.

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>

namespace gmcc {

/// Options of the closed-form route.
struct Mean3dOptions {
  /// MPFR/MPFI working precision in bits; 0 chooses it from the polygon's size
  /// (53 + 2·log2(1/ε) + guard bits, MATH §1a.7) and doubles it until the certified
  /// enclosure pins every component to better than 2^-60 relative.
  unsigned precision_bits = 0;
};

/// The 3-D mean by the closed form (method `analytic`), with a certified error bound.
///
/// With p_i = (a_i, b_i, 1) the lifted CCW vertices, c_i = p_i × p_{i+1} and
/// θ_i = atan2(|c_i|, p_i·p_{i+1}), the first moment of the solid is ¼τ with
///   τ = ½ Σ_i θ_i c_i / |c_i|          (Lambert; Arvo 1995, SIGGRAPH, eq. 9; MATH §1a.2)
/// and the map is (τ1/τ3, τ2/τ3): the centroid's direction does not depend on the ball's radius
/// (MATH §1a.1). c_i and p_i·p_{i+1} are exact rationals fed to interval arithmetic (MPFI) before
/// any rounding; the result is an enclosure, so `error_bound` is rigorous.
/// Degenerate F (SPEC §2, MATH §1a.6): a segment gives the perspective of the bisector
/// u1/|u1| + u2/|u2| of its end rays (the centroid of the planar fan ∩ unit disk); a point is
/// itself (exact). \pre F is not empty. Complexity O(n) interval operations.
MapEstimate mean_3d(const ConvexSet2& F, const Mean3dOptions& options = {});

}  // namespace gmcc
