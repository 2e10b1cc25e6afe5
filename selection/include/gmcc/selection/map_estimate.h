#pragma once
/// \file map_estimate.h
/// The value a selection rule returns: a perspective map (d1/d3, d2/d3).

#include <gmcc/geometry/point.h>

#include <array>
#include <optional>
#include <string>

namespace gmcc {

/// A chosen perspective map with its provenance.
struct MapEstimate {
  std::string rule;             ///< `max_area`, `mean_2d` or `mean_3d`
  std::string method;           ///< `exact` for rational rules; `analytic` (closed form) …
  std::array<double, 2> map{};  ///< the map as the nearest doubles (for use)
  std::optional<Point2> exact;  ///< the exact map, where the rule's answer is rational
  /// A rigorous bound on max_k |map[k] − true map_k|: the rounding of `exact` to double, or for
  /// an irrational answer the certified enclosure's reach from `map`.
  double error_bound = 0;
  /// Certified enclosure of each component (lo, hi), rounded outward to doubles.
  std::array<std::array<double, 2>, 2> enclosure{};
  unsigned precision_bits = 0;  ///< MPFR/MPFI precision used (0 for exact rules)
};

/// A MapEstimate for an exact rational answer: map rounded to nearest, with its error bound.
MapEstimate exact_map_estimate(std::string rule, const Point2& exact);

}  // namespace gmcc
