#include <gmcc/selection/mean_3d_monte_carlo.h>
#include <gmcc/numerics/filter_bounds.h>

#include <gmcc/numerics/interrupt.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace gmcc {
namespace {

// The closed half-space A·x + B·y + C·z >= 0 of directions whose perspective (x/z, y/z) lies
// left of a CCW edge p→q, exactly and as nearest doubles; filtered when each coefficient is 0 or
// its double in [2^-900, 2^900], so that the products with samples (0 or in [2^-53, 1)) are
// normal and the filter's relative bound holds.
struct Side {
  Rational a, b, c;
  double ad, bd, cd;
  bool filtered;
};
bool in_filter_range(const Rational& exact, double d) {
  return sgn(exact) == 0 || (std::fabs(d) >= 0x1p-900 && std::fabs(d) <= 0x1p900);
}

// Exact sign of A·x + B·y + C·z, with a floating-point filter in front: the coefficients' rounding
// to double (u each), three products and two sums, about 5u of the magnitude sum; 8u = 2^-50
// (filter_bounds.h).
int side_sign(const Side& s, double x, double y, double z) {
  if (s.filtered) {
    const double value = s.ad * x + s.bd * y + s.cd * z;
    const double bound =
        numerics::filter_bound::monte_carlo_side * (std::fabs(s.ad) * x + std::fabs(s.bd) * y + std::fabs(s.cd) * z);
    const numerics::UncertainSign filtered = numerics::sign_within(value, bound);
    if (filtered.is_certain()) return filtered.lo;
  }
  const Rational exact = s.a * rational_from_double(x) + s.b * rational_from_double(y) +
                         s.c * rational_from_double(z);
  return sgn(exact);
}

// x² + y² + z² <= 1, exactly (filtered the same way).
bool in_unit_ball(double x, double y, double z) {
  const double r2 = x * x + y * y + z * z;
  const double bound = numerics::filter_bound::monte_carlo_side * r2;
  if (r2 < 1 - bound) return true;
  if (r2 > 1 + bound) return false;
  const Rational rx = rational_from_double(x), ry = rational_from_double(y),
                 rz = rational_from_double(z);
  return rx * rx + ry * ry + rz * rz <= 1;
}

}  // namespace

MapEstimate mean_3d_monte_carlo(const ConvexSet2& F, std::uint64_t samples, std::uint64_t seed) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("mean_3d: empty feasible set");
  // A point is its own mean, exactly.
  MapEstimate e = F.kind == ConvexKind::point ? exact_map_estimate("mean_3d", F.vertices[0])
                                              : MapEstimate{};
  e.rule = "mean_3d";
  e.method = "monte-carlo";
  e.samples = samples;
  e.seed = seed;
  if (F.kind == ConvexKind::point) return e;
  if (F.kind == ConvexKind::segment) {
    e.valid = false;
    e.note = "the feasible set is a segment: its cone has no volume, so Monte Carlo cannot "
             "sample it (the analytic and quadrature routes can)";
    return e;
  }

  std::vector<Side> sides;
  const auto& v = F.vertices;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Point2& p = v[i];
    const Point2& q = v[(i + 1) % v.size()];
    Side s{Rational(p.y - q.y), Rational(q.x - p.x),
           Rational((q.y - p.y) * p.x - (q.x - p.x) * p.y), 0, 0, 0, false};
    s.ad = to_double_nearest(s.a), s.bd = to_double_nearest(s.b), s.cd = to_double_nearest(s.c);
    s.filtered = in_filter_range(s.a, s.ad) && in_filter_range(s.b, s.bd) && in_filter_range(s.c, s.cd);
    sides.push_back(std::move(s));
  }

  std::mt19937_64 generator(seed);
  auto uniform = [&generator] { return static_cast<double>(generator() >> 11) * 0x1p-53; };
  long double sx = 0, sy = 0, sz = 0, sxx = 0, syy = 0, szz = 0, sxz = 0, syz = 0;
  std::uint64_t kept = 0;
  for (std::uint64_t i = 0; i < samples; ++i) {
    if ((i & 0xffff) == 0) check_interrupt();  // a caller's Ctrl-C (interrupt.h)
    const double x = uniform(), y = uniform(), z = uniform();
    if (z == 0 || !in_unit_ball(x, y, z)) continue;
    bool inside = true;
    for (const Side& s : sides)
      if (side_sign(s, x, y, z) < 0) {
        inside = false;
        break;
      }
    if (!inside) continue;
    ++kept;
    sx += x, sy += y, sz += z;
    sxx += (long double)x * x, syy += (long double)y * y, szz += (long double)z * z;
    sxz += (long double)x * z, syz += (long double)y * z;
  }
  e.samples_kept = kept;
  if (kept < monte_carlo_min_kept) {
    e.valid = false;
    e.note = "only " + std::to_string(kept) + " of " + std::to_string(samples) +
             " samples fell in the cone over the feasible set (at least " +
             std::to_string(monte_carlo_min_kept) +
             " are needed): the set is too small for Monte Carlo at this sample count";
    return e;
  }
  const long double n = static_cast<long double>(kept);
  const long double m1 = sx / sz, m2 = sy / sz, mean_z = sz / n;
  e.map = {static_cast<double>(m1), static_cast<double>(m2)};
  // Delta method for a ratio of means: Var(X − m·Z)/n / E[Z]², with Bessel's correction.
  auto standard_error = [&](long double m, long double sqq, long double sqz) {
    const long double var = std::max(0.0L, (sqq - 2 * m * sqz + m * m * szz) / (n - 1));
    return static_cast<double>(std::sqrt(var / n) / mean_z);
  };
  e.standard_error = {standard_error(m1, sxx, sxz), standard_error(m2, syy, syz)};
  e.error_bounds = e.standard_error;
  e.error_bound = std::max(e.standard_error[0], e.standard_error[1]);
  return e;
}

}  // namespace gmcc
