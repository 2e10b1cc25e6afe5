#include <gmcc/geometry/chromaticity_hull.h>
#include <gmcc/numerics/filter_bounds.h>

#include "internal/monotone_chain.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gmcc {
namespace {

using Colour3 = std::array<double, 3>;

// u = 2^-53. Error bounds (Higham; products and sums of non-negative magnitudes): a computed
// a·b − c·d is within 3u·(|ab| + |cd|) of the exact value, and the 3×3 cofactor expansion below
// within 8u·(its magnitude sum); the factors used here (numerics/filter_bounds.h: 4u, 16u) leave
// room, and a decision is taken in double only when |value| exceeds the bound. The bounds are
// relative, so they hold only where every product is a normal number: the filters run only when
// every channel is 0 or in [2^-100, 2^100] (then products of three channels, the chromaticities,
// the octagon's coefficients and their products are all normal); otherwise every predicate is
// exact (a colour scaled by 2^±1000 has the same chromaticity, and the same answer).
constexpr double u = numerics::unit_roundoff;
bool in_filter_range(const Colour3& c) {
  return std::all_of(c.begin(), c.end(), [](double x) { return x == 0 || (x >= 0x1p-100 && x <= 0x1p100); });
}

Rational exact(double x) { return rational_from_double(x); }

// sign(r1·b2 − r2·b1) (k = 0): the order of x = r/b; of y = g/b for k = 1.
int compare(const Colour3& p, const Colour3& q, std::size_t k, bool filtered) {
  if (filtered) {
    const double a = p[k] * q[2], b = q[k] * p[2];
    const numerics::UncertainSign s =
        numerics::sign_within(a - b, numerics::filter_bound::chromaticity_order * (std::fabs(a) + std::fabs(b)));
    if (s.is_certain()) return s.lo;
  }
  return sgn(Rational(exact(p[k]) * exact(q[2]) - exact(q[k]) * exact(p[2])));
}

// Orientation of the chromaticities of p, q, s: sign of det[p; q; s] (all b > 0).
int orientation3(const Colour3& p, const Colour3& q, const Colour3& s, bool filtered) {
  if (filtered) {
    const double m0 = q[1] * s[2] - s[1] * q[2], m1 = q[0] * s[2] - s[0] * q[2],
                 m2 = q[0] * s[1] - s[0] * q[1];
    const double det = p[0] * m0 - p[1] * m1 + p[2] * m2;
    const double mag = std::fabs(p[0]) * (std::fabs(q[1] * s[2]) + std::fabs(s[1] * q[2])) +
                       std::fabs(p[1]) * (std::fabs(q[0] * s[2]) + std::fabs(s[0] * q[2])) +
                       std::fabs(p[2]) * (std::fabs(q[0] * s[1]) + std::fabs(s[0] * q[1]));
    const numerics::UncertainSign filtered_sign =
        numerics::sign_within(det, numerics::filter_bound::chromaticity_orientation * mag);
    if (filtered_sign.is_certain()) return filtered_sign.lo;
  }
  const Rational P[3] = {exact(p[0]), exact(p[1]), exact(p[2])},
                 Q[3] = {exact(q[0]), exact(q[1]), exact(q[2])},
                 S[3] = {exact(s[0]), exact(s[1]), exact(s[2])};
  return sgn(Rational(P[0] * (Q[1] * S[2] - S[1] * Q[2]) - P[1] * (Q[0] * S[2] - S[0] * Q[2]) +
                      P[2] * (Q[0] * S[1] - S[0] * Q[1])));
}

// Akl–Toussaint: any polygon of input points lies inside the hull, so a point strictly inside
// it is no vertex. Its corners are the input points extreme (approximately) in the eight
// directions −x, −x−y, −y, x−y, x, x+y, y, y−x, in counter-clockwise order (approximation only
// chooses them: they are input points either way, and coinciding corners merely weaken the
// filter). The points not dropped.
std::vector<Colour3> outside_extreme_octagon(const std::vector<Colour3>& pts) {
  constexpr int sides = 8;
  static const double dir[sides][2] = {{-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 1}};
  std::size_t corner[sides] = {};
  double best[sides];
  for (int k = 0; k < sides; ++k) best[k] = -INFINITY;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = pts[i][0] / pts[i][2], y = pts[i][1] / pts[i][2];
    for (int k = 0; k < sides; ++k) {
      const double v = dir[k][0] * x + dir[k][1] * y;
      if (v > best[k]) best[k] = v, corner[k] = i;
    }
  }
  // Edge k of the octagon, from its exact corners: A·x + B·y + C > 0 strictly inside.
  // Its coefficients rounded to double, and x, y computed in double, the test value is within
  // 8u·(|A x| + |B y| + |C|) of the exact one (each factor off by at most 2u relative, sums
  // by 3u): a point is discarded only if every edge's value exceeds 16u of that magnitude.
  struct Edge {
    double a, b, c;
  };
  Edge edges[sides];
  for (int k = 0; k < sides; ++k) {
    const Colour3& p = pts[corner[k]];
    const Colour3& q = pts[corner[(k + 1) % sides]];
    const Rational px = exact(p[0]) / exact(p[2]), py = exact(p[1]) / exact(p[2]);
    const Rational qx = exact(q[0]) / exact(q[2]), qy = exact(q[1]) / exact(q[2]);
    // orientation(p, q, x) = (qx − px)(y − py) − (qy − py)(x − px) = A x + B y + C
    const Rational A = py - qy, B = qx - px, C = (qy - py) * px - (qx - px) * py;
    edges[k] = {to_double_nearest(A), to_double_nearest(B), to_double_nearest(C)};
  }
  std::vector<Colour3> survivors;
  for (const Colour3& p : pts) {
    const double x = p[0] / p[2], y = p[1] / p[2];
    bool inside = true;
    for (int k = 0; k < sides && inside; ++k) {
      const Edge& e = edges[k];
      const double ax = e.a * x, by = e.b * y;
      const double value = ax + by + e.c;
      inside = value > 16 * u * (std::fabs(ax) + std::fabs(by) + std::fabs(e.c));
    }
    if (!inside) survivors.push_back(p);
  }
  return survivors;
}

}  // namespace

ChromaticityHull chromaticity_hull(const std::vector<std::array<double, 3>>& colours) {
  ChromaticityHull out;
  std::vector<Colour3> pts;
  pts.reserve(colours.size());
  for (const Colour3& c : colours) {
    for (double x : c)
      if (!std::isfinite(x) || x < 0)
        throw std::invalid_argument("chromaticity_hull: channels must be finite and >= 0");
    if (c[2] > 0)
      pts.push_back(c);
    else
      ++out.dropped;
  }
  if (pts.empty()) return out;
  const bool filtered = std::all_of(pts.begin(), pts.end(), in_filter_range);
  std::vector<Colour3> survivors = filtered ? outside_extreme_octagon(pts) : std::move(pts);

  // The hull of the survivors' distinct chromaticities, with exact (filtered) predicates.
  std::sort(survivors.begin(), survivors.end(), [filtered](const Colour3& p, const Colour3& q) {
    const int c = compare(p, q, 0, filtered);
    return c != 0 ? c < 0 : compare(p, q, 1, filtered) < 0;
  });
  survivors.erase(std::unique(survivors.begin(), survivors.end(),
                              [filtered](const Colour3& p, const Colour3& q) {
                                return compare(p, q, 0, filtered) == 0 && compare(p, q, 1, filtered) == 0;
                              }),
                  survivors.end());
  const std::vector<std::size_t> hull = internal::monotone_chain(survivors.size(), [&](std::size_t a, std::size_t b, std::size_t c) {
    return orientation3(survivors[a], survivors[b], survivors[c], filtered) > 0;
  });
  std::vector<Point2> cycle;
  cycle.reserve(hull.size());
  for (std::size_t i : hull) {
    const Colour3& c = survivors[i];
    const Rational b = exact(c[2]);
    cycle.push_back({Rational(exact(c[0]) / b), Rational(exact(c[1]) / b)});
  }
  out.hull = canonical_convex_set(std::move(cycle));
  return out;
}

}  // namespace gmcc

namespace gmcc {

namespace {
using Pixel = std::array<std::uint16_t, 3>;

// Akl & Toussaint (1978), exactly: the points extreme in eight directions of the chromaticity
// plane lie on the hull in counter-clockwise order (ties: any point of the extreme face keeps
// that order), so a point strictly inside every edge of their octagon is no hull vertex and
// is dropped before the sort. Direction (α, β) ranks (α·r + β·g)/b, compared by
// cross-multiplication: |α·r + β·g| < 2^17 and b < 2^16, so the products fit in 64 bits.
// Points equal by `same` (the same chromaticity) are kept or dropped together.
template <class Same>
void drop_inside_extreme_octagon(std::vector<Pixel>& p, Same same) {
  using C = Pixel;
  if (p.size() > 64) {
    static constexpr int dir[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    // Per direction, the best point's rank as the fraction num/den (den = its b).
    std::int64_t num[8], den[8];
    std::size_t best[8];
    for (int d = 0; d < 8; ++d) {
      best[d] = 0;
      num[d] = dir[d][0] * std::int64_t(p[0][0]) + dir[d][1] * std::int64_t(p[0][1]);
      den[d] = p[0][2];
    }
    for (std::size_t i = 1; i < p.size(); ++i) {
      const std::int64_t r = p[i][0], g = p[i][1], b = p[i][2];
      for (int d = 0; d < 8; ++d) {
        const std::int64_t f = dir[d][0] * r + dir[d][1] * g;
        if (f * den[d] > num[d] * b) {
          best[d] = i;
          num[d] = f;
          den[d] = b;
        }
      }
    }
    std::vector<C> corner;
    for (int d = 0; d < 8; ++d) {
      const C& c = p[best[d]];
      if (corner.empty() || !same(corner.back(), c)) corner.push_back(c);
    }
    while (corner.size() > 1 && same(corner.back(), corner.front())) corner.pop_back();
    if (corner.size() >= 3) {
      // orient(a, b, c) = det[a; b; c] = (a × b) · c: each edge's cross product once (entries
      // below 2^33), then three products below 2^49 per point; the same exact value.
      // Fewer than eight distinct corners: the first edge fills the rest (a repeated test), so
      // that every point takes the same eight branch-free tests.
      const std::size_t k = corner.size();
      std::array<std::array<std::int64_t, 3>, 8> normal;
      for (std::size_t e = 0; e < k; ++e) {
        const C& a = corner[e];
        const C& b = corner[(e + 1) % k];
        normal[e] = {std::int64_t(a[1]) * b[2] - std::int64_t(a[2]) * b[1],
                     std::int64_t(a[2]) * b[0] - std::int64_t(a[0]) * b[2],
                     std::int64_t(a[0]) * b[1] - std::int64_t(a[1]) * b[0]};
      }
      for (std::size_t e = k; e < 8; ++e) normal[e] = normal[0];
      auto inside = [&normal](const C& c) {
        bool in = true;
        for (std::size_t e = 0; e < 8; ++e)
          in &= normal[e][0] * c[0] + normal[e][1] * c[1] + normal[e][2] * c[2] > 0;
        return in;
      };
      p.erase(std::remove_if(p.begin(), p.end(), inside), p.end());
    }
  }
}
}  // namespace

ChromaticityHull chromaticity_hull_of_pixels(const std::vector<std::array<std::uint16_t, 3>>& colours) {
  using C = std::array<std::uint16_t, 3>;
  ChromaticityHull out;
  std::vector<C> p;
  p.reserve(colours.size());
  for (const C& c : colours) {
    if (c[2] == 0) ++out.dropped;
    else p.push_back(c);
  }
  // (r1/b1, g1/b1) < (r2/b2, g2/b2) lexicographically, by cross-multiplication (below 2^32).
  auto less = [](const C& a, const C& b) {
    const std::uint64_t xa = std::uint64_t(a[0]) * b[2], xb = std::uint64_t(b[0]) * a[2];
    if (xa != xb) return xa < xb;
    return std::uint64_t(a[1]) * b[2] < std::uint64_t(b[1]) * a[2];
  };
  auto same = [](const C& a, const C& b) {
    return std::uint64_t(a[0]) * b[2] == std::uint64_t(b[0]) * a[2] &&
           std::uint64_t(a[1]) * b[2] == std::uint64_t(b[1]) * a[2];
  };
  // sign of det[(r,g,b)_a; _o... ]: the orientation of the chromaticities of o, a, b (b's > 0).
  auto orient = [](const C& o, const C& a, const C& b) {
    const std::int64_t r0 = o[0], g0 = o[1], b0 = o[2], r1 = a[0], g1 = a[1], b1 = a[2],
                       r2 = b[0], g2 = b[1], b2 = b[2];
    const std::int64_t det = r0 * (g1 * b2 - g2 * b1) - g0 * (r1 * b2 - r2 * b1) +
                             b0 * (r1 * g2 - r2 * g1);
    return (det > 0) - (det < 0);
  };
  drop_inside_extreme_octagon(p, same);
  std::sort(p.begin(), p.end(), less);
  p.erase(std::unique(p.begin(), p.end(), same), p.end());
  std::vector<C> hull;
  for (std::size_t i : internal::monotone_chain(p.size(), [&](std::size_t a, std::size_t b, std::size_t c) {
         return orient(p[a], p[b], p[c]) > 0;
       }))
    hull.push_back(p[i]);
  out.hull.kind = hull.empty()        ? ConvexKind::empty
                  : hull.size() == 1 ? ConvexKind::point
                  : hull.size() == 2 ? ConvexKind::segment
                                     : ConvexKind::polygon;
  for (const C& c : hull) {
    Point2 v{Rational(static_cast<unsigned long>(c[0]), static_cast<unsigned long>(c[2])),
             Rational(static_cast<unsigned long>(c[1]), static_cast<unsigned long>(c[2]))};
    v.x.canonicalize();
    v.y.canonicalize();
    out.hull.vertices.push_back(std::move(v));
  }
  return out;
}

}  // namespace gmcc
