#pragma once
/// \file intersection.h
/// Exact intersection of two closed convex sets of the plane, any kinds.

#include <gmcc/geometry/convex_set.h>

namespace gmcc {

/// A ∩ B, exactly, in canonical ConvexSet2 form (polygon, segment, point or empty).
///
/// A's vertex cycle (a segment as its two ends, a point as itself) is clipped by B's closed
/// half-planes (a degenerate B as pairs of opposite half-planes), Sutherland–Hodgman on closed
/// half-planes in GMP rationals (Sutherland & Hodgman 1974; the same step as feasible_set).
/// Touching sets give the segment or point they share, not empty: nothing is regularised, unlike
/// CGAL's Boolean set operations. Used for Finlayson's (1996) illumination constraint, F ∩ C.
/// Complexity O(|A|·|B|) rational operations.
ConvexSet2 intersection(const ConvexSet2& a, const ConvexSet2& b);

}  // namespace gmcc
