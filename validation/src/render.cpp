#include <gmcc/validation/render.h>

#include <stdexcept>

namespace gmcc {

Colour render_narrow_band(const Spectrum& reflectance, const Spectrum& illuminant,
                          const std::array<Rational, 3>& wavelengths) {
  Rational p[3];
  for (int k = 0; k < 3; ++k)
    p[k] = reflectance.at(wavelengths[k]) * illuminant.at(wavelengths[k]);
  return {p[0], p[1], p[2]};
}

Colour render(const Spectrum& reflectance, const Spectrum& illuminant,
              const std::array<const Spectrum*, 3>& sensors) {
  const auto& grid = reflectance.wavelengths;
  if (illuminant.wavelengths != grid || sensors[0]->wavelengths != grid ||
      sensors[1]->wavelengths != grid || sensors[2]->wavelengths != grid)
    throw std::invalid_argument("render: reflectance, illuminant and sensors must share a grid "
                                "(resample them first)");
  Rational p[3] = {0, 0, 0};
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const Rational re = reflectance.values[i] * illuminant.values[i];
    for (int k = 0; k < 3; ++k) p[k] += re * sensors[k]->values[i];
  }
  return {p[0], p[1], p[2]};
}

Colour render_white(const Spectrum& illuminant, const std::array<const Spectrum*, 3>& sensors) {
  Spectrum white{"white", illuminant.wavelengths,
                 std::vector<Rational>(illuminant.wavelengths.size(), Rational(1))};
  return render(white, illuminant, sensors);
}

}  // namespace gmcc
