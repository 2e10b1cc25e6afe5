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

std::string to_string(NonPositiveBluePolicy policy) {
  return policy == NonPositiveBluePolicy::reject ? "reject" : "drop";
}

NonPositiveBluePolicy nonpositive_blue_policy_from_string(const std::string& text) {
  for (NonPositiveBluePolicy p : {NonPositiveBluePolicy::drop, NonPositiveBluePolicy::reject})
    if (text == to_string(p)) return p;
  throw std::invalid_argument(quoted_text(text) + " is not one of drop, reject");
}

std::vector<std::string> nonpositive_blue_policy_names() {
  return {to_string(NonPositiveBluePolicy::drop), to_string(NonPositiveBluePolicy::reject)};
}

}  // namespace gmcc
