#pragma once
// feasible_polygon by either clipping route: the convex pass (clip_convex in feasible_set.cpp,
// what feasible_polygon runs) or Sutherland–Hodgman line after line, what it ran before issue 13
// and still runs once the cycle degenerates. The second is kept reachable for the differential
// test and the benchmark that compare the two (docs/performance-history.md, "Many-vertex canonical
// gamuts (issue 13)"). Internal to gmcc::geometry.

#include <gmcc/geometry/feasible_polygon.h>

#include <vector>

namespace gmcc::internal {

enum class Clipping { convex_pass, line_by_line };

/// feasible_polygon(canonical, image) by the given route: the same set either way.
FeasiblePolygon feasible_polygon(const CanonicalConstraints& canonical, const std::vector<Point2>& image,
                                 Clipping route);

}  // namespace gmcc::internal
