#pragma once
/// \file crule_3d.h
/// Forsyth's (1990) CRULE in 3-D, end to end: the feasible set of diagonal maps and its two
/// selections, max-volume (CRULE-MV) and the centroid (CRULE-AVE, Barnard et al. 2002 Part I),
/// with their worst cases. The entry point for experiments comparing 3-D and 2-D rules.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/selection/centroid_3.h>
#include <gmcc/selection/map_estimate_3.h>

#include <optional>
#include <vector>

namespace gmcc {

/// The angle, in degrees, between two diagonal maps as 3-vectors (the map-space angular error of
/// Finlayson & Hordley 1999 §4, in 3-D; a 2-D map m compares as (m1, m2, 1)): atan2(|u×v|, u·v)
/// from the exact maps, within about one ulp — the same computation as every 2-D angular error
/// (angular_error.h), on each map's ray (its primitive integer vector), so that every positive
/// multiple of a map gives the same double. \throws std::invalid_argument if either is 0.
double diagonal_map_angular_error_deg(const Point3& estimate, const Point3& truth);

/// max over d ∈ F3 \ {0} of the angle to m: the angle to a fixed direction is quasi-convex on
/// the octant, so it is attained at a non-zero vertex; chosen exactly by cos² in ℚ.
/// \pre F3 has a non-zero vertex, m != 0. O(|F3|).
double worst_case_map_deg_3d(const ConvexSet3& F3, const Point3& m);
/// The same on F3 with vertices made exact on request (lazy_convex_set_3.h): only the filter's
/// contenders are made exact. Equal to worst_case_map_deg_3d(F3.exact(), m).
double worst_case_map_deg_3d(const LazyConvexSet3& F3, const Point3& m);

/// One 3-D rule's answer and its worst case within F3.
struct Selection3 {
  MapEstimate3 estimate;  ///< the selected map d = (d1, d2, d3), exact or certified
  std::optional<double> worst_case_deg;  ///< absent when the map or F3 is only {0}
};

/// A 3-D rule's map with its worst case within F3 (worst_case_map_deg_3d, from the map as
/// measured), absent when the map or F3 is only {0}: how every 3-D rule's answer is reported.
Selection3 with_worst_case(const ConvexSet3& F3, MapEstimate3 estimate);
/// The same on F3 with vertices made exact on request (lazy_convex_set_3.h).
Selection3 with_worst_case(const LazyConvexSet3& F3, MapEstimate3 estimate);

/// CRULE in 3-D: F3 and its selections (absent when F3 is empty).
struct Crule3d {
  ConvexSet3 feasible;  ///< F3, exactly (feasible_set_3d)
  /// F3's exact volume (0 unless F3 is a polytope); absent on the certified route, which does
  /// not need it.
  std::optional<Rational> volume;
  /// CRULE-MV (argmax d1·d2·d3, max_volume.h) and CRULE-AVE (F3's centroid); absent when F3 is empty.
  ///@{
  std::optional<Selection3> max_volume, centroid;
  ///@}
};

/// CRULE-MV and CRULE-AVE on a given F3: the two selections of Crule3d.
struct Crule3dSelections {
  /// max_volume and the centroid (centroid_3 on the route asked), each with_worst_case; absent
  /// when F3 is empty
  ///@{
  std::optional<Selection3> max_volume, centroid;
  ///@}
};

/// CRULE's two selections (Forsyth 1990; Barnard et al. 2002 Part I for the centroid) on F3 as given, its
/// vertices made exact only where a rule needs them: what crule_3d reports for its F3, and what
/// the experiments score on F3 kept symbolic (feasible_set_3d_lazy). O(the rules' filters).
Crule3dSelections crule_3d_selections(const LazyConvexSet3& F3, Crule3dRoute route);

/// feasible_set_3d(canonical, image, black), then max_volume and the centroid (centroid_3, exact),
/// each with worst_case_map_deg_3d (a map that is not rational, or only certified, is measured
/// from its double map, taken exactly). \throws as feasible_set_3d.
Crule3d crule_3d(const std::vector<Colour>& canonical, const std::vector<Colour>& image,
                 CanonicalBlack black = CanonicalBlack::include);

/// The same from a canonical gamut prepared once (CanonicalConstraints3, feasible_set_3d.h;
/// docs/math.md §1b "The prepared route"), with `route` certified: the centroid certified, no
/// volume; F3 and max-volume exact as always. (The experiments run the same rules on F3 kept
/// symbolic, feasible_set_3d_lazy, and make F3 exact only where a rule needs it.)
/// \throws as feasible_set_3d.
Crule3d crule_3d(const CanonicalConstraints3& canonical, const std::vector<Colour>& image,
                 Crule3dRoute route = Crule3dRoute::exact);

}  // namespace gmcc
