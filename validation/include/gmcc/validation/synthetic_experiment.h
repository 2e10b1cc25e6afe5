#pragma once
/// \file synthetic_experiment.h
/// The synthetic experiment of Finlayson & Hordley (1999) §4, Fig. 3: perfectly narrow-band
/// sensors at 610, 540 and 450 nm, the 1269 Munsell matte chips, canonical light CIE D55, test
/// lights D75, D100, a yellowish Planckian (2856 K) and a bluish one (15000 K).

#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/input/spectral_table.h>

#include <array>
#include <string>
#include <vector>

namespace gmcc {

/// The paper's sensor wavelengths (r, g, b), nm.
inline const std::array<Rational, 3> narrow_band_wavelengths{Rational(610), Rational(540), Rational(450)};

/// The Planckian temperatures `named_light` accepts, in kelvin: lights from a candle flame
/// (~1850 K) to the bluest sky (~27000 K) with room; outside, the exact spectrum is either no
/// light at all in the visible range or needs unbounded memory (issue 13).
///@{
inline constexpr long kPlanckMinKelvin = 1000, kPlanckMaxKelvin = 100000;
///@}

/// A light named as in the paper's figure: `D<k>` is CIE daylight of nominal temperature k×100 K
/// at its CIE-rule correlated colour temperature (D55 → 5503 K, D75 → 7504 K, D100 → 10006 K);
/// `P<T>` is a Planckian radiator at T kelvin (P2856, P15000). Sampled at the basis wavelengths.
/// k and T are exact numbers (parse_rational: `P2856.5`, `P1e4`, `D65`).
/// \throws std::invalid_argument for any other name; std::domain_error for k outside 40 … 250
/// (the CIE rule's 4000–25000 K) or T outside kPlanckMinKelvin … kPlanckMaxKelvin
/// (docs/cli.md "Resource limits").
Spectrum named_light(const std::string& name, const SpectralTable& daylight_basis);

/// The setup: the chips' colours under the canonical light (the canonical gamut) and under each
/// test light, rendered narrow-band and exactly, and the exact true maps
/// d_k = E_canonical(λ_k) / E_test(λ_k) → (d1/d3, d2/d3). The diagonal model holds exactly, so
/// the true map lies in every scene's feasible set.
/// \param munsell reflectances sampled at 610, 540 and 450 nm (munsell_matt_1269_joensuu_5nm).
/// \param daylight_basis the CIE S0, S1, S2 table, for named_light.
/// \param canonical_light the canonical light's name (named_light; the paper: D55).
/// \param test_lights the test lights' names, in report order (the paper: D75, D100, P2856, P15000).
ExperimentSetup synthetic_setup(const SpectralTable& munsell, const SpectralTable& daylight_basis,
                                const std::string& canonical_light,
                                const std::vector<std::string>& test_lights);

}  // namespace gmcc
