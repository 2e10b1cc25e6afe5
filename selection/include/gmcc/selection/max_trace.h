#pragma once
/// \file max_trace.h
/// The max-trace selection on the 3-D feasible set: the map with the largest d1 + d2 + d3, the
/// selection of Gijsenij, Gevers & van de Weijer's (2010) generalized gamut mapping
/// (docs/math.md §1c).

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/lazy_convex_set_3.h>
#include <gmcc/selection/map_estimate_3.h>

namespace gmcc {

/// argmax_{d ∈ F3} d1 + d2 + d3, exactly (docs/math.md §1c). A linear function attains its
/// maximum over a polytope at a vertex, so the vertices are compared in ℚ (those a double-enclosure
/// filter of their traces cannot rule out); of tied vertices
/// (the maximum on an edge or facet of F3) the lexicographically smallest is returned. Method
/// `exact`, rule `max_trace`.
/// \pre F3 not empty. \throws std::invalid_argument if it is. O(|F3| vertices).
MapEstimate3 max_trace(const ConvexSet3& F3);
/// The same on F3 with vertices made exact on request (lazy_convex_set_3.h): only the filter's
/// contenders are made exact. Equal to max_trace(F3.exact()).
MapEstimate3 max_trace(const LazyConvexSet3& F3);

}  // namespace gmcc
