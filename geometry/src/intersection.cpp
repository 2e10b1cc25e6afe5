#include <gmcc/geometry/intersection.h>

#include "internal/half_plane.h"

namespace gmcc {

ConvexSet2 intersection(const ConvexSet2& a, const ConvexSet2& b) {
  if (a.kind == ConvexKind::empty || b.kind == ConvexKind::empty) return {};
  // A canonical polygon is CCW; a segment's two ends or a point are convex cycles as they are.
  std::vector<Point2> cycle = a.vertices;
  for (const internal::HalfPlane& h : internal::half_planes(b)) {
    cycle = internal::clip(cycle, h);
    if (cycle.empty()) return {};
  }
  return canonical_convex_set(std::move(cycle));
}

}  // namespace gmcc
