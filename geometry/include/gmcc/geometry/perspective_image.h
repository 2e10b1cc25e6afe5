#pragma once
/// \file perspective_image.h
/// The perspective image of a 3-D feasible set of diagonal maps: {(d1/d3, d2/d3) : d ∈ F3,
/// d3 > 0}, the 2-D perspective maps that 3-D CRULE's maps stand for (docs/math.md §1c).

#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/convex_set_3.h>

#include <optional>

namespace gmcc {

/// The perspective image {(d1/d3, d2/d3) : d ∈ F3, d3 > 0} of a convex set F3 in the closed
/// octant, exactly (docs/math.md §1c): the convex hull of the images of F3's vertices with
/// d3 > 0, when F3's only vertex with d3 = 0 (if any) is the origin, as when black is in the
/// canonical gamut. Empty (kind `empty`) when no point of F3 has d3 > 0 (F3 empty, {0}, or in
/// the plane d3 = 0). No value when the image is unbounded: F3 has a non-zero vertex with
/// d3 = 0 and a point with d3 > 0 (the edge between them runs off to infinity in the plane).
/// \pre every vertex of F3 has components >= 0 (a feasible set of diagonal maps).
/// \throws std::invalid_argument if a vertex has a negative component. O(|V| log |V|).
std::optional<ConvexSet2> perspective_image(const ConvexSet3& F3);

}  // namespace gmcc
