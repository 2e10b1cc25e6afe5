#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/illumination_constraint.h>

namespace gmcc {
namespace {
bool positive(const Colour& c) { return sgn(c.r) > 0 && sgn(c.g) > 0 && sgn(c.b) > 0; }
}  // namespace

Point2 illuminant_map(const Colour& e, const Colour& c) {
  if (!positive(e) || !positive(c))
    throw std::invalid_argument("illuminant_map: every channel must be > 0");
  return {Rational(c.r * e.b / (c.b * e.r)), Rational(c.g * e.b / (c.b * e.g))};
}

ConvexSet2 illumination_constraint(const std::vector<Colour>& illuminants, const Colour& c) {
  if (illuminants.empty()) throw std::invalid_argument("illumination_constraint: no illuminants");
  if (!positive(c))
    throw std::invalid_argument("illumination_constraint: the canonical light needs channels > 0");
  std::vector<Point2> maps;
  maps.reserve(illuminants.size());
  for (std::size_t j = 0; j < illuminants.size(); ++j) {
    if (!positive(illuminants[j]))
      throw NonPositiveIlluminant(j, "an illuminant has a channel <= 0: no map takes it to the "
                                     "canonical light");
    maps.push_back(illuminant_map(illuminants[j], c));
  }
  return convex_hull(maps);
}

}  // namespace gmcc
