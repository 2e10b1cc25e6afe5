#pragma once
/// \file select_scene.h
/// The select pipeline for one image against a prepared canonical side (docs/cli.md
/// "gmcc select"): the feasible set F (Finlayson & Hordley 1999 eqs. 7–9 in perspective), F ∩ C
/// under Finlayson's illumination constraint, a recovery policy when F is empty, the three
/// selection rules with their worst cases (§3, §4), and, given the true light, each rule's
/// errors. What `gmcc select`, its batch mode and other front ends call. It reads no file (colours
/// in, results out) and needs only geometry, so it lives in selection; the command line reads
/// the files and turns SceneInputError into file-and-line messages.

#include <gmcc/geometry/grow_canonical.h>
#include <gmcc/geometry/min_violation.h>
#include <gmcc/selection/prepare_canonical.h>
#include <gmcc/selection/select_maps.h>
#include <gmcc/selection/rule_errors.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// Finlayson's illumination constraint, when SelectSceneOptions::illuminants is given.
struct ConstraintReport {
  std::size_t illuminants = 0;  ///< how many plausible lights were given
  ConvexSet2 maps;           ///< C: hull of the lights' perspective maps
  ConvexSet2 unconstrained;  ///< F before F ∩ C
};

/// What the recovery policy did. `applied` is false when F was not empty or the policy could
/// not help.
struct RecoveryReport {
  RecoveryPolicy policy = RecoveryPolicy::none;  ///< the policy asked for (SelectSceneOptions::on_empty)
  std::string reason;  ///< why F was empty
  bool applied = false;  ///< true when the policy ran and recovered a non-empty F
  std::optional<GrownFeasibleSet> grown;      ///< grow-canonical
  Rational precision;                         ///< grow-canonical: bisection precision
  std::optional<MinViolation> min_violation;  ///< min-violation
};

/// The scene scored against its true light.
struct TruthReport {
  Colour light;         ///< the true light's RGB under which the image was taken
  Point2 map;           ///< its perspective map: illuminant_map(light, c), c ⊘ light in perspective
  bool in_feasible_set = false;  ///< map ∈ F (after the constraint and any recovery), exactly
  /// Per rule, exact_rule_errors of its Selection (absent when the rule gave no map).
  PerRule<std::optional<RuleErrors>> errors;
};

/// Everything select_scene found; the canonical side is in the PreparedCanonical it was given.
struct SceneResult {
  /// Image colours given, and of those how many had b <= 0 and were dropped (NonPositiveBluePolicy::drop).
  ///@{
  std::size_t image_colours = 0, image_dropped = 0;
  ///@}
  ConvexSet2 feasible;       ///< F (∩ C), replaced by what a recovery policy recovered
  std::string empty_reason;  ///< why `feasible` is empty (set only then)
  std::optional<ConstraintReport> constraint;  ///< present when illuminants were given
  std::optional<RecoveryReport> recovery;  ///< present when the policy is not none
  Selections selections;  ///< every rule on `feasible` (select_maps); all absent when it is empty
  std::optional<TruthReport> truth;  ///< present when select_scene was given the true light
};

/// Largest canonical gamut (vertices) min-violation accepts: its minimisers are clipped in
/// rationals, O(k·m²) for m gamut edges (2000 edges: about 13 s).
inline constexpr std::size_t max_min_violation_edges = 2000;

/// The first half of select_scene: image chromaticities, F against the prepared G_c (and C) and
/// the recovery policy when F is empty; no selections and no truth (`selections` and `truth` are
/// left empty). For callers that want the feasible set alone (the Python module's feasible_set).
/// \throws SceneInputError as select_scene, except for the truth. Complexity: feasible_set.
SceneResult scene_feasible_set(const PreparedCanonical& canonical, const std::vector<Colour>& image);

/// Run the pipeline on one image: image chromaticities, F against the prepared G_c (and C), the
/// recovery policy when F is empty, select_maps with the illuminant-space worst cases for c, and
/// with `truth` (the true light's RGB, channels > 0) exact_rule_errors for each rule against its map
/// illuminant_map(truth, c).
/// \throws SceneInputError (input image, truth or on_empty): no usable colour, b <= 0 under
///         reject, chromaticities or maps beyond max_scene_coordinate, an unbounded F, a truth
///         with a channel <= 0, min-violation on a gamut of more than max_min_violation_edges
///         vertices. Complexity: feasible_set, then select_maps (worst_case_illuminant dominates
///         on long exact vertices).
SceneResult select_scene(const PreparedCanonical& canonical, const std::vector<Colour>& image,
                         const std::optional<Colour>& truth = std::nullopt);

/// The same with this call's own choices instead of the ones `canonical` was prepared with (the
/// 3-D mean's route, the illuminant-space worst cases): everything else as above.
/// \throws SceneInputError as above; OptionError for a 3-D mean parameter outside its limits.
SceneResult select_scene(const PreparedCanonical& canonical, const std::vector<Colour>& image,
                         const std::optional<Colour>& truth, const SceneChoices& choices);

}  // namespace gmcc
