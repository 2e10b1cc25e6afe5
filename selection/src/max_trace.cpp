#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/numerics/may_be_largest.h>
#include <gmcc/selection/max_trace.h>


#include <cstddef>
#include <stdexcept>
#include <vector>

namespace gmcc {
namespace {
// The vertices whose trace d1 + d2 + d3, enclosed in doubles, may be the largest, in vertex order.
std::vector<std::size_t> contenders(const LazyConvexSet3& F) {
  std::vector<Enclosure> trace;
  for (const Enclosure3& v : F.enclosures()) trace.push_back(v[0] + v[1] + v[2]);
  return numerics::may_be_largest(trace);
}
}  // namespace

MapEstimate3 max_trace(const ConvexSet3& F3) { return max_trace(LazyConvexSet3(F3)); }

MapEstimate3 max_trace(const LazyConvexSet3& F3) {
  if (F3.size() == 0) throw std::invalid_argument("max_trace: the feasible set is empty");
  // Vertices are sorted lexicographically (ConvexSet3), so a strict comparison over the
  // contenders, in order, keeps the smallest of tied vertices.
  const Point3* best = nullptr;
  Rational best_trace;
  for (std::size_t i : contenders(F3)) {
    const Point3& v = F3.vertex(i);
    Rational t = v.x + v.y + v.z;
    if (!best || t > best_trace) best = &v, best_trace = std::move(t);
  }
  return exact_map_estimate_3("max_trace", *best);
}

}  // namespace gmcc
