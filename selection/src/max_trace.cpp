#include <gmcc/selection/max_trace.h>

#include <stdexcept>

namespace gmcc {

MapEstimate3 max_trace(const ConvexSet3& F3) {
  if (F3.vertices.empty()) throw std::invalid_argument("max_trace: the feasible set is empty");
  // Vertices are sorted lexicographically (ConvexSet3), so a strict comparison keeps the
  // smallest of tied vertices.
  const Point3* best = &F3.vertices.front();
  Rational best_trace = best->x + best->y + best->z;
  for (const Point3& v : F3.vertices) {
    Rational t = v.x + v.y + v.z;
    if (t > best_trace) best = &v, best_trace = std::move(t);
  }
  return exact_map_estimate_3("max_trace", *best);
}

}  // namespace gmcc
