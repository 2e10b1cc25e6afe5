#pragma once
// convex_hull by CGAL::convex_hull_2 over the lazy exact kernel (Epeck), what gmcc used before
// issue 13: kept reachable for the test that compares it with the filtered monotone chain that
// replaced it, and for bench/bench_hull's exact baseline. Internal to gmcc::geometry.

#include <gmcc/geometry/convex_set.h>

#include <vector>

namespace gmcc::internal {

ConvexSet2 convex_hull_cgal(const std::vector<Point2>& points);

}  // namespace gmcc::internal
