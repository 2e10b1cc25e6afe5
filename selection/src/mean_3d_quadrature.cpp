#include <gmcc/selection/mean_3d_quadrature.h>

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gmcc {
namespace {

// Gauss–Legendre nodes and weights on [0, 1]: Newton's method on P_n in long double.
void gauss_legendre_01(unsigned n, std::vector<long double>& x, std::vector<long double>& w) {
  x.assign(n, 0);
  w.assign(n, 0);
  const long double pi = 3.141592653589793238462643383279502884L;
  for (unsigned i = 0; i < n; ++i) {
    long double z = std::cos(pi * (i + 0.75L) / (n + 0.5L)), derivative = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      long double p0 = 1, p1 = z;
      for (unsigned k = 2; k <= n; ++k) {
        const long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (z * p1 - p0) / (z * z - 1);
      const long double step = p1 / derivative;
      z -= step;
      if (step == 0 || std::fabs(step) <= std::fabs(z) * 0x1p-63L) break;
    }
    if (n == 1) z = 0, derivative = 1;
    x[i] = (1 - z) / 2;
    w[i] = 1 / ((1 - z * z) * derivative * derivative);
  }
}

// apex + offset, rounded once to the nearest double.
double add_exact(const Rational& apex, long double offset) {
  mpfr_t a, o;
  mpfr_inits2(256, a, o, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(a, apex.get_mpq_t(), MPFR_RNDN);
  mpfr_set_ld(o, offset, MPFR_RNDN);
  mpfr_add(a, a, o, MPFR_RNDN);
  const double d = mpfr_get_d(a, MPFR_RNDN);
  mpfr_clears(a, o, static_cast<mpfr_ptr>(nullptr));
  return d;
}

// Weighted sums Σw, Σw·offset over a region, in offsets from the global apex.
struct Sums {
  long double w = 0, x = 0, y = 0;
};

struct Rule {
  std::vector<long double> x, w;  // Gauss–Legendre on [0, 1]
  long double ax, ay;             // the apex, nearest long double
  unsigned depth_limit = 8;
};

// The weight's singularities are where 1 + a² + b² = 0 (complex), about sqrt(1 + |x|²) away from
// a real point x: a piece much larger than that converges slowly, so pieces are halved until
// their diameter² <= 1 + (smallest |x|² over their corners) (MATH §1c: composite rules).
bool needs_split(long double d2, long double r2_min) { return d2 > 1 + r2_min; }

long double r2_at(const Rule& r, long double ox, long double oy) {
  const long double px = r.ax + ox, py = r.ay + oy;
  return px * px + py * py;
}

// Triangle with corners (offsets) P, Q, R: Duffy-collapsed product rule, with w = |x|^-4.
void triangle(const Rule& r, const long double P[2], const long double Q[2], const long double R[2],
              unsigned depth, Sums& s) {
  auto d2 = [](const long double* a, const long double* b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
  };
  const long double diameter2 = std::max({d2(P, Q), d2(Q, R), d2(R, P)});
  const long double r2_min = std::min({r2_at(r, P[0], P[1]), r2_at(r, Q[0], Q[1]), r2_at(r, R[0], R[1])});
  if (depth < r.depth_limit && needs_split(diameter2, r2_min)) {
    const long double PQ[2] = {(P[0] + Q[0]) / 2, (P[1] + Q[1]) / 2};
    const long double QR[2] = {(Q[0] + R[0]) / 2, (Q[1] + R[1]) / 2};
    const long double RP[2] = {(R[0] + P[0]) / 2, (R[1] + P[1]) / 2};
    triangle(r, P, PQ, RP, depth + 1, s);
    triangle(r, PQ, Q, QR, depth + 1, s);
    triangle(r, RP, QR, R, depth + 1, s);
    triangle(r, PQ, QR, RP, depth + 1, s);
    return;
  }
  const long double ex = Q[0] - P[0], ey = Q[1] - P[1], fx = R[0] - P[0], fy = R[1] - P[1];
  const long double jacobian = std::fabs(ex * fy - ey * fx);
  const std::size_t n = r.x.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const long double u = r.x[i], v = r.x[j] * (1 - r.x[i]);  // Duffy collapse
      const long double ox = P[0] + u * ex + v * fx, oy = P[1] + u * ey + v * fy;
      const long double r2 = 1 + r2_at(r, ox, oy);
      const long double wt = r.w[i] * r.w[j] * (1 - r.x[i]) * jacobian / (r2 * r2);
      s.w += wt, s.x += wt * ox, s.y += wt * oy;
    }
}

// Segment from offset P to Q: the planar fan's weight |x|^-3 along it (MATH §1a.6).
void segment(const Rule& r, const long double P[2], const long double Q[2], unsigned depth, Sums& s) {
  const long double ex = Q[0] - P[0], ey = Q[1] - P[1];
  const long double r2_min = std::min(r2_at(r, P[0], P[1]), r2_at(r, Q[0], Q[1]));
  if (depth < r.depth_limit && needs_split(ex * ex + ey * ey, r2_min)) {
    const long double M[2] = {(P[0] + Q[0]) / 2, (P[1] + Q[1]) / 2};
    segment(r, P, M, depth + 1, s);
    segment(r, M, Q, depth + 1, s);
    return;
  }
  const long double length = std::sqrt(ex * ex + ey * ey);
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    const long double ox = P[0] + r.x[i] * ex, oy = P[1] + r.x[i] * ey;
    const long double r2 = 1 + r2_at(r, ox, oy);
    const long double wt = r.w[i] * length / (r2 * std::sqrt(r2));
    s.w += wt, s.x += wt * ox, s.y += wt * oy;
  }
}

// The map by n-point rules: the offset centroid from v0 under the weight, plus v0.
std::array<double, 2> quadrature_map(const ConvexSet2& F, unsigned n) {
  Rule rule;
  gauss_legendre_01(n, rule.x, rule.w);
  const auto& v = F.vertices;
  rule.ax = to_long_double_nearest(v[0].x), rule.ay = to_long_double_nearest(v[0].y);
  auto offset = [&](const Point2& p, long double out[2]) {
    out[0] = to_long_double_nearest(Rational(p.x - v[0].x));
    out[1] = to_long_double_nearest(Rational(p.y - v[0].y));
  };
  Sums s;
  const long double origin[2] = {0, 0};
  if (F.kind == ConvexKind::segment) {
    long double q[2];
    offset(v[1], q);
    segment(rule, origin, q, 0, s);
  } else {
    long double q[2], r[2];
    for (std::size_t t = 1; t + 1 < v.size(); ++t) {
      offset(v[t], q);
      offset(v[t + 1], r);
      triangle(rule, origin, q, r, 0, s);
    }
  }
  return {add_exact(v[0].x, s.x / s.w), add_exact(v[0].y, s.y / s.w)};
}

}  // namespace

MapEstimate mean_3d_quadrature(const ConvexSet2& F, unsigned order) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("mean_3d: empty feasible set");
  if (order == 0) throw std::invalid_argument("mean_3d_quadrature: order must be >= 1");
  // A point is its own mean, exactly.
  MapEstimate e = F.kind == ConvexKind::point ? exact_map_estimate("mean_3d", F.vertices[0])
                                              : MapEstimate{};
  e.rule = "mean_3d";
  e.method = "quadrature";
  e.quadrature_order = order;
  if (F.kind == ConvexKind::point) return e;
  e.map = quadrature_map(F, order);
  const std::array<double, 2> finer = quadrature_map(F, 2 * order);
  for (int k = 0; k < 2; ++k) {
    const double ulp = std::nextafter(std::fabs(e.map[k]), INFINITY) - std::fabs(e.map[k]);
    // Twice the difference: Q_2n is not exact when convergence is slow (wide polygons).
    e.error_bound = std::max({e.error_bound, 2 * std::fabs(e.map[k] - finer[k]), ulp});
  }
  return e;
}

}  // namespace gmcc
