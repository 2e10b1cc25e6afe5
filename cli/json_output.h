#pragma once
// What `gmcc select` prints: the JSON contract of docs/cli.md "JSON output" and a short summary for people.

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/grow_canonical.h>
#include <gmcc/geometry/min_violation.h>
#include <gmcc/selection/select_maps.h>

#include <cstddef>
#include <optional>
#include <string>

namespace gmcc::cli {

/// Finlayson's illumination constraint, when --illuminants is given.
struct ConstraintReport {
  std::size_t illuminants = 0;
  ConvexSet2 maps;           ///< C: hull of the lights' perspective maps
  ConvexSet2 unconstrained;  ///< F before F ∩ C
};

/// What --on-empty did. `applied` is false when F was not empty or the policy could not help.
struct RecoveryReport {
  std::string policy = "none";
  std::string reason;  ///< why F was empty
  bool applied = false;
  std::optional<GrownFeasibleSet> grown;      ///< grow-canonical
  Rational precision;                         ///< grow-canonical: bisection precision
  std::optional<MinViolation> min_violation;  ///< min-violation
};

struct SelectReport {
  Expansion expansion;
  Colour canonical_illuminant{1, 1, 1};
  std::size_t canonical_colours = 0, canonical_dropped = 0;
  std::size_t image_colours = 0, image_dropped = 0;
  ConvexSet2 canonical_gamut;
  ConvexSet2 feasible;
  std::string empty_reason;  ///< why `feasible` is empty (set only then)
  std::optional<ConstraintReport> constraint;
  std::optional<RecoveryReport> recovery;
  Selections selections;
};

/// One JSON object, pretty-printed, ending in a newline.
std::string select_json(const SelectReport& report);
/// A short readable summary.
std::string select_text(const SelectReport& report);

}  // namespace gmcc::cli
