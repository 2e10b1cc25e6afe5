#pragma once
/// \file mean_3d_analytic.h
/// The 3-D mean of Finlayson & Hordley (1999) §3.2 by its closed form: lift F to the plane
/// d3 = 1, take the cone of rays through it from the origin, intersect with the unit ball, take
/// the centroid of that solid and project it back to the plane.

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>

namespace gmcc {

/// Options of the closed-form route.
struct AnalyticOptions {
  /// Working precision in bits, forced; 0 (the default) chooses it: first double-word
  /// enclosures with proven bounds (Joldes, Muller & Popescu 2017; docs/math.md "The double-word
  /// stage"; reported as 106 bits), then a rigorous interval evaluation in x87 extended precision (from the vertices, then from exactly formed edge
  /// vectors), kept when each component's enclosure rounds to a single double; otherwise MPFI at
  /// 53 + 40 + 2·log2(1/ε) bits for a polygon of angular width ε (docs/math.md §2), doubled
  /// until each component's enclosure rounds to a single double, up to max(8192, 4 × the start)
  /// bits (docs/math.md §2 "Correct rounding").
  unsigned precision_bits = 0;
};

/// The 3-D mean by the closed form (method `analytic`), with a certified error bound.
///
/// With p_i = (a_i, b_i, 1) the lifted vertices in order, c_i = p_i × p_{i+1} and
/// θ_i = atan2(|c_i|, p_i·p_{i+1}), the solid's first moment is ¼τ with
///   τ = ½ Σ_i θ_i c_i / |c_i|          (Lambert; Arvo 1995, SIGGRAPH; docs/derivations.md §1.2)
/// and the map is (τ1/τ3, τ2/τ3): the direction depends neither on the ball's radius nor on the
/// orientation (docs/derivations.md §1.1, §1.4). c_i and p_i·p_{i+1} are exact rationals, enclosed
/// before any rounding; the result is an enclosure, so `error_bounds` are rigorous (the
/// extended-precision fast path relies on the x87 fpatan's < 1 ulp error and allows 4 ulps), and
/// `map` is, per component, the correctly rounded double (`correctly_rounded`; false only at the
/// precision cap or a forced precision, with a `note`).
/// Degenerate F (docs/math.md §2, docs/derivations.md §1.5): a segment gives the perspective of the
/// bisector u1/|u1| + u2/|u2| of its end rays (the centroid of the planar fan ∩ unit disk); a point
/// is itself (exact). A forced precision too low to bound the quotient within the doubles (τ3's
/// enclosure holding 0, or nearly) gives an estimate that is not `valid`, with a note; the
/// automatic precision doubles until it is tight instead.
/// \pre F is not empty. Complexity O(n) interval operations.
MapEstimate mean_3d_analytic(const ConvexSet2& F, const AnalyticOptions& options = {});

}  // namespace gmcc
