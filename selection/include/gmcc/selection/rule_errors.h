#pragma once
/// \file rule_errors.h
/// One rule's errors against a known true map: the record every scoring route returns (the
/// paper's evaluation, Finlayson & Hordley 1999 §4: the angular error of the selected map and its
/// worst case over F; plus the illuminant and reproduction errors of angular_error.h), and the
/// exact route that fills it from an exact map (certified_rule_errors.h is the other route).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>
#include <gmcc/selection/select_maps.h>

#include <array>
#include <optional>

namespace gmcc {

/// One rule's errors against the true map, in degrees.
struct RuleErrors {
  double map_error_deg = 0;         ///< map_angular_error_deg(selected map, truth): the paper's
  double worst_case_deg = 0;        ///< worst_case_map_deg(F, selected map)
  bool positive_map = false;        ///< both components of the selected map are > 0
  /// illuminant_angular_error_deg (recovery error; Hordley & Finlayson 2006), when positive_map
  /// (a map with a component <= 0 implies no light); 0 otherwise.
  double illuminant_error_deg = 0;
  /// reproduction_angular_error_deg (Finlayson & Zakizadeh 2014), when positive_map; 0 otherwise.
  double reproduction_error_deg = 0;
  /// The selected map in doubles: the exact map rounded to nearest on the exact route; on the
  /// certified route its enclosure's midpoint, narrow enough for the angles above but not
  /// necessarily the nearest double (for records only).
  std::array<double, 2> map{};
};

/// The errors of the exact map m against `truth` for the canonical light c, by the exact
/// functions of angular_error.h (illuminant and reproduction errors only when m > 0);
/// `worst_case_deg` is left 0 for the caller, and `map` is m rounded to nearest. What the exact
/// route records per rule, and how CRULE's maps (in perspective) and the baselines' estimates
/// are scored. O(1).
RuleErrors exact_rule_errors(const Point2& m, const Point2& truth, const Colour& canonical_illuminant);

/// The errors of one selection against `truth` (components > 0) for the canonical light c
/// (components > 0): exact_rule_errors of its measured map (the rule's exact map where it is
/// rational, else its reported double map taken exactly), with the selection's map-space worst
/// case. \returns nothing when the selection has no map (estimate not valid).
/// \throws std::invalid_argument unless truth and c are > 0. O(1).
std::optional<RuleErrors> exact_rule_errors(const Selection& selection, const Point2& truth,
                                            const Colour& canonical_illuminant);

}  // namespace gmcc
