#pragma once
/// \file perspective_cone_mean.h
/// Finlayson & Hordley's (1999, §3.2) 3-D cone mean applied to the perspective image of 3-D
/// CRULE's feasible set F3: the 2-D route's selection on what F3 says about the light's
/// chromaticity (docs/math.md §1c).

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/selection/map_estimate.h>
#include <gmcc/selection/mean_3d.h>

#include <optional>

namespace gmcc {

/// mean_3d(P, options) for P = perspective_image(F3) (perspective_image.h), exact polygon,
/// segment or point; the mean then certified (or estimated) by the chosen route as in the 2-D
/// pipeline (docs/math.md §1c, §2). The estimate's rule is `cone_mean`. No value when P is
/// empty (no point of F3 with d3 > 0) or unbounded (a non-zero vertex of F3 with d3 = 0).
/// \pre F3 in the closed octant. \throws std::invalid_argument as perspective_image.
/// Cost: one hull of |F3| points and one 3-D mean.
std::optional<MapEstimate> perspective_cone_mean(const ConvexSet3& F3, const Mean3dOptions& options = {});

}  // namespace gmcc
