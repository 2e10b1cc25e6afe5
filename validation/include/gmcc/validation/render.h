#pragma once
/// \file render.h
/// Sensor responses of surfaces under lights: p_k = ∫ R(λ) E(λ) S_k(λ) dλ (Finlayson & Hordley
/// 1999 eq. 1), exactly.

#include <gmcc/geometry/colour.h>
#include <gmcc/input/spectral_table.h>

#include <array>

namespace gmcc {

/// Perfectly narrow-band sensors at three wavelengths (r, g, b): p_k = R(λ_k)·E(λ_k), exact
/// (Finlayson & Hordley 1999 §4's synthetic sensors). Under such sensors the diagonal model
/// holds exactly: the map between two lights is d_k = E1(λ_k)/E2(λ_k).
/// \throws std::out_of_range if a wavelength is not sampled by R or E.
Colour render_narrow_band(const Spectrum& reflectance, const Spectrum& illuminant,
                          const std::array<Rational, 3>& wavelengths);

/// Broad-band sensors: p_k = Σ_λ R(λ) E(λ) S_k(λ) over a common grid (a Riemann sum; the
/// constant Δλ is dropped, as it cancels in every ratio the experiments use). All four spectra
/// must share the wavelengths. \throws std::invalid_argument otherwise.
Colour render(const Spectrum& reflectance, const Spectrum& illuminant,
              const std::array<const Spectrum*, 3>& sensors);

/// The response to a perfect white (R = 1): the light's colour as the sensors see it.
Colour render_white(const Spectrum& illuminant, const std::array<const Spectrum*, 3>& sensors);

}  // namespace gmcc
