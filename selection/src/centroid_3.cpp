#include <gmcc/geometry/enclosure.h>
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
using E3 = Enclosure3;

E3 sub(const E3& a, const E3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Enclosure det(const E3& a, const E3& b, const E3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

StageCounts& counts() {
  static StageCounts c;
  return c;
}
}  // namespace

std::optional<MapEstimate3> certified_centroid_filtered(const ConvexSet3& F) {
  if (F.kind != ConvexKind3::polytope) return std::nullopt;
  std::vector<E3> v;
  v.reserve(F.vertices.size());
  for (const Point3& p : F.vertices) v.push_back(enclose_point(p));
  const E3& o = v[0];
  Enclosure w_sum = Enclosure::exact(0);
  E3 acc{Enclosure::exact(0), Enclosure::exact(0), Enclosure::exact(0)};
  for (const auto& f : F.faces) {
    if (f[0] == 0) continue;  // facets through the apex add nothing
    const E3 a = sub(v[f[0]], o);
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      const Enclosure w = det(a, sub(v[f[i]], o), sub(v[f[i + 1]], o));
      w_sum = w_sum + w;
      for (int k = 0; k < 3; ++k) acc[k] = acc[k] + w * (o[k] + v[f[0]][k] + v[f[i]][k] + v[f[i + 1]][k]);
    }
  }
  if (!w_sum.positive()) return std::nullopt;
  MapEstimate3 e;
  e.rule = "centroid";
  e.method = "certified";
  const Enclosure four_w = Enclosure::exact(4) * w_sum;
  for (int k = 0; k < 3; ++k) {
    const Enclosure c = acc[k] / four_w;
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
  auto exact = [&] { return exact_map_estimate_3("centroid", centroid(F)); };
  if (route == Crule3dRoute::exact) return exact();
  return internal::staged(internal::counts(), [&] { return internal::certified_centroid_filtered(F); }, exact);
}

}  // namespace gmcc
