#pragma once
/// \file worst_case.h
/// Worst-case error of a selection: the largest error it can make if the true map may be any
/// map of the feasible set (Finlayson & Hordley 1999 §4, second panel of Figs. 3–5).

#include <gmcc/geometry/convex_set.h>

namespace gmcc {

/// max_{x ∈ F} ∠((m, 1), (x, 1)) in degrees (map space).
/// The angle to a fixed m is quasi-convex on the plane, so the maximum is at a vertex of F
/// (MATH §1e): the largest vertex angle, each evaluated from the exact values as
/// map_angular_error_deg does (certified extended precision, else MPFR). \pre F not empty. Complexity O(n).
double worst_case_map_deg(const ConvexSet2& F, const Point2& m);

}  // namespace gmcc
