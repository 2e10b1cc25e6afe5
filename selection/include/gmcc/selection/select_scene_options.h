#pragma once
/// \file select_scene_options.h
/// The options of the select pipeline (select_scene.h) as types, and the error it throws for
/// input it cannot use: what `gmcc select` reads from its command line (docs/cli.md
/// "gmcc select"), for any caller.

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/colour.h>
#include <gmcc/selection/mean_3d.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gmcc {

/// What to do when the feasible set is empty (docs/cli.md "gmcc select", `--on-empty`).
enum class RecoveryPolicy {
  none,            ///< report the empty set
  grow_canonical,  ///< grow_canonical_until_feasible (grow_canonical.h)
  min_violation,   ///< min_violation (min_violation.h)
};

/// `none`, `grow-canonical`, `min-violation`.
std::string to_string(RecoveryPolicy policy);
/// Inverse of to_string. \throws std::invalid_argument listing the valid names.
RecoveryPolicy recovery_policy_from_string(const std::string& name);
/// Every name to_string gives, in declaration order: the choices a front end offers.
std::vector<std::string> recovery_policy_names();

/// What select_scene computes on a feasible set: the per-scene choices. A PreparedCanonical holds
/// defaults for them (SelectSceneOptions); select_scene takes others per call, so comparing the
/// 3-D mean's routes needs no second prepare_canonical.
struct SceneChoices {
  Mean3dOptions mean3d;  ///< the 3-D mean's route (check_options, mean_3d.h)
  /// Each rule's illuminant-space worst case (worst_case_illuminant.h). Exact edge quartics where
  /// double filters cannot decide: on 11-colour scenes of the shipped sample about a third of a
  /// scene's time (docs/performance.md "Batch selection"); false leaves it out.
  bool illuminant_worst_case = true;
};

/// Every option of the 2-D select pipeline (docs/cli.md "gmcc select"): the canonical side's,
/// fixed by prepare_canonical, and the per-scene choices' defaults (the base class).
struct SelectSceneOptions : SceneChoices {
  NonPositiveBluePolicy nonpositive_blue = NonPositiveBluePolicy::drop;  ///< both colour sets
  Expansion expansion;                    ///< of the canonical gamut
  Colour canonical_illuminant{1, 1, 1};   ///< c: maps of lights, illuminant-space errors
  /// Plausible lights (Finlayson's illumination constraint): F becomes F ∩ conv{c ⊘ e_j}.
  std::optional<std::vector<Colour>> illuminants;
  RecoveryPolicy on_empty = RecoveryPolicy::none;  ///< what to do when F is empty (docs/math.md §1)
};

/// Which input a SceneInputError is about.
enum class SceneInput {
  canonical,    ///< the canonical colours
  image,        ///< the image colours
  illuminants,  ///< SelectSceneOptions::illuminants
  truth,        ///< the true light given to select_scene
  canonical_illuminant,  ///< SelectSceneOptions::canonical_illuminant
  expansion,    ///< SelectSceneOptions::expansion
  on_empty,     ///< SelectSceneOptions::on_empty
};

/// What is wrong, so that a caller can add its own advice (a command line names its options).
enum class SceneProblem {
  nonpositive_blue,       ///< a colour with b <= 0 under NonPositiveBluePolicy::reject
  no_usable_colour,       ///< every colour has b <= 0
  too_large,              ///< a chromaticity, gamut vertex or map beyond max_scene_coordinate
  unbounded,              ///< the image leaves a map component free (UnboundedFeasibleSet)
  nonpositive_light,      ///< an illuminant or the truth with a channel <= 0
  bad_option,             ///< an option that cannot apply (its message says why)
};

/// Input the pipeline cannot use. what() is the problem in words; `index`, when the problem is
/// one colour, its position in that input (0-based).
struct SceneInputError : std::invalid_argument {
  SceneInput input;      ///< which input the problem is in
  SceneProblem problem;  ///< what kind of problem, for a caller that maps it to its own message
  std::optional<std::size_t> index;  ///< the offending colour's 0-based position, when it is one colour
  /// The error `what` in `in`, of kind `p`, at colour `i` if any.
  SceneInputError(SceneInput in, SceneProblem p, std::optional<std::size_t> i, const std::string& what)
      : std::invalid_argument(what), input(in), problem(p), index(i) {}
};

/// The largest coordinate the pipeline accepts for chromaticities, gamut vertices and maps (1e150;
/// docs/cli.md "Input files", the limits): far beyond any physical value, small enough that every
/// number reported as a double stays finite.
const Rational& max_scene_coordinate();

}  // namespace gmcc
