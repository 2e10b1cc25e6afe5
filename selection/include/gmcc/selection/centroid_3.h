#pragma once
/// \file centroid_3.h
/// CRULE-AVE: the centroid of the 3-D feasible set (the hull average of Barnard, Cardei & Funt
/// 2002, Part I, on Forsyth's 1990 set F3), exact or certified.

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/lazy_convex_set_3.h>
#include <gmcc/selection/map_estimate_3.h>

#include <string>
#include <vector>

namespace gmcc {

/// How a 3-D rule measures F3: `exact` (the answer in ℚ: what `gmcc select --space 3d` prints) or
/// `certified` (a double map with a rigorous bound, falling back to the exact route wherever the
/// bound cannot be certified: what the experiments score, at a small part of the cost).
enum class Crule3dRoute { exact, certified };
/// `exact` or `certified`: the name every front end reads and writes (--centroid, Python).
std::string to_string(Crule3dRoute route);
/// The inverse of to_string. \throws std::invalid_argument (quoting the text) for any other.
Crule3dRoute crule_3d_route_from_string(const std::string& text);
/// Every name to_string gives, in declaration order: the choices a front end offers.
std::vector<std::string> crule_3d_route_names();

/// F3's centroid (its uniform measure in its own dimension, convex_set_3.h centroid()) as rule
/// `centroid`.
/// - `exact`: centroid() in ℚ, method `exact`.
/// - `certified`, F3 a polytope: the same tetrahedral sum (the facets fan-triangulated and coned
///   from the first vertex) in double enclosures of the exact vertices (numerics/enclosure.h),
///   method `certified` with map = the enclosure's midpoints (not necessarily the nearest
///   doubles), error_bound a bound on |map − exact| (the radius is at most 2^-32 of |map|, or the
///   exact route answers) and the enclosure; the exact route for the
///   lower-dimensional kinds and wherever the volume's sign or a range cannot be certified.
/// \pre F3 not empty. \throws std::invalid_argument if it is. O(total facet size).
MapEstimate3 centroid_3(const ConvexSet3& F3, Crule3dRoute route = Crule3dRoute::exact);
/// The same on F3 with vertices made exact on request (lazy_convex_set_3.h): the certified route
/// reads only the enclosures; the exact route, and a fallback, make every vertex. Equal to
/// centroid_3(F3.exact(), route).
MapEstimate3 centroid_3(const LazyConvexSet3& F3, Crule3dRoute route = Crule3dRoute::exact);

}  // namespace gmcc
