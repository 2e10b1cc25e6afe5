#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/option_error.h>

#include "internal/half_plane.h"

#include <algorithm>
#include <stdexcept>

namespace gmcc {

std::string to_string(ExpansionPolicy policy) {
  switch (policy) {
    case ExpansionPolicy::none: return "none";
    case ExpansionPolicy::centroid_clip: return "centroid-clip";
    case ExpansionPolicy::multiplicative: return "multiplicative";
  }
  return "none";
}

namespace {
constexpr ExpansionPolicy all_expansion_policies[] = {ExpansionPolicy::none, ExpansionPolicy::centroid_clip,
                                                      ExpansionPolicy::multiplicative};
}  // namespace

ExpansionPolicy expansion_policy_from_string(const std::string& name) {
  for (ExpansionPolicy p : all_expansion_policies)
    if (to_string(p) == name) return p;
  throw std::invalid_argument("unknown expansion policy '" + name +
                              "' (expected none, centroid-clip or multiplicative)");
}

std::vector<std::string> expansion_policy_names() {
  std::vector<std::string> names;
  for (ExpansionPolicy p : all_expansion_policies) names.push_back(to_string(p));
  return names;
}

void check_options(const Expansion& expansion) {
  if (sgn(expansion.factor) < 0) throw OptionError("expand", "must be >= 0");
  if (expansion.policy == ExpansionPolicy::none && sgn(expansion.factor) != 0)
    throw OptionError("expand_policy", "must be centroid-clip or multiplicative for an expansion factor > 0");
}

ConvexSet2 canonical_gamut(const std::vector<Point2>& chromaticities, const Expansion& expansion) {
  check_options(expansion);
  ConvexSet2 hull = convex_hull(chromaticities);
  if (expansion.policy == ExpansionPolicy::none || sgn(expansion.factor) == 0 ||
      hull.kind == ConvexKind::empty)
    return hull;

  const Rational s = 1 + expansion.factor;
  std::vector<Point2> grown;
  if (expansion.policy == ExpansionPolicy::multiplicative) {
    const Rational inv = 1 / s;
    for (const Point2& v : hull.vertices)
      for (const Rational* fx : {&s, &inv})
        for (const Rational* fy : {&s, &inv})
          grown.push_back({Rational(v.x * *fx), Rational(v.y * *fy)});
    return convex_hull(grown);
  }

  // centroid_clip: scale about the centroid, then keep x >= x_min/s and y >= y_min/s.
  const Point2 c = centroid(hull);
  Rational x_min = hull.vertices.front().x, y_min = hull.vertices.front().y;
  for (const Point2& v : hull.vertices) {
    x_min = std::min(x_min, v.x);
    y_min = std::min(y_min, v.y);
    grown.push_back({Rational(c.x + s * (v.x - c.x)), Rational(c.y + s * (v.y - c.y))});
  }
  grown = internal::clip(grown, {-1, 0, Rational(-x_min / s)});
  grown = internal::clip(grown, {0, -1, Rational(-y_min / s)});
  return canonical_convex_set(std::move(grown));
}

}  // namespace gmcc
