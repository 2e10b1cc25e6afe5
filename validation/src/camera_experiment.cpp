#include <gmcc/validation/camera_experiment.h>
#include <gmcc/validation/render.h>

namespace gmcc {

ExperimentSetup camera_setup(const SpectralTable& sensor_table, const SpectralTable& canonical_reflectances,
                             const SpectralTable& scene_reflectances, const SpectralTable& lights,
                             const std::string& canonical_light,
                             const std::vector<std::string>& test_lights) {
  const std::array<const Spectrum*, 3> sensors{&sensor_table.spectrum("R"), &sensor_table.spectrum("G"),
                                               &sensor_table.spectrum("B")};
  const Spectrum& canonical = lights.spectrum(canonical_light);
  ExperimentSetup setup;
  setup.name = "camera";
  setup.figure = "Fig. 5, simulated with the camera's sensors";
  setup.canonical_light = render_white(canonical, sensors);
  for (const Spectrum& r : canonical_reflectances.spectra)
    setup.canonical_surfaces.push_back(render(r, canonical, sensors));
  for (const std::string& name : test_lights) {
    const Spectrum& light = lights.spectrum(name);
    TestLight t;
    t.name = name;
    for (const Spectrum& r : scene_reflectances.spectra) t.surfaces.push_back(render(r, light, sensors));
    const Colour white = render_white(light, sensors);
    const Colour& c = setup.canonical_light;
    const Rational d0 = c.r / white.r, d1 = c.g / white.g, d2 = c.b / white.b;
    t.true_map = {Rational(d0 / d2), Rational(d1 / d2)};
    t.true_diagonal_map = {d0, d1, d2};
    setup.lights.push_back(std::move(t));
  }
  return setup;
}

}  // namespace gmcc
