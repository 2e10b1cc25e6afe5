#pragma once
/// \file illumination_constraint.h
/// Finlayson's illumination constraint (Finlayson 1996, "Color in perspective", §5; the
/// conclusion of Finlayson & Hordley 1999): only maps that take a plausible light to the
/// canonical light are admitted, so F is intersected with the set of such maps.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/convex_set.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace gmcc {

/// Thrown by illumination_constraint for an illuminant with a channel <= 0 (c ⊘ e undefined).
struct NonPositiveIlluminant : std::invalid_argument {
  std::size_t index;  ///< position of the offending illuminant in the input
  /// The illuminant at position `i` has a channel <= 0; `what` is the message.
  NonPositiveIlluminant(std::size_t i, const char* what) : std::invalid_argument(what), index(i) {}
};

/// The perspective map of a light e: d = c ⊘ e takes colours seen under e to colours seen under
/// the canonical light c (diagonal model), and m = (d1/d3, d2/d3) = (c1·e3/(c3·e1),
/// c2·e3/(c3·e2)). Exact. \pre every channel of e and c is > 0. O(1).
Point2 illuminant_map(const Colour& illuminant, const Colour& canonical_illuminant);

/// C = conv{ illuminant_map(e_j, c) }: the plausible maps in perspective, as the convex hull of
/// the maps of a set of plausible lights e_j (RGBs of lights as the camera sees them; Finlayson
/// 1996 §5). Exact, any kind (one light gives a point, lights on a line a segment).
/// Intersect it with F by gmcc::intersection.
/// \throws std::invalid_argument for no illuminants or a channel of c <= 0;
///         NonPositiveIlluminant naming the first illuminant with a channel <= 0.
/// Complexity O(n log n).
ConvexSet2 illumination_constraint(const std::vector<Colour>& illuminants,
                                   const Colour& canonical_illuminant);

}  // namespace gmcc
