#pragma once
/// \file prepare_canonical.h
/// The canonical side of the select pipeline, prepared once for many images (docs/cli.md
/// "Batch selection"): chromaticities, the (expanded) canonical gamut G_c, Finlayson's
/// illumination constraint C and G_c's half-planes (CanonicalConstraints, feasible_set.h).

#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/select_scene_options.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace gmcc {

/// The canonical side. Immutable once made: one object may serve many select_scene calls, also
/// from several threads.
struct PreparedCanonical {
  SelectSceneOptions options;  ///< the options it was prepared with; select_scene uses the same
  std::vector<Point2> chromaticities;  ///< the measured canonical chromaticities
  std::size_t colours = 0;             ///< canonical colours given
  std::size_t dropped = 0;             ///< of those, with b <= 0 (dropped)
  ConvexSet2 gamut;                    ///< G_c after expansion
  std::optional<ConvexSet2> constraint;  ///< C, with options.illuminants
  CanonicalConstraints constraints;      ///< G_c alone
  std::optional<CanonicalConstraints> constrained;  ///< G_c with C (F ∩ C in one pass)
};

/// Check the options and prepare the canonical side: perspective chromaticities (Finlayson &
/// Hordley 1999 eq. 10), G_c and its expansion (canonical_gamut.h), C (illumination_constraint.h).
/// \throws SceneInputError (input canonical, illuminants, expansion or on_empty) for input or
///         options that admit no answer: no usable colour, b <= 0 under reject, coordinates
///         beyond max_scene_coordinate, an illuminant or c with a channel <= 0, a negative
///         factor or a factor with ExpansionPolicy::none, grow-canonical after a centroid-clip
///         expansion; OptionError for a 3-D mean parameter outside its limits (check_options,
///         mean_3d.h). Complexity O(n log n) in the colours and lights.
PreparedCanonical prepare_canonical(const std::vector<Colour>& canonical,
                                    const SelectSceneOptions& options);

}  // namespace gmcc
