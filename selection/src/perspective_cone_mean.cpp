#include <gmcc/geometry/perspective_image.h>
#include <gmcc/selection/perspective_cone_mean.h>

namespace gmcc {

std::optional<MapEstimate> perspective_cone_mean(const ConvexSet3& F3, const Mean3dOptions& options) {
  const std::optional<ConvexSet2> P = perspective_image(F3);
  if (!P || P->kind == ConvexKind::empty) return std::nullopt;
  MapEstimate e = mean_3d(*P, options);
  e.rule = "cone_mean";
  return e;
}

}  // namespace gmcc
