#pragma once
/// \file filter_bounds.h
/// The hand-derived error constants of the floating-point filters, one name a site: each is the
/// factor k·u (u = 2^-53) that the site multiplies by its computed magnitude sum to bound the
/// error of its double evaluation, beside the sum of rounding steps n its derivation counts
/// (docs/derivations.md §4.6 and the comment at each site), so that k·u >= γ_n
/// (filtered_sign.h) leaves room. tests/numerics/test_filter_bounds.cpp checks every constant:
/// k·u >= γ_n, and on random and adversarial inputs, in each site's stated range, the exact error
/// of the site's double evaluation (in rationals) within k·u times its computed magnitude.

#include <gmcc/numerics/filtered_sign.h>

namespace gmcc::numerics::filter_bound {

/// chromaticity_hull's order of chromaticities, sign(a·d − b·c) of exact doubles: two products
/// and a difference, within 3u of |ad| + |bc| (geometry/src/chromaticity_hull.cpp).
inline constexpr double chromaticity_order = 4 * unit_roundoff;
/// chromaticity_hull's orientation of three colours' chromaticities, the 3×3 cofactor expansion
/// of exact doubles: within 8u of its magnitude sum (geometry/src/chromaticity_hull.cpp).
inline constexpr double chromaticity_orientation = 16 * unit_roundoff;
/// The image hull's order of exact points from their truncations (each within 2u): a difference
/// within 4.01u of |a| + |b| (geometry/src/image_hull.cpp).
inline constexpr double image_hull_order = 5 * unit_roundoff;
/// The image hull's orientation of exact points from their truncations: differences within
/// 3.01u, products within 6.1u, two roundings more (geometry/src/image_hull.cpp).
inline constexpr double image_hull_orientation = 12 * unit_roundoff;
/// The 2-D clip's weight sign det[(a_p, b_p); (a_q, b_q)] of lines within 6u of a positive
/// multiple of the exact ones: products within 12.01u, the evaluation 2.01u
/// (geometry/src/internal/polygon_clipper.h, weight_sign and enclose_double).
inline constexpr double clip_weight = 16 * unit_roundoff;
/// The 2-D clip's side a·m1 + b·m2 − c of a line (within 6u) at a truncated point (within 2u):
/// products within 9.01u, two additions 2.01u (polygon_clipper.h, side_of_point and box_side).
inline constexpr double clip_point_side = 16 * unit_roundoff;
/// The 2-D clip's side of the meet of two lines for a third, a 3×3 determinant of lines within
/// 6u: triple products within 18.01u, six roundings γ_6, 24.1u of the exact magnitude sum
/// (polygon_clipper.h, side_raw).
inline constexpr double clip_vertex_side = 32 * unit_roundoff;
/// The 3-D clip's homogeneous vertex X, Y, Z, W (Cramer on plane copies within 6u): sums of six
/// triple products, 18u from the inputs and five roundings, 24u of the magnitude sum
/// (docs/derivations.md §4.6; geometry/src/polytope_clip.cpp).
inline constexpr double polytope_vertex = 32 * unit_roundoff;
/// The 3-D clip's side s = a·(X, Y, Z) − b·W of a plane copy at a filtered vertex: E + (γ_4 +
/// 6.1u)(T + E) <= E + 16u(T + E) (docs/derivations.md §4.6); also the vertex's own α, β
/// (geometry/src/clip_filter.cpp).
inline constexpr double polytope_side = 16 * unit_roundoff;
/// The factor 1 + 64u that covers the evaluation of polytope_side's bound, non-negative sums
/// and products (docs/derivations.md §4.6).
inline constexpr double polytope_side_evaluation = 64 * unit_roundoff;
/// The factor 1 + 128u that covers the evaluation of the vertex's own bound max_k |a_k|·α +
/// |b|·β, fewer than twenty roundings (docs/derivations.md §4.6, "The vertex's own bound").
inline constexpr double polytope_quick_evaluation = 128 * unit_roundoff;
/// Monte Carlo mean_3d's side A·x + B·y + C·z of nearest-double coefficients (u each) at exact
/// sample doubles: three products and two sums, about 5u; also its test x² + y² + z² <= 1 of
/// exact doubles, three products and two sums (selection/src/mean_3d_monte_carlo.cpp).
inline constexpr double monte_carlo_side = 8 * unit_roundoff;

}  // namespace gmcc::numerics::filter_bound
