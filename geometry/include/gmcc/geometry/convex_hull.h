#pragma once
/// \file convex_hull.h
/// Exact 2-D convex hull (CGAL `convex_hull_2` over an exact kernel).

#include <gmcc/geometry/convex_set.h>

#include <vector>

namespace gmcc {

/// The convex hull of a finite point set, exactly, in canonical ConvexSet2 form: a polygon,
/// or a segment (collinear input), a point (one distinct point), or empty (no points).
/// Uses CGAL::convex_hull_2 (Akl–Toussaint + Graham–Andrew) with exact predicates.
/// Complexity O(n log n).
ConvexSet2 convex_hull(const std::vector<Point2>& points);

}  // namespace gmcc
