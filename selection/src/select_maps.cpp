#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/selection/select_maps.h>
#include <gmcc/selection/worst_case.h>

namespace gmcc {
namespace {
Selection with_worst_case(const ConvexSet2& F, MapEstimate e) {
  if (!e.valid) return {std::move(e), std::nullopt};
  const Point2 m = e.exact ? *e.exact
                           : Point2{rational_from_double(e.map[0]), rational_from_double(e.map[1])};
  const double w = worst_case_map_deg(F, m);
  return {std::move(e), w};
}
}  // namespace

Selections select_maps(const ConvexSet2& F, const Mean3dOptions& mean3d) {
  Selections s;
  if (F.kind == ConvexKind::empty) return s;
  s.max_area = with_worst_case(F, max_area(F));
  s.mean_2d = with_worst_case(F, mean_2d(F));
  s.mean_3d = with_worst_case(F, mean_3d(F, mean3d));
  return s;
}

}  // namespace gmcc
