#pragma once
/// \file mean_3d_quadrature.h
/// The 3-D mean of Finlayson & Hordley (1999) §3.2 by deterministic quadrature.

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>

namespace gmcc {

/// The 3-D mean as the weighted planar centroid (docs/math.md §2 "Quadrature")
///   m = ∫_F (a, b) w dA / ∫_F w dA,   w = (1 + a² + b²)^-2,
/// by Duffy-collapsed n×n Gauss–Legendre on the fan triangles of F (docs/math.md §2 "Quadrature";
/// Duffy 1982): s = u, t = v(1 − u), Jacobian (1 − u). Written in offsets from the fan apex v0
/// (F's first vertex), formed exactly and rounded once, so small polygons do not
/// cancel; the apex is added back exactly and the sum rounded once (MPFR). Each fan triangle's
/// Jacobian is its exact area, rounded once; its midpoint pieces take exactly a quarter each, so
/// slivers keep their width. The rule is exact for polynomials of total degree 2n − 1; the
/// integrand is analytic near F, so the error falls geometrically in n as long as a piece is
/// small beside the distance √(1 + |x|²) to the weight's complex singularities: larger pieces
/// are split in four (graded, up to 4200 levels) until they are.
/// A segment is integrated the same way along its length with w = |(a, b, 1)|^-3 (the planar
/// fan's centroid: the bisector of docs/math.md §2); a point is itself (exact).
/// `error_bounds[k]`: the truncation estimate 2·|Q_n − Q_2n| plus a rigorous bound on both rules'
/// rounding errors (weights, node positions, row sums added with Neumaier's compensation), around the reported
/// double (docs/math.md §2 "Error statement"); the reported map is Q_n, and `correctly_rounded[k]`
/// says whether Q_n ± that statement lies in one rounding interval. Where no trustworthy
/// statement can be made (the weight leaves the long double's range, or the subdivision limit is
/// reached) the estimate is not `valid` and `note` says why. method `quadrature`,
/// `quadrature_order` = n.
/// \pre F not empty, order >= 1. Complexity O(n²·|F|) long double operations, times the
/// subdivision's pieces.
MapEstimate mean_3d_quadrature(const ConvexSet2& F, unsigned order = 12);

}  // namespace gmcc
