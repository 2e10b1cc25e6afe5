#pragma once
/// \file map_estimate.h
/// The value a selection rule returns: a perspective map (d1/d3, d2/d3).

#include <gmcc/geometry/point.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace gmcc {

/// A chosen perspective map with its provenance.
struct MapEstimate {
  std::string rule;             ///< `max_area`, `mean_2d` or `mean_3d`
  std::string method;           ///< `exact` (rational rules), `analytic`, `quadrature`, `monte-carlo`
  std::array<double, 2> map{};  ///< the map as the nearest doubles (for use)
  std::optional<Point2> exact;  ///< the exact map, where the rule's answer is rational
  /// The error statement for |map[k] − true map_k|, per coordinate k, by method:
  /// exact and analytic: a rigorous bound (the distance from map[k] to the far end of the
  /// certified enclosure); quadrature: the truncation estimate 2·|Q_n − Q_2n| plus a rigorous
  /// bound on the rounding errors of the sums, which covered the error on every polygon of the
  /// honesty test and sweep (docs/math.md §4); monte-carlo: the standard error (one sigma).
  std::array<double, 2> error_bounds{};
  /// max(error_bounds[0], error_bounds[1]), kept for callers of one number.
  double error_bound = 0;
  /// Per coordinate: map[k] is the double nearest the true value (ties to even). exact: always;
  /// analytic: certified (the enclosure lies inside one rounding interval; false only at the
  /// precision cap, with a note); quadrature: as far as its error statement holds (the interval
  /// map[k] ± its pre-rounding bound lies in one rounding interval); monte-carlo: never.
  std::array<bool, 2> correctly_rounded{};
  /// exact and analytic: certified enclosure of each component (lo, hi), rounded outward.
  std::optional<std::array<std::array<double, 2>, 2>> enclosure;
  unsigned precision_bits = 0;  ///< analytic: working precision (64: the x87 extended fast path)

  /// False when the method could not produce a map (Monte Carlo with too few samples in the
  /// cone, or on a set with no volume; the closed form at a forced precision too low to bound
  /// it); `note` says why and `map` is not meaningful.
  bool valid = true;
  /// Why the map is not valid, or a caveat on a valid one (e.g. not proven correctly rounded);
  /// empty otherwise.
  std::string note;
  unsigned quadrature_order = 0;  ///< quadrature: Gauss–Legendre points per direction
  std::uint64_t samples = 0;      ///< monte-carlo: points drawn in the unit cube
  std::uint64_t samples_kept = 0; ///< monte-carlo: of those, inside cone ∩ ball
  std::uint64_t seed = 0;         ///< monte-carlo: generator seed (generator: mt19937_64)
  std::array<double, 2> standard_error{};  ///< monte-carlo: per component
};

/// A MapEstimate for an exact rational answer: map rounded to nearest, with its error bound.
MapEstimate exact_map_estimate(std::string rule, const Point2& exact);

/// The map a rule's estimate stands for when it is measured (worst cases, errors against truth):
/// the exact map where the rule is rational, else the reported double map taken exactly.
/// \pre e.valid. O(1).
Point2 measured_map(const MapEstimate& e);

}  // namespace gmcc
