#pragma once
// max_area_point's stages, reachable for the tests that compare them (Finlayson & Hordley 1999
// §3.1; docs/derivations.md §2.3). Internal to gmcc::selection.

#include <gmcc/geometry/convex_set.h>

#include "internal/staged.h"

#include <optional>

namespace gmcc::internal {

/// The filter: every candidate's m1·m2 in x87 extended-precision intervals; the unique maximum
/// when one enclosure lies strictly above all others', else nothing. Only where
/// numerics::extended_precision_active().
std::optional<Point2> max_area_filtered(const ConvexSet2& F);

/// The exact stage: the candidates' m1·m2 in ℚ, ties to the lexicographically least point.
Point2 max_area_exact(const ConvexSet2& F);

/// How often each stage answered max_area_point (0: filtered, 1: exact), since the start.
const StageCounts& max_area_stage_counts();

}  // namespace gmcc::internal
