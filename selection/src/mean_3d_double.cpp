#include <gmcc/geometry/rational.h>
#include <gmcc/selection/mean_3d_double.h>

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace gmcc {

std::array<double, 2> mean_3d_double(const ConvexSet2& F) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("mean_3d_double: empty set");
  const auto& v = F.vertices;
  auto lift = [](const Point2& p) {
    return Eigen::Vector3d(to_double_nearest(p.x), to_double_nearest(p.y), 1.0);
  };
  Eigen::Vector3d tau = Eigen::Vector3d::Zero();
  if (F.kind == ConvexKind::point) {
    tau = lift(v[0]);
  } else if (F.kind == ConvexKind::segment) {
    tau = lift(v[0]).normalized() + lift(v[1]).normalized();
  } else {
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Eigen::Vector3d p = lift(v[i]), q = lift(v[(i + 1) % v.size()]);
      const Eigen::Vector3d c = p.cross(q);
      const double n = c.norm();
      tau += std::atan2(n, p.dot(q)) / n * c;
    }
  }
  return {tau.x() / tau.z(), tau.y() / tau.z()};
}

}  // namespace gmcc
