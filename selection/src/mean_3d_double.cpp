#include <gmcc/geometry/rational.h>
#include <gmcc/selection/mean_3d_double.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace gmcc {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 cross(const Vec3& p, const Vec3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
double dot(const Vec3& p, const Vec3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
double norm(const Vec3& p) { return std::sqrt(dot(p, p)); }

}  // namespace

std::array<double, 2> mean_3d_double(const ConvexSet2& F) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("mean_3d_double: empty set");
  const auto& v = F.vertices;
  auto lift = [](const Point2& p) { return Vec3{to_double_nearest(p.x), to_double_nearest(p.y), 1.0}; };
  Vec3 tau{0, 0, 0};
  if (F.kind == ConvexKind::point) {
    tau = lift(v[0]);
  } else if (F.kind == ConvexKind::segment) {
    const Vec3 p = lift(v[0]), q = lift(v[1]);
    const double np = norm(p), nq = norm(q);
    for (int k = 0; k < 3; ++k) tau[k] = p[k] / np + q[k] / nq;
  } else {
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Vec3 p = lift(v[i]), q = lift(v[(i + 1) % v.size()]);
      const Vec3 c = cross(p, q);
      const double n = norm(c);
      const double s = std::atan2(n, dot(p, q)) / n;
      for (int k = 0; k < 3; ++k) tau[k] += s * c[k];
    }
  }
  return {tau[0] / tau[2], tau[1] / tau[2]};
}

}  // namespace gmcc
