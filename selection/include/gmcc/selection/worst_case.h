#pragma once
/// \file worst_case.h
/// Worst-case error of a selection: the largest error it can make if the true map may be any
/// map of the feasible set (Finlayson & Hordley 1999 §4, second panel of Figs. 3–5).

#include <gmcc/geometry/convex_set.h>

namespace gmcc {

/// max_{x ∈ F} ∠((m, 1), (x, 1)) in degrees (map space), for any m.
/// Where (m, 1)·(x, 1) > 0 on F (always for m >= 0 and F in the quadrant) every angle is below
/// 90° and quasi-convex in x, so the maximum is at a vertex of F (docs/derivations.md §3.1).
/// Otherwise it may lie inside an edge, at the one stationary point of the edge's cos (a linear
/// equation in the edge parameter, solved exactly). The largest of these candidates' angles, each
/// evaluated from the exact values as map_angular_error_deg does (certified extended precision,
/// else MPFR); candidates certainly below the best are skipped. \pre F not empty. Complexity O(n).
double worst_case_map_deg(const ConvexSet2& F, const Point2& m);

}  // namespace gmcc
