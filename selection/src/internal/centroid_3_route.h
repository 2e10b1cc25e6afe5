#pragma once
// centroid_3's certified route, reachable for the tests that compare it with the exact centroid
// (docs/derivations.md §2.4). Internal to gmcc::selection.

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/lazy_convex_set_3.h>
#include <gmcc/selection/map_estimate_3.h>

#include "internal/staged.h"

#include <optional>

namespace gmcc::internal {

/// The largest bound the certified centroid accepts, relative to each component: 2^-32 (the
/// enclosures come out near 10^-12 relative; a map off by 2^-32 moves an angular error by about
/// 10^-8 degrees).
inline constexpr double certified_centroid_relative_bound = 0x1p-32;

/// The filter: F3's tetrahedral centroid sum in double enclosures, method `certified`; nothing
/// when F3 is not a polytope, the volume is not certainly positive or a component's bound exceeds
/// certified_centroid_relative_bound of it.
std::optional<MapEstimate3> certified_centroid_filtered(const ConvexSet3& F3);
/// The same from F3's enclosures alone (lazy_convex_set_3.h): no vertex is made exact.
std::optional<MapEstimate3> certified_centroid_filtered(const LazyConvexSet3& F3);

/// How often each stage answered centroid_3's certified route, since the start (0: the filter,
/// 1: the exact centroid).
const StageCounts& certified_centroid_stage_counts();

}  // namespace gmcc::internal
