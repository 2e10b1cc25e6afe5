#pragma once
/// \file mean_3d_monte_carlo.h
/// The 3-D mean of Finlayson & Hordley (1999) §3.2 by the paper's own Monte Carlo method.

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>

#include <cstdint>

namespace gmcc {

/// Fewest samples in cone ∩ ball for which a Monte Carlo mean is reported at all.
inline constexpr std::uint64_t monte_carlo_min_kept = 1000;

/// The paper's method: draw `samples` points uniformly in the positive unit cube [0,1)³ (the
/// cone over F ⊂ closed positive quadrant lies in the positive octant), keep those inside the
/// unit ball and inside the cone over F, average them, and project the mean to d3 = 1.
/// Generator: std::mt19937_64 seeded with `seed`; a coordinate is (next() >> 11)·2^-53, so the
/// same seed gives the same bytes on every platform. Cone membership is decided exactly: a
/// floating-point test with a rigorous error bound, and exact rational arithmetic when the bound
/// cannot decide. `standard_error` per component by the delta method on the ratio of means;
/// `error_bound` is the larger one (one sigma).
/// When fewer than monte_carlo_min_kept points land (a tiny F, or a segment, which has no
/// volume) the estimate is marked invalid with a note rather than returning noise; a point F is
/// itself. \pre F not empty. Complexity O(samples·|F|).
MapEstimate mean_3d_monte_carlo(const ConvexSet2& F, std::uint64_t samples, std::uint64_t seed);

}  // namespace gmcc
