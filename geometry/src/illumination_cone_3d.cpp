// The illumination constraint in 3-D as one more gamut type (illumination_cone_3d.h).
#include <gmcc/geometry/illumination_cone_3d.h>

#include <gmcc/geometry/point3_arithmetic.h>

#include <algorithm>
#include <stdexcept>

namespace gmcc {

CanonicalConstraints3 illumination_cone_3d(const std::vector<Colour>& lights, const Colour& c, const Point3& box) {
  if (lights.empty()) throw std::invalid_argument("illumination_cone_3d: no plausible light");
  if (sgn(c.r) <= 0 || sgn(c.g) <= 0 || sgn(c.b) <= 0)
    throw std::invalid_argument("illumination_cone_3d: the canonical light needs every channel > 0");
  if (sgn(box.x) <= 0 || sgn(box.y) <= 0 || sgn(box.z) <= 0)
    throw std::invalid_argument("illumination_cone_3d: the box needs every component > 0");
  std::vector<Colour> maps;
  Rational least;
  for (std::size_t j = 0; j < lights.size(); ++j) {
    const Colour& l = lights[j];
    if (sgn(l.r) <= 0 || sgn(l.g) <= 0 || sgn(l.b) <= 0)
      throw std::invalid_argument("illumination_cone_3d: plausible light " + std::to_string(j + 1) +
                                  " has a channel <= 0");
    maps.push_back({Rational(c.r / l.r), Rational(c.g / l.g), Rational(c.b / l.b)});
    const Rational m = std::min({maps.back().r, maps.back().g, maps.back().b});
    if (j == 0 || m < least) least = m;
  }
  const Rational s = std::max({box.x, box.y, box.z}) / least;
  for (Colour& d : maps) d = {Rational(d.r * s), Rational(d.g * s), Rational(d.b * s)};
  return CanonicalConstraints3(maps, CanonicalBlack::include);
}

const std::vector<Colour>& illumination_cone_colour() {
  static const std::vector<Colour> one{{Rational(1), Rational(1), Rational(1)}};
  return one;
}

}  // namespace gmcc
