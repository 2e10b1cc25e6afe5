#pragma once
// worst_case_illuminant by each of its routes, kept reachable for the tests that compare them and
// for bench/bench_worst_case_illuminant. Every route gives the same answer, bit for bit (angle,
// location, at_vertex); they differ only in how much exact work they skip. Internal to
// gmcc::selection.

#include <gmcc/selection/worst_case_illuminant.h>

namespace gmcc::internal {

enum class IlluminantRoute {
  /// Every vertex's closeness and every edge's quartic in exact arithmetic (the definition).
  exact,
  /// Double enclosures skip vertices and edges that cannot hold the worst case (issue 13's first
  /// round, 396d073); the rest exactly, in edge order.
  double_filtered,
  /// The library's route: the double filter, then MPFI enclosures at increasing precision on what
  /// survives it, then the exact work on the survivors (docs/math.md §3).
  certified,
};

IlluminantWorstCase worst_case_illuminant(const ConvexSet2& F, const Point2& m, const Colour& canonical_illuminant,
                                          IlluminantRoute route);

}  // namespace gmcc::internal
