#pragma once
// worst_case_illuminant by each of its routes, kept reachable for the tests that compare them and
// for bench/bench_worst_case_illuminant. Every route gives the same answer, bit for bit (angle,
// location, at_vertex); they differ only in how much exact work they skip. Internal to
// gmcc::selection.

#include <gmcc/selection/worst_case_illuminant.h>

#include <cstddef>

namespace gmcc::internal {

enum class IlluminantRoute {
  /// Every vertex's closeness and every edge's quartic in exact arithmetic (the definition).
  exact,
  /// Double enclosures skip vertices and edges that cannot hold the worst case (issue 13's first
  /// round, 396d073, and the dyadic edge pieces of e97d192); the rest exactly, in edge order.
  double_filtered,
  /// The library's route: the double filter, then MPFI enclosures at increasing precision on what
  /// survives it, then the exact work on the survivors (docs/math.md §3).
  certified,
};

/// How much exact work a call did (for tests and the benchmark).
struct IlluminantRouteWork {
  std::size_t exact_vertices = 0;  ///< vertices whose closeness was computed in ℚ
  std::size_t exact_edges = 0;     ///< edges whose quartic was built in ℤ
  std::size_t sturm_edges = 0;     ///< of those, edges whose roots went through a Sturm sequence
  unsigned sine_bits = 0;          ///< the sin² filter's last precision (0: not run)
};

IlluminantWorstCase worst_case_illuminant(const ConvexSet2& F, const Point2& m, const Colour& canonical_illuminant,
                                          IlluminantRoute route, IlluminantRouteWork* work = nullptr);

}  // namespace gmcc::internal
