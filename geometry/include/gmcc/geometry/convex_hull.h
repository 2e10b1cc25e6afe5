#pragma once
/// \file convex_hull.h
/// Exact 2-D convex hull: Andrew's monotone chain with filtered exact predicates.

#include <gmcc/geometry/convex_set.h>

#include <vector>

namespace gmcc {

/// The convex hull of a finite point set, exactly, in canonical ConvexSet2 form: a polygon,
/// or a segment (collinear input), a point (one distinct point), or empty (no points).
/// Andrew's monotone chain (Andrew 1979): the lexicographic order and every orientation are
/// decided from certified double enclosures of the coordinates when those suffice, else in exact
/// rationals; the same hull as CGAL::convex_hull_2 over an exact kernel, which it replaced for
/// speed on many-vertex inputs (docs/performance-history.md, "Many-vertex canonical gamuts (issue 13)").
/// Complexity O(n log n).
ConvexSet2 convex_hull(const std::vector<Point2>& points);

}  // namespace gmcc
