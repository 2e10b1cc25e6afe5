#pragma once
/// \file max_area.h
/// Max-area selection: the map that makes the corrected image as colourful as possible.
/// Forsyth (1990) §4 (maximum-volume map, CRULE-MV) in Finlayson's (1996) perspective form:
/// argmax m1·m2 over the feasible set F. Finlayson & Hordley (1999) §3, first rule.

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>

namespace gmcc {

/// argmax_{m ∈ F} m1·m2, exactly (docs/derivations.md §2).
///
/// m1·m2 is strictly log-concave on the open quadrant, so the maximiser is unique and lies on
/// the north-east chain of ∂F: it is a vertex or the stationary point
/// t* = −(Δa·p_b + Δb·p_a) / (2·Δa·Δb) of an edge with Δa·Δb < 0 (the midpoint of the edge
/// line's axis intercepts). All candidates are compared exactly in ℚ.
/// Degenerate F: a segment by the same rule, a point is itself. Ties (only possible when F
/// touches an axis, where m1·m2 = 0) go to the lexicographically smallest candidate.
/// \pre F is not empty, with components >= 0. Complexity O(n).
Point2 max_area_point(const ConvexSet2& F);

/// max_area_point as a MapEstimate (rule `max_area`, method `exact`).
MapEstimate max_area(const ConvexSet2& F);

}  // namespace gmcc
