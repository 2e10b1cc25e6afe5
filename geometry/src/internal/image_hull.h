#pragma once
// The image hull's vertices with their filtered approximations, the first step of
// feasible_polygon: only the image hull's vertices constrain F (Finlayson & Hordley 1999 §2).
// Internal to gmcc::geometry.

#include <gmcc/geometry/point.h>

#include <array>
#include <vector>

namespace gmcc::internal {

// An image chromaticity with its approximations, computed once: doubles within a relative 2u
// (when `filtered`) and extended-precision values within 2^-61.6 (when `extended`).
struct ImagePoint {
  const Point2* exact;
  std::array<double, 2> f;
  std::array<long double, 2> l;
  bool filtered, extended;
};

/// q with its approximations (ImagePoint); q must outlive the result.
ImagePoint image_point(const Point2& q);

// The image hull's vertices (extreme points, counter-clockwise): Andrew's monotone chain with the
// lexicographic order and orientations filtered (doubles within 2u decide when they differ by
// more than their error; mpq_cmp, no gcd, otherwise). Image hulls are small (a scene's colours),
// so this beats building exact-kernel points for CGAL.
std::vector<ImagePoint> image_hull_vertices(const std::vector<const Point2*>& image);

}  // namespace gmcc::internal
