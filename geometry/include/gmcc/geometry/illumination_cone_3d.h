#pragma once
/// \file illumination_cone_3d.h
/// The illumination constraint in 3-D (Barnard 2000; Barnard, Cardei & Funt 2002 Part I,
/// "ECRULE"; in perspective Finlayson 1996 §5, illumination_constraint.h): only the maps of
/// plausible lights are admitted. A light l is known only up to intensity, so its maps are the ray
/// through c ⊘ l, and the plausible maps are the cone K = {Σ λ_j (c ⊘ l_j) : λ_j >= 0} of the
/// plausible lights' maps; the constrained feasible set is F3 ∩ K (docs/math.md §1e).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/feasible_set_3d.h>

#include <vector>

namespace gmcc {

/// K as one more gamut type for feasible_set_3d (GamutConstraint3), exactly: the "canonical gamut"
/// conv({0} ∪ {s·d_j}) of the maps d_j = c ⊘ l_j scaled by s = max_k b_k / min_{j,k} d_jk, taken
/// with the single "image colour" (1, 1, 1) (so that its rows read d ∈ conv(...)). Every point of
/// K in the box 0 <= d <= b is Σ λ_j d_j with Σ λ_j <= max_k b_k / min_{j,k} d_jk = s, hence in the
/// truncated cone: within the box, the truncation is K itself. With b the box that bounds F3
/// (feasible_set_3d_box), F3 ∩ K = feasible_set_3d(constraints + this type), every kind exact.
/// \param lights the plausible lights l_j (camera RGB), at least one, every channel > 0.
/// \param canonical_light c, every channel > 0. \param box b, every component > 0.
/// \throws std::invalid_argument for no light, a channel <= 0, or a box component <= 0.
/// Complexity O(n log n) for n lights (one exact 3-D hull).
CanonicalConstraints3 illumination_cone_3d(const std::vector<Colour>& lights, const Colour& canonical_light,
                                           const Point3& box);

/// The colour the cone type is taken with: (1, 1, 1), for which d ⊙ (1, 1, 1) = d.
const std::vector<Colour>& illumination_cone_colour();

/// The box 0 <= d_k <= min over the types of X_k / P_k (X the largest canonical channels, P the
/// largest image channels) that holds feasible_set_3d(constraints). \throws as feasible_set_3d.
/// O(image colours).
Point3 feasible_set_3d_box(const std::vector<GamutConstraint3>& constraints);

}  // namespace gmcc
