#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/polytope_moments.h>
#include <gmcc/selection/centroid_3.h>

#include "internal/centroid_3_route.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace gmcc {
namespace internal {
namespace {
StageCounts& counts() {
  static StageCounts c;
  return c;
}
}  // namespace

std::optional<MapEstimate3> certified_centroid_filtered(const ConvexSet3& F) {
  return certified_centroid_filtered(LazyConvexSet3(F));
}

std::optional<MapEstimate3> certified_centroid_filtered(const LazyConvexSet3& F) {
  if (F.kind() != ConvexKind3::polytope) return std::nullopt;
  const PolytopeMoments<Enclosure> m = polytope_moments(F.enclosures(), F.faces(), true);
  const Enclosure& w_sum = m.six_volume;
  if (!certainly_positive(w_sum)) return std::nullopt;
  MapEstimate3 e;
  e.rule = "centroid";
  e.method = "certified";
  const Enclosure four_w = Enclosure::exact(4) * w_sum;
  for (int k = 0; k < 3; ++k) {
    const Enclosure c = m.weighted[static_cast<std::size_t>(k)] / four_w;
    if (!c.finite() || !(c.rad <= std::fabs(c.mid) * certified_centroid_relative_bound)) return std::nullopt;
    e.map[static_cast<std::size_t>(k)] = c.mid;
    e.enclosure[static_cast<std::size_t>(k)] = {c.lo(), c.hi()};
    e.error_bound = std::max(e.error_bound, std::max(c.mid - c.lo(), c.hi() - c.mid));
  }
  return e;
}

const StageCounts& certified_centroid_stage_counts() { return counts(); }

}  // namespace internal

MapEstimate3 centroid_3(const ConvexSet3& F, Crule3dRoute route) {
  if (F.kind == ConvexKind3::empty) throw std::invalid_argument("centroid_3: empty feasible set");
  if (route == Crule3dRoute::exact) return exact_map_estimate_3("centroid", centroid(F));
  return centroid_3(LazyConvexSet3(F), route);
}

MapEstimate3 centroid_3(const LazyConvexSet3& F, Crule3dRoute route) {
  if (F.kind() == ConvexKind3::empty) throw std::invalid_argument("centroid_3: empty feasible set");
  auto exact = [&] { return exact_map_estimate_3("centroid", centroid(F.exact())); };
  if (route == Crule3dRoute::exact) return exact();
  return internal::staged(internal::counts(), [&] { return internal::certified_centroid_filtered(F); }, exact);
}

std::string to_string(Crule3dRoute route) { return route == Crule3dRoute::exact ? "exact" : "certified"; }

Crule3dRoute crule_3d_route_from_string(const std::string& text) {
  for (Crule3dRoute r : {Crule3dRoute::exact, Crule3dRoute::certified})
    if (text == to_string(r)) return r;
  throw std::invalid_argument(quoted_text(text) + " is not one of exact, certified");
}

std::vector<std::string> crule_3d_route_names() {
  return {to_string(Crule3dRoute::exact), to_string(Crule3dRoute::certified)};
}

}  // namespace gmcc
