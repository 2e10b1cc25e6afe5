#pragma once
/// \file illuminants.h
/// Illuminant spectra for the experiments: CIE daylight from its basis (CIE 15:2004 §3.1) and
/// Planckian radiators, as exact relative spectral power distributions.

#include <gmcc/input/spectral_table.h>

namespace gmcc {

/// The CIE rule for the correlated colour temperature of a daylight named by a nominal
/// temperature: T = nominal × 1.4388 / 1.438 (the 1968 change of c2). D55 → 5503 K, D75 → 7504 K,
/// D100 → 10006 K (rounded). Exact.
Rational cie_daylight_cct(const Rational& nominal_kelvin);

/// CIE daylight at correlated colour temperature T (4000 K ≤ T ≤ 25000 K) on the basis table's
/// wavelengths: S = S0 + M1·S1 + M2·S2 with the CIE chromaticity polynomial x_D(T), y_D(x_D) and
/// M1, M2 rounded to three decimals as CIE 15 prescribes (CIE 15:2004 eqs. 3.3–3.6). Every step
/// is rational, so the result is exact. \param cct_kelvin T, exact, in kelvin. \param basis the S0, S1, S2 table.
/// \throws std::domain_error outside 4000–25000 K.
Spectrum cie_daylight(const Rational& cct_kelvin, const SpectralTable& basis);

/// Relative spectral power of a Planckian radiator at temperature T (Planck's law with
/// c2 = 1.4388e-2 m·K, CIE 15:2004), normalised to 100 at 560 nm, at the given wavelengths.
/// exp is irrational: each value is evaluated in MPFR at 256 bits and that binary value is taken
/// exactly — the one place where irrational spectral data becomes exact (relative error 2^-250).
Spectrum planckian(const Rational& kelvin, const std::vector<Rational>& wavelengths);

}  // namespace gmcc
