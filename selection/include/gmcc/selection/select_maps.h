#pragma once
/// \file select_maps.h
/// The selection rules of Finlayson & Hordley (1999) §3 (rule.h) applied to one feasible set,
/// each with its map-space worst case (§4): what `gmcc select` reports and what every
/// experiment evaluates per scene.

#include <gmcc/geometry/colour.h>
#include <gmcc/selection/map_estimate.h>
#include <gmcc/selection/mean_3d.h>
#include <gmcc/selection/rule.h>

#include <optional>

namespace gmcc {

/// One rule's answer and the largest map-space error it can make within F.
struct Selection {
  MapEstimate estimate;  ///< the rule's map (d1/d3, d2/d3): exact, certified or sampled
  /// worst_case_map_deg(F, estimate), at the estimate's double map when it is not rational;
  /// absent when the estimate is not valid (Monte Carlo with too few samples).
  std::optional<double> worst_case_deg;
  /// worst_case_illuminant_deg(F, estimate, c): the same in illuminant space
  /// (docs/derivations.md §3.2, exact edge quartics); absent when the estimate is not valid or F
  /// or the map touches an axis (an illuminant c ⊘ (m, 1) needs m > 0).
  std::optional<double> worst_case_illuminant_deg;
};

/// Every rule's Selection of F (rule.h: max-area, the 2-D mean and the 3-D mean, §3 of the
/// paper), indexed by Rule; all absent when F is empty.
using Selections = PerRule<std::optional<Selection>>;

/// What to compute besides the three maps and their map-space worst cases.
struct SelectionOptions {
  Mean3dOptions mean3d;  ///< the 3-D mean's route
  /// The canonical illuminant c: when given, each rule's illuminant-space worst case too (exact
  /// edge quartics: costly when the exact map has hundreds of digits, as the 2-D mean can).
  std::optional<Colour> illuminant_worst_case_for;
};

/// Apply every rule (select_rule) to F with its worst cases. The worst cases of an
/// irrational estimate are measured from its reported double map, taken exactly.
/// \throws std::domain_error if a vertex of F exceeds the range of doubles (the maps are
///         reported as doubles).
Selections select_maps(const ConvexSet2& F, const SelectionOptions& options = {});

}  // namespace gmcc
