#pragma once
/// \file certified_rule_errors.h
/// The errors the paper's evaluation records for each rule (Finlayson & Hordley 1999 §4: the
/// angular error of the selected map and its worst case over F; plus the illuminant and
/// reproduction errors of angular_error.h), computed from certified enclosures of F's vertices
/// instead of exact rational vertices. An experiment needs only these angles; this computes them
/// at nearly the cost of doubles, certified, and says when it cannot (docs/performance-history.md).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/selection/rule.h>
#include <gmcc/selection/rule_errors.h>

#include <array>
#include <optional>

namespace gmcc {

/// The certified accuracy of every angle certified_rule_errors returns: within 2^-36·(1 + θ)
/// degrees of the exact θ (about 1.5e-11·(1 + θ)); the exact routes are within a relative 2^-50.
inline constexpr double rule_errors_accuracy = 0x1p-36;

/// The errors (rule_errors.h) of every rule (rule.h) — the max-area map (§3.1), the 2-D mean
/// (§3.2) and the 3-D mean by its closed form (§3.3, docs/derivations.md §1) — against a known
/// true map, for F given by feasible_polygon: the certified route.
///
/// Every value is computed in midpoint–radius double intervals (enclosure.h) from F's certified
/// vertex enclosures: the max-area map is the candidate (vertex, or the stationary point
/// (c/2a, c/2b) of m1·m2 on an edge a·x + b·y = c of the north-east chain) whose m1·m2 is
/// certainly above all others' (the maximiser is unique: m1·m2 is strictly quasi-concave on the
/// quadrant); the 2-D mean the fan centroid; the 3-D mean τ = ½ Σ θ_i c_i/|c_i| with θ/|c|
/// enclosed by its monotonicity (no cancellation for short edges); the worst case the largest
/// vertex angle (every vertex certainly at an acute angle to the map: docs/derivations.md §3.1).
/// The map that is scored is each rule's exact map (for the 3-D mean, the exact irrational one).
///
/// \returns nothing when F is not enclosed (degenerate or out of the filter's range), when a
/// decision is uncertain (near-tied max-area candidates, a stationary point at an edge's end, a
/// map component of uncertain sign) or when an angle's enclosure is wider than the accuracy
/// above, or when a rule has no certified form. The caller then uses the exact route (select_maps
/// and exact_rule_errors), which agrees
/// within that accuracy (tested on thousands of scenes). Also nothing when F's vertices, the truth,
/// c or a map leave [2^-100, 2^100] in magnitude, the range its double analysis is made for.
/// \throws std::invalid_argument unless truth and c are > 0.
std::optional<PerRule<RuleErrors>> certified_rule_errors(const FeasiblePolygon& F, const Point2& truth,
                                                        const Colour& canonical_illuminant);

}  // namespace gmcc
