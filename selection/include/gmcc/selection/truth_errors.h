#pragma once
/// \file truth_errors.h
/// A selection scored against a known true light: the errors the paper's evaluation records
/// (Finlayson & Hordley 1999 §4; docs/cli.md "Scoring against truth"), by the exact functions of
/// angular_error.h that the experiments use.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>
#include <gmcc/selection/select_maps.h>

#include <optional>

namespace gmcc {

/// One rule's errors against the true map, in degrees.
struct TruthErrors {
  double map_error_deg = 0;  ///< map_angular_error_deg(selected map, true map): the paper's
  /// illuminant_angular_error_deg (recovery error; Hordley & Finlayson 2006) and
  /// reproduction_angular_error_deg (Finlayson & Zakizadeh 2014): absent when a component of
  /// the selected map is <= 0 (it implies no light).
  /// degrees, in [0, 90]
  ///@{
  std::optional<double> illuminant_error_deg, reproduction_error_deg;
  ///@}
};

/// The errors of one selection against the true perspective map `truth` (components > 0), for
/// the canonical light c. The map scored is the rule's exact map where it is rational, else its
/// reported double map taken exactly (as the experiments' exact route).
/// \returns nothing when the selection has no map (estimate not valid).
/// \throws std::invalid_argument unless truth and c are > 0. O(1).
std::optional<TruthErrors> truth_errors(const Selection& selection, const Point2& truth,
                                        const Colour& canonical_illuminant);

}  // namespace gmcc
