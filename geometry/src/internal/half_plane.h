#pragma once
// Closed half-planes and exact convex clipping: the workhorse of feasible_set and of the
// centroid-clip expansion. Internal to gmcc::geometry.

#include <gmcc/geometry/convex_set.h>

#include <vector>

namespace gmcc::internal {

/// The closed half-plane { (x, y) : a·x + b·y <= c }.
struct HalfPlane {
  Rational a, b, c;
};

/// A closed convex set (non-empty, any kind) as half-planes: a polygon by its CCW edges
/// (outward normal (dy, -dx)); a segment or a point by pairs of opposite half-planes, so that
/// clipping against them keeps degenerate sets degenerate instead of losing them.
std::vector<HalfPlane> half_planes(const ConvexSet2& set);

/// Sutherland–Hodgman step: the part of a convex vertex cycle (CCW, possibly degenerate)
/// inside a closed half-plane, exactly. Vertices on the line are kept once. O(n).
std::vector<Point2> clip(const std::vector<Point2>& cycle, const HalfPlane& h);

}  // namespace gmcc::internal
