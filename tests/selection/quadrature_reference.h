#pragma once
// An independent numerical route to the 3-D mean for tests: the weighted planar centroid
// m = ∫_F (a, b) w dA / ∫_F w dA with w = (1 + a² + b²)^-2 (docs/derivations.md §1.3), by
// Duffy-collapsed Gauss–Legendre on the fan triangles of F, in long double and in offsets from the
// fan apex so that small polygons do not cancel (docs/derivations.md §1.6). Shares no code with the
// closed form.

#include <gmcc/geometry/convex_set.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <vector>

namespace gmcc::test {

/// Gauss–Legendre nodes and weights on [0, 1] by Golub–Welsch: the eigenvalues of the Jacobi
/// matrix of the Legendre recurrence (off-diagonal k/√(4k² − 1)) are the nodes on [−1, 1], and
/// twice the squared first components of the eigenvectors the weights (a different algorithm
/// from the library's Newton iteration, on purpose).
inline void gauss_legendre01(int n, std::vector<long double>& x, std::vector<long double>& w) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) J(k, k - 1) = J(k - 1, k) = k / std::sqrt(4.0 * k * k - 1);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(J);
  x.resize(n);
  w.resize(n);
  for (int i = 0; i < n; ++i) {
    x[i] = (1 + eig.eigenvalues()(i)) / 2;
    const double v0 = eig.eigenvectors()(0, i);
    w[i] = v0 * v0;  // 2·v0² on [−1, 1], halved for [0, 1]
  }
}

/// The weighted centroid of a polygon by n×n-point Duffy–Gauss–Legendre per fan triangle.
inline std::array<long double, 2> weighted_centroid_reference(const ConvexSet2& F, int n) {
  std::vector<long double> x, w;
  gauss_legendre01(n, x, w);
  const auto& v = F.vertices;
  auto ld = [](const Rational& q) { return to_long_double_nearest(q); };
  // Offsets from the apex are formed exactly, then rounded once.
  const long double ax = ld(v[0].x), ay = ld(v[0].y);
  long double sw = 0, sx = 0, sy = 0;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const long double ex = ld(Rational(v[i].x - v[0].x)), ey = ld(Rational(v[i].y - v[0].y));
    const long double fx = ld(Rational(v[i + 1].x - v[0].x)),
                      fy = ld(Rational(v[i + 1].y - v[0].y));
    const long double jac = std::fabs(ex * fy - ey * fx);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        const long double s = x[a], t = x[b] * (1 - x[a]);  // Duffy: t = v(1 − u)
        const long double ox = s * ex + t * fx, oy = s * ey + t * fy;
        const long double px = ax + ox, py = ay + oy;
        const long double r2 = 1 + px * px + py * py;
        const long double wt = w[a] * w[b] * (1 - x[a]) * jac / (r2 * r2);
        sw += wt;
        sx += wt * ox;
        sy += wt * oy;
      }
  }
  return {ax + sx / sw, ay + sy / sw};
}

}  // namespace gmcc::test
