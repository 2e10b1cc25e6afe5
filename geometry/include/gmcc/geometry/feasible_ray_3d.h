#pragma once
/// \file feasible_ray_3d.h
/// Whether a diagonal map lies in Forsyth's 3-D feasible set up to a positive scale (Forsyth
/// 1990 §3; docs/math.md §1d "Truth in F3"): the question a benchmark asks of the true light,
/// whose map c ⊘ e is known only up to the light's intensity.

#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/geometry/convex_set_3.h>

#include <vector>

namespace gmcc {

/// Whether some positive multiple t·d (t > 0) of the map d lies in the joint feasible set F3 of
/// `constraints` (feasible_set_3d.h): whether the open ray through d meets F3. Decided exactly on
/// the rows that define F3 — (a ⊙ p)·(t·d) <= b for every canonical half-space a·x <= b of each
/// type and every vertex p of that type's image hull — as an interval of t, in integers; F3's
/// vertices are never formed, so maps with zero components in F3 (a canonical gamut with
/// vertices on the axes) change nothing. With black in every canonical gamut (b >= 0 on every
/// row) the answer is whether d satisfies every row through the origin.
/// \param constraints as feasible_set_3d. \param d a map with every component > 0.
/// \throws std::invalid_argument if d has a component <= 0, and as feasible_set_3d (an empty
///         image, a negative channel; UnboundedFeasibleSet when every colour of a type has some
///         channel 0).
/// Complexity: the image hulls (as feasible_set_3d), then O(k·f) integer dot products for k
/// image-hull vertices and f canonical half-spaces of each type; with no row b < 0 (black in every
/// gamut) only the f₀ half-spaces through the origin are read, O(k·f₀).
bool feasible_set_3d_meets_ray(const std::vector<GamutConstraint3>& constraints, const Point3& d);

}  // namespace gmcc
