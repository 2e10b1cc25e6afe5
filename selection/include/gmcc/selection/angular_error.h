#pragma once
/// \file angular_error.h
/// Angular errors between maps, the accuracy measures of colour constancy.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>

namespace gmcc {

/// The paper's measure (Finlayson & Hordley 1999 §4): the angle, in degrees, between the lifted
/// maps (m, 1) and (m*, 1). Inputs exact; evaluated as atan2(|u×v|, u·v) (well conditioned
/// for small angles) in certified extended-precision intervals, or in 160-bit MPFR where those
/// are not tight (tiny angles), then rounded to double (within about one ulp). Domain: any two points.
double map_angular_error_deg(const Point2& estimate, const Point2& truth);

/// The illuminant recovery error benchmarks report (Hordley & Finlayson 2006): the angle, in
/// degrees, between the illuminants e = c ⊘ (m, 1) implied by the estimated and the true map,
/// for the canonical illuminant c. \pre all map components and c are > 0.
double illuminant_angular_error_deg(const Point2& estimate, const Point2& truth,
                                    const Colour& canonical_illuminant);

/// The reproduction angular error (Finlayson & Zakizadeh, BMVC 2014
/// [Finlayson2014Reproduction]), in degrees: the angle between e_true ⊘ e_est = d_est ⊘ d_true
/// and the white (1, 1, 1), with d = (m1, m2, 1) the lifted maps. It measures how far the
/// corrected white is from white, and does not depend on the canonical illuminant c (the c of
/// e = c ⊘ d cancels). Inputs exact; evaluated like the others. O(1).
/// \pre all map components > 0 (the illuminants must exist). \throws std::invalid_argument.
double reproduction_angular_error_deg(const Point2& estimate, const Point2& truth);

}  // namespace gmcc
