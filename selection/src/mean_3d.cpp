#include <gmcc/selection/mean_3d.h>

#include "internal/interval.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace gmcc {
namespace {
using internal::Interval;
using Vec3 = std::array<Rational, 3>;

Vec3 lift(const Point2& p) { return {p.x, p.y, Rational(1)}; }
Vec3 cross(const Vec3& u, const Vec3& v) {
  return {Rational(u[1] * v[2] - u[2] * v[1]), Rational(u[2] * v[0] - u[0] * v[2]),
          Rational(u[0] * v[1] - u[1] * v[0])};
}
Rational dot(const Vec3& u, const Vec3& v) { return Rational(u[0] * v[0] + u[1] * v[1] + u[2] * v[2]); }

// floor(log2 |x|) for x != 0, from the sizes of numerator and denominator (±1).
long log2_size(const Rational& x) {
  return static_cast<long>(mpz_sizeinbase(x.get_num_mpz_t(), 2)) -
         static_cast<long>(mpz_sizeinbase(x.get_den_mpz_t(), 2));
}

// Bits the closed form needs: the edge terms are O(ε) and τ is O(ε²) for a polygon of angular
// width ε (MATH §1a.7), so 2·log2(1/ε) bits cancel; add 53 for the answer and 40 guard bits.
unsigned automatic_precision(const std::vector<Point2>& v) {
  Rational width2 = 0;
  for (const Point2& p : v)
    width2 = std::max(width2, Rational((p.x - v[0].x) * (p.x - v[0].x) +
                                       (p.y - v[0].y) * (p.y - v[0].y)));
  const Rational norm2 = 1 + v[0].x * v[0].x + v[0].y * v[0].y;
  const long cancel = std::max(0L, log2_size(norm2) - log2_size(width2) + 2);
  return static_cast<unsigned>(53 + 40 + cancel);
}

// (τ1/τ3, τ2/τ3) for a polygon, or the segment's bisector direction, as enclosures.
std::array<Interval, 2> direction_map(const ConvexSet2& F, mpfr_prec_t bits) {
  const auto& v = F.vertices;
  std::array<Interval, 3> dir{Interval(0, bits), Interval(0, bits), Interval(0, bits)};
  if (F.kind == ConvexKind::segment) {
    // û1 + û2: the bisector of the end rays (MATH §1a.6).
    for (const Point2& p : v) {
      const Vec3 u = lift(p);
      const Interval inv_norm = Interval(1, bits) / sqrt(Interval(dot(u, u), bits));
      for (int k = 0; k < 3; ++k) dir[k] = dir[k] + inv_norm * u[k];
    }
  } else {
    // τ = ½ Σ θ_i c_i/|c_i|; the ½ cancels in the ratio, as does the orientation sign.
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Vec3 p = lift(v[i]), q = lift(v[(i + 1) % v.size()]);
      const Vec3 c = cross(p, q);  // exact
      const Interval norm = sqrt(Interval(dot(c, c), bits));
      const Interval theta = atan2(norm, Interval(dot(p, q), bits));
      const Interval w = theta / norm;
      for (int k = 0; k < 3; ++k) dir[k] = dir[k] + w * c[k];
    }
  }
  return {dir[0] / dir[2], dir[1] / dir[2]};
}

}  // namespace

MapEstimate mean_3d(const ConvexSet2& F, const Mean3dOptions& options) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("mean_3d: empty feasible set");
  if (F.kind == ConvexKind::point) {
    MapEstimate e = exact_map_estimate("mean_3d", F.vertices[0]);
    e.method = "analytic";
    return e;
  }
  // Precision is chosen from the polygon's size, then doubled until the certified enclosure
  // pins each component to 2^-60 relative (a forced precision is used once, as given).
  constexpr int target_bits = 60;
  constexpr unsigned max_bits = 1u << 20;
  unsigned bits = options.precision_bits ? options.precision_bits
                                          : automatic_precision(F.vertices);
  for (;;) {
    const std::array<Interval, 2> m = direction_map(F, bits);
    const bool done = options.precision_bits != 0 || bits >= max_bits ||
                      (internal::tight(m[0], target_bits) && internal::tight(m[1], target_bits));
    if (done) {
      MapEstimate e;
      e.rule = "mean_3d";
      e.method = "analytic";
      e.precision_bits = bits;
      for (int k = 0; k < 2; ++k) {
        const auto [value, bound] = internal::nearest_with_bound(m[k]);
        e.map[k] = value;
        e.error_bound = std::max(e.error_bound, bound);
        const auto [lo, hi] = internal::outward_doubles(m[k]);
        e.enclosure[k] = {lo, hi};
      }
      return e;
    }
    bits *= 2;
  }
}

}  // namespace gmcc
