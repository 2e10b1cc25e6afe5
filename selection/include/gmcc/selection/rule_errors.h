#pragma once
/// \file rule_errors.h
/// The errors the paper's evaluation records for each rule (Finlayson & Hordley 1999 §4: the
/// angular error of the selected map and its worst case over F; plus the illuminant and
/// reproduction errors of angular_error.h), computed from certified enclosures of F's vertices
/// instead of exact rational vertices. An experiment needs only these angles; this computes them
/// at nearly the cost of doubles, certified, and says when it cannot (docs/performance.md).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/feasible_polygon.h>

#include <array>
#include <optional>

namespace gmcc {

/// One rule's errors, in degrees, each within the accuracy stated at rule_errors.
struct RuleErrors {
  double map_error_deg;             ///< map_angular_error_deg(selected map, truth)
  double worst_case_deg;            ///< worst_case_map_deg(F, selected map)
  bool positive_map;                ///< both components of the selected map are > 0
  double illuminant_error_deg = 0;  ///< illuminant_angular_error_deg (when positive_map)
  double reproduction_error_deg = 0;///< reproduction_angular_error_deg (when positive_map)
  /// The selected map's midpoint in doubles: within its certified enclosure, which is narrow
  /// enough for the angles above, but not necessarily the nearest double (for records only).
  std::array<double, 2> map{};
};

/// The certified accuracy of every angle rule_errors returns: within 2^-36·(1 + θ) degrees of the
/// exact θ (about 1.5e-11·(1 + θ)); the exact routes are within a relative 2^-50.
inline constexpr double rule_errors_accuracy = 0x1p-36;

/// Errors of the max-area map (§3.1), the 2-D mean (§3.2) and the 3-D mean by its closed form
/// (§3.3, docs/derivations.md §1) against a known true map, for F given by feasible_polygon, in
/// that order.
///
/// Every value is computed in midpoint–radius double intervals (enclosure.h) from F's certified
/// vertex enclosures: the max-area map is the candidate (vertex, or the stationary point
/// (c/2a, c/2b) of m1·m2 on an edge a·x + b·y = c of the north-east chain) whose m1·m2 is
/// certainly above all others' (the maximiser is unique: m1·m2 is strictly quasi-concave on the
/// quadrant); the 2-D mean the fan centroid; the 3-D mean τ = ½ Σ θ_i c_i/|c_i| with θ/|c|
/// enclosed by its monotonicity (no cancellation for short edges); the worst case the largest
/// vertex angle (every vertex certainly at an acute angle to the map: docs/derivations.md §3.1).
/// The map that is scored is each rule's exact map (for the 3-D mean, the exact irrational one).
///
/// \returns nothing when F is not enclosed (degenerate or out of the filter's range), when a
/// decision is uncertain (near-tied max-area candidates, a stationary point at an edge's end, a
/// map component of uncertain sign) or when an angle's enclosure is wider than the accuracy
/// above. The caller then uses the exact routes (select_maps and angular_error.h), which agree
/// within that accuracy (tested on thousands of scenes). Also nothing when F's vertices, the truth,
/// c or a map leave [2^-100, 2^100] in magnitude, the range its double analysis is made for.
/// \throws std::invalid_argument unless truth and c are > 0.
std::optional<std::array<RuleErrors, 3>> rule_errors(const FeasiblePolygon& F, const Point2& truth,
                                                     const Colour& canonical_illuminant);

}  // namespace gmcc
