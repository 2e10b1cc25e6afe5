#include <gmcc/validation/illuminants.h>
#include <gmcc/validation/render.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <stdexcept>

namespace gmcc {

Spectrum named_light(const std::string& name, const SpectralTable& basis) {
  if (name.size() >= 2 && (name[0] == 'D' || name[0] == 'P')) {
    Rational k;
    try {
      k = parse_rational(name.substr(1));
    } catch (const std::invalid_argument&) {
      k = 0;
    }
    if (sgn(k) > 0 && name[0] == 'D') {
      // The CIE rule is defined for correlated colour temperatures 4000 K to 25000 K: D40 … D249.
      const Rational T = cie_daylight_cct(Rational(k * 100));
      if (T < 4000 || T > 25000)
        throw std::domain_error("light " + quoted_text(name) + ": CIE daylight is defined for "
                                "4000 K to 25000 K (D40 to D249), not " + to_string(Rational(k * 100)) +
                                " K nominal");
      Spectrum s = cie_daylight(T, basis);
      s.name = name;
      return s;
    }
    if (sgn(k) > 0) {
      // Below ~1000 K a Planckian radiator gives no usable light at 380–780 nm (its blue is
      // e^-38 of its red at 1000 K, and e^-(10^9) at 10^-5 K: the exact powers then need
      // gigabytes); above 10^5 K the spectrum no longer changes colour (Rayleigh–Jeans).
      if (k < kPlanckMinKelvin || k > kPlanckMaxKelvin)
        throw std::domain_error("light " + quoted_text(name) + ": a Planckian light P<T> needs T from " +
                                to_string(Rational(kPlanckMinKelvin)) + " to " +
                                to_string(Rational(kPlanckMaxKelvin)) + " K");
      Spectrum s = planckian(k, basis.wavelengths);
      s.name = name;
      return s;
    }
  }
  throw std::invalid_argument("unknown light " + quoted_text(name) +
                              " (expected D<k> for CIE daylight at k×100 K, e.g. D55, or "
                              "P<T> for a Planckian radiator at T K, e.g. P2856)");
}

ExperimentSetup synthetic_setup(const SpectralTable& munsell, const SpectralTable& basis,
                                const std::string& canonical_light,
                                const std::vector<std::string>& test_lights) {
  const auto& w = narrow_band_wavelengths;
  const Spectrum canonical = named_light(canonical_light, basis);
  ExperimentSetup setup;
  setup.name = "synthetic";
  setup.figure = "Fig. 3";
  setup.canonical_light = {canonical.at(w[0]), canonical.at(w[1]), canonical.at(w[2])};
  for (const Spectrum& chip : munsell.spectra)
    setup.canonical_surfaces.push_back(render_narrow_band(chip, canonical, w));
  for (const std::string& name : test_lights) {
    const Spectrum light = named_light(name, basis);
    TestLight t;
    t.name = name;
    for (const Spectrum& chip : munsell.spectra) t.surfaces.push_back(render_narrow_band(chip, light, w));
    Rational d[3];
    for (int k = 0; k < 3; ++k) d[k] = canonical.at(w[k]) / light.at(w[k]);
    t.true_map = {Rational(d[0] / d[2]), Rational(d[1] / d[2])};
    t.true_diagonal_map = {d[0], d[1], d[2]};
    setup.lights.push_back(std::move(t));
  }
  return setup;
}

}  // namespace gmcc
