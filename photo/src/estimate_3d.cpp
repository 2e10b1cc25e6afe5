#include <gmcc/photo/estimate_3d.h>

#include <gmcc/selection/centroid_3.h>
#include <gmcc/selection/max_trace.h>
#include <gmcc/selection/max_volume.h>

#include "internal/names.h"

#include <cmath>
#include <stdexcept>

namespace gmcc {

std::string to_string(Rule3 rule) {
  switch (rule) {
    case Rule3::max_volume: return "max_volume";
    case Rule3::centroid: return "centroid";
    case Rule3::max_trace: return "max_trace";
  }
  return "?";
}

Rule3 rule_3_from_string(const std::string& text) {
  for (Rule3 r : all_rules_3)
    if (internal::names_match(text, to_string(r))) return r;
  throw std::invalid_argument("\"" + text + "\" is not one of max-volume, centroid, max-trace");
}

const std::optional<ImageSelection3>& ImageEstimate3::operator[](Rule3 rule) const {
  return rule == Rule3::max_volume ? max_volume : rule == Rule3::centroid ? centroid : max_trace;
}

std::optional<std::array<double, 3>> light_of_map_3(const Point3& d, const Colour& c) {
  if (sgn(d.x) == 0 || sgn(d.y) == 0 || sgn(d.z) == 0) return std::nullopt;
  // e = c ⊘ d in ℚ, then to doubles and unit length (a reported direction, not a decision).
  const double e[3] = {to_double_nearest(c.r / d.x), to_double_nearest(c.g / d.y),
                       to_double_nearest(c.b / d.z)};
  const double n = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  return std::array<double, 3>{e[0] / n, e[1] / n, e[2] / n};
}

double recovery_angular_error_deg(const std::array<double, 3>& estimate, const Colour& truth) {
  return diagonal_map_angular_error_deg({estimate[0], estimate[1], estimate[2]},
                                        {truth.r, truth.g, truth.b});
}

ImageEstimate3 estimate_3d(const CanonicalConstraints3& canonical, const ImageColours& image,
                           const Estimate3Options& o) {
  if (!pixel_colours(image.set))
    throw std::invalid_argument(
        "the image's colours are chromaticity lifts (x, y, 1) of the 2-D hull colour set, not "
        "pixel colours: 3-D gamut mapping needs ColourSet distinct or hull_3d");
  if (image.colours.empty()) throw std::invalid_argument("the image has no colour");
  return estimate_3d(std::vector<GamutConstraint3>{{&canonical, &image.colours, image.set == ColourSet::hull_3d}}, o);
}

ImageEstimate3 estimate_3d(const std::vector<GamutConstraint3>& constraints, const Estimate3Options& o) {
  const Colour& c = o.canonical_light;
  if (sgn(c.r) <= 0 || sgn(c.g) <= 0 || sgn(c.b) <= 0)
    throw std::invalid_argument("the canonical light needs every channel > 0");
  bool want[3] = {false, false, false};
  for (Rule3 r : o.rules) want[static_cast<int>(r)] = true;

  ImageEstimate3 out;
  auto light_of = [&](Selection3 s) {
    ImageSelection3 i{std::move(s), std::nullopt};
    i.light = light_of_map_3(measured_map(i.selection.estimate), c);
    return i;
  };
  out.lazy_feasible = feasible_set_3d_lazy(constraints);
  const LazyConvexSet3& F = out.lazy_feasible;
  if (F.kind() != ConvexKind3::empty) {
    if (want[0]) out.max_volume = light_of(with_worst_case(F, max_volume(F)));
    if (want[1]) out.centroid = light_of(with_worst_case(F, centroid_3(F, o.route)));
    if (want[2]) out.max_trace = light_of(with_worst_case(F, max_trace(F)));
  }
  if (o.exact_feasible_set) out.feasible = F.exact();
  return out;
}

}  // namespace gmcc
