#pragma once
/// \file mean_3d_quadrature.h
/// The 3-D mean of Finlayson & Hordley (1999) §3.2 by deterministic quadrature.

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>

namespace gmcc {

/// The 3-D mean as the weighted planar centroid (MATH §1a.3)
///   m = ∫_F (a, b) w dA / ∫_F w dA,   w = (1 + a² + b²)^-2,
/// by Duffy-collapsed n×n Gauss–Legendre on the fan triangles of F (MATH §1c; Duffy 1982):
/// s = u, t = v(1 − u), Jacobian (1 − u). Written in offsets from the fan apex v0, which are
/// formed exactly and rounded once, so small polygons do not cancel; the apex is added back to
/// the offset centroid exactly and rounded once (MPFR). The rule is exact for polynomials of
/// total degree 2n − 1; the integrand is analytic near F, so the error falls geometrically in n
/// as long as a triangle is small beside the distance √(1 + |x|²) to the weight's complex
/// singularities: larger triangles are split in four (at most 8 levels) until it is.
/// A segment is integrated the same way along its length with w = |(a, b, 1)|^-3 (the planar
/// fan's centroid: the bisector of SPEC §2); a point is itself (exact).
/// `error_bound` is an a-posteriori estimate: 2·|Q_n − Q_2n| (the reported map is Q_n; the factor
/// covers a Q_2n that is not yet exact on wide polygons), and at least one ulp of the map. method `quadrature`, `quadrature_order` = n.
/// \pre F not empty, order >= 1. Complexity O(n²·|F|) double operations.
MapEstimate mean_3d_quadrature(const ConvexSet2& F, unsigned order = 12);

}  // namespace gmcc
