#include <gmcc/selection/select_maps.h>
#include <gmcc/selection/worst_case.h>
#include <gmcc/selection/worst_case_illuminant.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gmcc {
namespace {
bool positive(const Point2& p) { return sgn(p.x) > 0 && sgn(p.y) > 0; }

Selection with_worst_case(const ConvexSet2& F, MapEstimate e, const std::optional<Colour>& c) {
  if (!e.valid) return {std::move(e), std::nullopt, std::nullopt};
  const Point2 m = measured_map(e);
  Selection s{std::move(e), worst_case_map_deg(F, m), std::nullopt};
  if (c && positive(m) && std::all_of(F.vertices.begin(), F.vertices.end(), positive))
    s.worst_case_illuminant_deg = worst_case_illuminant_deg(F, m, *c);
  return s;
}
}  // namespace

Selections select_maps(const ConvexSet2& F, const SelectionOptions& options) {
  Selections s;
  if (F.kind == ConvexKind::empty) return s;
  for (const Point2& v : F.vertices) {
    const auto d = to_double_nearest(v);
    if (!std::isfinite(d[0]) || !std::isfinite(d[1]))
      throw std::domain_error("select_maps: the feasible set exceeds the range of doubles "
                              "(1.8e308), in which the estimates are reported");
  }
  const auto& c = options.illuminant_worst_case_for;
  for (Rule r : all_rules) s[r] = with_worst_case(F, select_rule(r, F, options.mean3d), c);
  return s;
}

}  // namespace gmcc
