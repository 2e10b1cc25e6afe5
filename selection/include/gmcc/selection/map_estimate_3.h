#pragma once
/// \file map_estimate_3.h
/// The value a 3-D (CRULE) selection rule returns: a diagonal map d = (d1, d2, d3).

#include <gmcc/geometry/convex_set_3.h>

#include <array>
#include <optional>
#include <string>

namespace gmcc {

/// A chosen 3-D diagonal map with its provenance.
struct MapEstimate3 {
  std::string rule;    ///< `max_volume` or `centroid`
  std::string method;  ///< `exact` (rational) or `certified` (a quadratic irrational, enclosed)
  std::array<double, 3> map{};  ///< the map as the nearest doubles
  std::optional<Point3> exact;  ///< the exact map, where it is rational
  double error_bound = 0;       ///< rigorous bound on max_k |map[k] − d_k|
  /// Certified enclosure of each component (lo, hi), rounded outward.
  std::array<std::array<double, 2>, 3> enclosure{};
  /// When the map is irrational: it is from + t·(to − from) on an edge of F3, with t the root
  /// (−b + sign·√(b² − 4ac)) / (2a) of a·t² + b·t + c, all exact.
  struct EdgeRoot {
    /// the edge's ends (vertices of F3), exact
    ///@{
    Point3 from, to;
    ///@}
    /// the quadratic's coefficients, exact
    ///@{
    Rational a, b, c;
    ///@}
    int sign = 1;      ///< +1 or −1: which root of the quadratic is t
  };
  std::optional<EdgeRoot> edge_root;  ///< the exact description of an irrational map; absent when `exact` is set
};

/// A MapEstimate3 for an exact rational map: rounded to nearest, with its rounding bound.
MapEstimate3 exact_map_estimate_3(std::string rule, const Point3& exact);

/// The 3-D map an estimate stands for when it is measured: the exact map where it is rational,
/// else the reported double map taken exactly (as measured_map in 2-D). O(1).
Point3 measured_map(const MapEstimate3& e);

}  // namespace gmcc
