#pragma once
/// \file score_rules.h
/// The paper's per-scene evaluation (Finlayson & Hordley 1999 §4): the three selection rules on a
/// feasible set F scored against a known true map — each rule's map, its map-space angular error,
/// its worst case over F, and its illuminant and reproduction errors. The one place that chooses
/// the route: the certified route (certified_rule_errors.h: enclosures of F's vertices, at nearly
/// the cost of doubles) where it applies and certifies its angles, else the exact route
/// (select_maps.h and exact_rule_errors in rule_errors.h). The two agree within rule_errors_accuracy (docs/performance-history.md).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/selection/mean_3d.h>
#include <gmcc/selection/certified_rule_errors.h>
#include <gmcc/selection/rule.h>
#include <gmcc/selection/rule_errors.h>

#include <array>
#include <optional>

namespace gmcc {

/// How score_rules may compute.
struct ScoreOptions {
  /// The 3-D mean's route. The certified route computes the certified closed form, so it applies
  /// only with the analytic method at automatic precision; any other choice takes the exact route.
  Mean3dOptions mean3d;
  /// False: the exact route for every scene (to compare the routes, or to time the exact one).
  bool certified_route = true;
};

/// The rules scored on one scene.
struct ScoredRules {
  /// Per rule: absent when the rule gave no map (Monte Carlo with too few samples in the cone).
  /// On the exact route, each `map` is the rule's exact map rounded to nearest; on the certified
  /// route, its enclosure's midpoint (RuleErrors::map).
  PerRule<std::optional<RuleErrors>> rules;
  /// F's area as a double: on the certified route the shoelace sum of the vertex enclosures'
  /// midpoints (a description of F, not certified); on the exact route the exact area rounded.
  double area = 0;
  bool certified = false;  ///< true when the certified route answered
};

/// Every rule on F scored against the true perspective map `truth` (components > 0) for the
/// canonical light c (components > 0). Complexity: that of certified_rule_errors when it answers, else of
/// F.exact(), select_maps and the exact angles.
/// \pre F is not empty. \throws std::invalid_argument unless truth and c are > 0.
ScoredRules score_rules(const FeasiblePolygon& F, const Point2& truth, const Colour& canonical_illuminant,
                        const ScoreOptions& options);

}  // namespace gmcc
