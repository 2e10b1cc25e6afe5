#include <gmcc/geometry/enclosure.h>
#include <gmcc/selection/max_trace.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace gmcc {
namespace {
// The vertices whose trace d1 + d2 + d3, enclosed in doubles (numerics/enclosure.h), may reach
// the largest lower end, in vertex order (the maximum is among them); all of them where an
// enclosure is not finite.
std::vector<std::size_t> contenders(const ConvexSet3& F) {
  std::vector<Enclosure> trace;
  double best = -std::numeric_limits<double>::infinity();
  for (const Point3& v : F.vertices) {
    trace.push_back(enclose_rational(v.x) + enclose_rational(v.y) + enclose_rational(v.z));
    best = std::max(best, trace.back().lo());
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < trace.size(); ++i)
    if (!trace[i].finite() || trace[i].hi() >= best) out.push_back(i);
  return out;
}
}  // namespace

MapEstimate3 max_trace(const ConvexSet3& F3) {
  if (F3.vertices.empty()) throw std::invalid_argument("max_trace: the feasible set is empty");
  // Vertices are sorted lexicographically (ConvexSet3), so a strict comparison over the
  // contenders, in order, keeps the smallest of tied vertices.
  const Point3* best = nullptr;
  Rational best_trace;
  for (std::size_t i : contenders(F3)) {
    const Point3& v = F3.vertices[i];
    Rational t = v.x + v.y + v.z;
    if (!best || t > best_trace) best = &v, best_trace = std::move(t);
  }
  return exact_map_estimate_3("max_trace", *best);
}

}  // namespace gmcc
