#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/perspective_image.h>

#include <stdexcept>

namespace gmcc {

// docs/math.md §1c: d ∈ F3 with d3 > 0 is Σ λ_i v_i over the vertices; a vertex with v3 = 0 is
// the origin (else the image is unbounded) and adds nothing, so d/d3 = Σ (λ_i v_i3 / d3)(v_i / v_i3)
// over the vertices with v3 > 0, weights >= 0 summing to 1: the hull of their images.
std::optional<ConvexSet2> perspective_image(const ConvexSet3& F3) {
  std::vector<Point2> images;
  bool nonzero_on_floor = false;
  for (const Point3& v : F3.vertices) {
    if (sgn(v.x) < 0 || sgn(v.y) < 0 || sgn(v.z) < 0)
      throw std::invalid_argument("perspective_image: a vertex outside the closed octant");
    if (sgn(v.z) > 0) images.push_back({Rational(v.x / v.z), Rational(v.y / v.z)});
    else if (sgn(v.x) > 0 || sgn(v.y) > 0) nonzero_on_floor = true;
  }
  if (nonzero_on_floor && !images.empty()) return std::nullopt;
  return convex_hull(images);
}

}  // namespace gmcc
