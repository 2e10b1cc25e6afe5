#pragma once
/// \file max_volume.h
/// Forsyth's (1990) CRULE-MV selection: the map that makes the corrected image as colourful as
/// possible, argmax d1·d2·d3 over the 3-D feasible set (docs/derivations.md §2.4).

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/lazy_convex_set_3.h>
#include <gmcc/selection/map_estimate_3.h>

namespace gmcc {

/// argmax_{d ∈ F3} d1·d2·d3, certified (docs/derivations.md §2.4).
///
/// log(d1·d2·d3) is strictly concave on the open octant, so the maximiser is unique (when the
/// maximum is > 0). It is a vertex; or, on a facet (or the polygon's plane) n·d = k whose
/// stationary point d* = (k/(3n1), k/(3n2), k/(3n3)) is positive and inside it, d*; or on an edge
/// d(t) = p + t(q − p), a root in (0, 1) of the quadratic f'(t) of the cubic f(t) = Π d_k(t).
/// Vertex and facet candidates are rational; edge roots are rational when the discriminant is a
/// square and quadratic irrationals otherwise. Rational candidates are compared exactly; the
/// irrational ones are enclosed in MPFI at doubling precision (from 128 bits) until one candidate
/// is separated from all others — which happens, because the maximiser is unique and an
/// irrational edge point equals no other candidate. Method `exact` or `certified`.
/// When the product is 0 on all of F3 (F3 in a coordinate plane) every point ties and the
/// lexicographically smallest vertex is returned, as max_area does.
/// \pre F3 not empty, components >= 0. Complexity O(|F3|) candidates.
MapEstimate3 max_volume(const ConvexSet3& F3);
/// The same on F3 with vertices made exact on request (lazy_convex_set_3.h): the filter reads the
/// enclosures, the exact stage makes only the vertices of the candidates it compares. Equal to
/// max_volume(F3.exact()).
MapEstimate3 max_volume(const LazyConvexSet3& F3);

}  // namespace gmcc
