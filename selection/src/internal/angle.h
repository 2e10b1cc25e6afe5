#pragma once
// Angles between exact 3-vectors: the one implementation behind every angular error and worst
// case. Internal to gmcc::selection.

#include <gmcc/geometry/rational.h>

#include "ld_interval.h"

#include <array>

namespace gmcc::internal {

/// ∠(u, v) in degrees as atan2(|u×v|, u·v) (well conditioned for small angles, unlike acos),
/// rounded to double. First in x87 extended-precision intervals from enclosures of the exact
/// inputs (cheap even when they have hundreds of digits), kept when the enclosure pins the angle
/// to 2^-56 relative; otherwise (tiny angles, where the cross product cancels) in MPFR at
/// 160 bits from the exact inputs rounded once. Either way the double is within about one ulp.
/// Equal vectors give 0 at once; between the two stages above, the cross product is enclosed
/// from its exact value (integer cross-multiplication), which settles small angles.
double angle_deg(const std::array<Rational, 3>& u, const std::array<Rational, 3>& v);

/// A rigorous enclosure of ∠(u, v) in degrees from the first stage alone, however wide (for
/// pruning: a maximum need not evaluate candidates that certainly lose). Needs the x87 fast path.
LDInterval angle_deg_enclosure(const std::array<Rational, 3>& u, const std::array<Rational, 3>& v);
/// The same from enclosures of u and v.
LDInterval angle_deg_enclosure(const std::array<LDInterval, 3>& u, const std::array<LDInterval, 3>& v);

}  // namespace gmcc::internal
