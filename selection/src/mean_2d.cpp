#include <gmcc/selection/mean_2d.h>

#include <stdexcept>

namespace gmcc {

MapEstimate mean_2d(const ConvexSet2& F) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("mean_2d: empty feasible set");
  return exact_map_estimate("mean_2d", centroid(F));
}

}  // namespace gmcc
