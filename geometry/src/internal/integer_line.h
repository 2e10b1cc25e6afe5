#pragma once
// Exact lines with integer coefficients and their double filters: what feasible_polygon clips
// with (docs/derivations.md §4.3, docs/math.md §1a′). Internal to gmcc::geometry.

#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/numerics/filtered_sign.h>

#include "internal/half_plane.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>

namespace gmcc::internal {

// Exact clipping in homogeneous integer coordinates, with filtered predicates. A line (a, b, c)
// means a·x + b·y <= c with integer coefficients. A vertex is kept *symbolically*, as the pair of
// input lines it is the intersection of (docs/derivations.md §4.3: every vertex is the meet of two
// input lines, so constructions never nest). Every decision is the sign of a small determinant of
// line coefficients: it is first evaluated in double from rounded coefficients with a rigorous
// error bound, and only when |value| does not exceed the bound in exact integer arithmetic (GMP),
// from exact lines built on demand. Exact coordinates are constructed only for the final vertices.
struct Line {
  mpz_class a, b, c;
};
// u = 2^-53, the unit roundoff of double.
constexpr double u = numerics::unit_roundoff;
// Magnitudes allowed in filtered evaluation: every non-zero coefficient in [2^-300, 2^300], so
// that products of up to three stay normal (no underflow or overflow) and the error bounds
// below, which are relative, hold. Inputs outside this range take the exact path.
constexpr double filter_min = 0x1p-300, filter_max = 0x1p300;
inline bool in_filter_range(double x) { return x == 0 || (std::fabs(x) >= filter_min && std::fabs(x) <= filter_max); }

inline Line integer_line(const internal::HalfPlane& h) {
  const mpz_class l = lcm_of_denominators_of(h.a, h.b, h.c);
  Line line{times_lcm(h.a, l), times_lcm(h.b, l), times_lcm(h.c, l)};
  divide_by_content_of(line.a, line.b, line.c);
  return line;
}

// An integer line scaled by 2^-E (E its largest binary exponent) and truncated to doubles:
// mpz_get_d_2exp truncates to 53 bits, a relative error below 2^-52 = 2u; the scaling is exact.
// False (no filter) when a coefficient would fall below 2^-150 relative to the largest.
inline bool approx_line(const Line& l, ApproximateLine& out) {
  long e[3];
  const double m[3] = {mpz_get_d_2exp(&e[0], l.a.get_mpz_t()), mpz_get_d_2exp(&e[1], l.b.get_mpz_t()),
                       mpz_get_d_2exp(&e[2], l.c.get_mpz_t())};
  long top = 0;
  bool any = false;
  for (int k = 0; k < 3; ++k)
    if (m[k] != 0) top = any ? std::max(top, e[k]) : e[k], any = true;
  double r[3];
  for (int k = 0; k < 3; ++k) {
    if (m[k] == 0) {
      r[k] = 0;
      continue;
    }
    if (e[k] - top < -150) return false;
    r[k] = std::ldexp(m[k], static_cast<int>(e[k] - top));
  }
  out = {r[0], r[1], r[2]};
  return true;
}

// x = (X/W, Y/W) with W the lcm of the denominators: integers, no gcd per operation after.
struct HomogeneousPoint {
  mpz_class x, y, w;
};
inline HomogeneousPoint homogeneous(const Point2& p) {
  HomogeneousPoint h;
  h.w = lcm_of_denominators_of(p.x, p.y);
  h.x = times_lcm(p.x, h.w);
  h.y = times_lcm(p.y, h.w);
  return h;
}

}  // namespace gmcc::internal
