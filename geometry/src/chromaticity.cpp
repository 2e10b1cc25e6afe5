#include <gmcc/geometry/chromaticity.h>

namespace gmcc {

Point2 perspective_chromaticity(const Colour& c) {
  return {Rational(c.r / c.b), Rational(c.g / c.b)};
}

Chromaticities perspective_chromaticities(const std::vector<Colour>& colours,
                                          NonPositiveBluePolicy policy) {
  Chromaticities out;
  out.points.reserve(colours.size());
  for (std::size_t i = 0; i < colours.size(); ++i) {
    if (sgn(colours[i].b) <= 0) {
      if (policy == NonPositiveBluePolicy::reject) throw NonPositiveBlue(i);
      ++out.dropped;
      continue;
    }
    out.points.push_back(perspective_chromaticity(colours[i]));
    out.source_index.push_back(i);
  }
  return out;
}

}  // namespace gmcc
