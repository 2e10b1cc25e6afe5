#pragma once
// The image-hull prefilter's last step (docs/derivations.md §4.6, the image-hull prefilter): which
// colours its shifted facet copies do not certify strictly inside Q. Internal to gmcc::geometry.

#include <array>
#include <cstddef>
#include <vector>

namespace gmcc::internal {

// The indices, increasing, of the colours d[i] that are not certified strictly inside: a colour is
// certified when its channels are >= 0 and in the double range policy (numerics::in_double_range)
// and fl(fl(fl(fl(g0·p0) + fl(g1·p1)) + fl(g2·p2)) − g3) < 0 (each product and sum rounded) for
// every shifted facet g (none: every colour is
// kept). With `simd` and AVX2 at run time, four facets at a time: the same operations lane by lane
// (no fused multiply-add), so the same decisions as without (derivations.md §4.6).
std::vector<std::size_t> not_certified_inside(const std::vector<std::array<double, 4>>& shifted,
                                              const std::vector<std::array<double, 3>>& d, bool simd = true);

}  // namespace gmcc::internal
