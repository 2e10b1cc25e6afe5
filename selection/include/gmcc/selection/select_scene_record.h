#pragma once
/// \file select_scene_record.h
/// The select pipeline's record form (docs/cli.md "Batch selection", `--record`): what a study
/// of many scenes keeps of select_scene, as certified doubles built from enclosures of F's
/// vertices (feasible_polygon.h), the way the experiments' route (certified_rule_errors.h) is
/// built, without the exact rationals and exact vertex lists. Finlayson & Hordley (1999) §3 (the
/// rules), §4 (the worst cases); the illuminant-space worst case of docs/derivations.md §3.2.
///
/// Record contract, version `scene_record_version`:
/// - Every map and vertex coordinate is an Enclosure: the exact value lies in [mid − rad, mid + rad].
/// - Every angle (degrees) is an Enclosure with rad <= rule_errors_accuracy·(1 + |mid|), so its
///   midpoint is within 2^-36·(1 + θ) degrees of the exact θ.
/// - Each rule is scored at its exact map: max-area and the 2-D mean are rational, the 3-D mean
///   (closed form, docs/derivations.md §1) is irrational. (select_scene scores the 3-D mean at its
///   correctly rounded double map; the two differ by far less than the accuracy above.)
/// - Exact stages decide only where an enclosure cannot (a segment or point F, a thin set, an edge
///   that may hold the illuminant-space worst case, a recovery): select_scene, worst_case_illuminant.

#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/selection/certified_rule_errors.h>
#include <gmcc/selection/rule.h>
#include <gmcc/selection/select_scene.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// The version of the record contract above (docs/cli.md "Record contract"): 1.
inline constexpr int scene_record_version = 1;

/// One rule's selection in the record.
struct RecordSelection {
  std::array<Enclosure, 2> map;  ///< the rule's exact map (d1/d3, d2/d3), enclosed
  Enclosure worst_case_deg;      ///< the map-space worst case (worst_case.h) at the exact map
  /// The illuminant-space worst case (worst_case_illuminant.h) at the exact map; absent when not
  /// asked for (SceneChoices::illuminant_worst_case) or when F or the map touches an axis.
  std::optional<Enclosure> worst_case_illuminant_deg;
};

/// One rule's errors against the true light (rule_errors.h, angular_error.h), at the exact map.
struct RecordErrors {
  Enclosure map_error_deg;  ///< map space, the paper's
  /// Recovery and reproduction errors; absent when the map has a component <= 0.
  ///@{
  std::optional<Enclosure> illuminant_error_deg, reproduction_error_deg;
  ///@}
};

/// The scene against its true light.
struct RecordTruth {
  bool in_feasible_set = false;  ///< the true map ∈ F, exactly (FeasiblePolygon::contains)
  PerRule<std::optional<RecordErrors>> errors;  ///< per rule with a map
};

/// What select_scene_record keeps of a scene.
struct SelectRecord {
  /// Image colours given, and of those how many had b <= 0 and were dropped.
  ///@{
  std::size_t image_colours = 0, image_dropped = 0;
  ///@}
  ConvexKind kind = ConvexKind::empty;  ///< F's kind (after the constraint and any recovery), exact
  /// F's vertices, each coordinate enclosed: counter-clockwise from the one of least midpoint (x,
  /// then y); a segment's two ends, a point's one vertex.
  std::vector<std::array<Enclosure, 2>> vertices;
  std::string empty_reason;  ///< why F is empty (set only then)
  std::size_t illuminants = 0;  ///< plausible lights of the illumination constraint (0: none given)
  std::optional<RecoveryReport> recovery;  ///< as SceneResult::recovery (present when the policy is not none)
  PerRule<std::optional<RecordSelection>> selections;  ///< every rule; all absent when F is empty
  std::optional<RecordTruth> truth;  ///< present when given the true light
  /// True when the whole scene came from select_scene (a segment or point F, a set too thin for
  /// the enclosures, a recovery), false when from enclosures (for tests and benchmarks; not part
  /// of the contract).
  bool exact_route = false;
};

/// The pipeline of select_scene (same input, same checks, same SceneInputError) giving the
/// record of the contract above. The 3-D mean is the closed form's; the canonical side's options
/// apply except the 3-D mean's route. With illuminants, F ∩ C in one clipping (and F alone for
/// the empty reason). A scene whose F is empty under a recovery policy takes the exact route
/// (select_scene) and is converted. Safe to call from several threads on one PreparedCanonical.
/// \throws SceneInputError as select_scene; OptionError when choices.mean3d is not the closed form
///         (the record scores the exact 3-D mean). Complexity: feasible_polygon, then O(n) enclosure
///         operations for F of n vertices where they decide; else select_scene's.
SelectRecord select_scene_record(const PreparedCanonical& canonical, const std::vector<Colour>& image,
                                const std::optional<Colour>& truth, const SceneChoices& choices);

/// The record of a scene that select_scene has computed with the closed-form 3-D mean (its
/// estimate's enclosure; each angle of the 3-D mean, measured by select_scene at the rounded map,
/// widened by the angle between that map and the enclosure, so it encloses the value at the
/// exact map). `c` is the canonical illuminant. The exact route of select_scene_record.
/// \throws std::invalid_argument when a 3-D mean has no enclosure (not the closed form).
SelectRecord scene_record(const SceneResult& result, const Colour& c);

}  // namespace gmcc
