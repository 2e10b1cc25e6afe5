#pragma once
/// \file mean_2d.h
/// The 2-D mean: Barnard's mean of the feasible set in perspective, the rule Finlayson &
/// Hordley (1999) §3 compare against ("the mean of the 2-D feasible set").

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>

namespace gmcc {

/// The exact area centroid of F (gmcc::centroid): ∫_F m dA / ∫_F dA. Degenerate F: a segment
/// gives its midpoint, a point itself (docs/math.md §2). Rational, exact.
/// \pre F is not empty. Complexity O(n).
MapEstimate mean_2d(const ConvexSet2& F);

}  // namespace gmcc
