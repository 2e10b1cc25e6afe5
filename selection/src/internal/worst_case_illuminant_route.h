#pragma once
// worst_case_illuminant with or without its double-precision filters (the enclosures that skip
// edges and vertices which cannot change the answer, added for many-vertex feasible sets in
// issue 13). The same answer either way; the unfiltered route is kept reachable for the test
// that compares the two. Internal to gmcc::selection.

#include <gmcc/selection/worst_case_illuminant.h>

namespace gmcc::internal {

IlluminantWorstCase worst_case_illuminant(const ConvexSet2& F, const Point2& m, const Colour& canonical_illuminant,
                                          bool filtered);

}  // namespace gmcc::internal
