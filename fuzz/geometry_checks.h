#pragma once
// The exact checks fuzz_geometry and fuzz_hard_geometry share: canonical form of a ConvexSet2, the
// feasible set's definition by brute force, the separating-axis box test for the 3-D mean's
// enclosure, the certified route's enclosures and edge lines, and worst cases against probes.

#include "fuzz_support.h"

#include <gmcc/geometry/convex_set.h>
#include <gmcc/numerics/platform.h>
#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/rational.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gmcc::fuzz {

inline Rational reduced(const mpz_class& num, const mpz_class& den) {
  Rational r(num, den);
  r.canonicalize();
  return r;
}

inline mpz_class power_of_two(unsigned k) { return mpz_class(1) << k; }

inline std::string text(const Point2& p) { return "(" + gmcc::to_string(p.x) + ", " + gmcc::to_string(p.y) + ")"; }

inline void check_canonical(const ConvexSet2& s, const char* what) {
  const auto& v = s.vertices;
  const std::size_t n = v.size();
  switch (s.kind) {
    case ConvexKind::empty: FUZZ_CHECK(n == 0, what); break;
    case ConvexKind::point: FUZZ_CHECK(n == 1, what); break;
    case ConvexKind::segment: FUZZ_CHECK(n == 2 && v[0] < v[1], what); break;
    case ConvexKind::polygon:
      FUZZ_CHECK(n >= 3, what);
      for (std::size_t i = 0; i < n; ++i) {
        FUZZ_CHECK(sgn(gmcc::orientation(v[i], v[(i + 1) % n], v[(i + 2) % n])) > 0,
                   std::string(what) + ": not strictly convex counter-clockwise");
        FUZZ_CHECK(!(v[i] < v[0]), std::string(what) + ": does not start at the smallest vertex");
      }
      break;
  }
}

// p ∈ S by the definition of each kind: for a polygon, p on or left of every counter-clockwise
// edge, by exact orientation tests. Written here rather than taken from gmcc::contains, so that
// the brute force below is independent of the library (whose integer-scaled test costs
// O(|S| · size of the vertices' common denominator), much more on many-vertex sets). p is
// written once over one denominator, p = (X, Y)/D, and each edge's line through v_i, v_j as
// integers A, B, K (a positive multiple of dx = x_j − x_i, dy = y_j − y_i and dx·y_i − dy·x_i),
// so that orientation(v_i, v_j, p)·D·L = A·Y − B·X − K·D in ℤ: a point of 10^5 digits (a 2-D
// mean) against a 920-vertex F costs products, not 920 rational orientations (7 s before).
inline bool inside(const ConvexSet2& s, const Point2& p) {
  const auto& v = s.vertices;
  switch (s.kind) {
    case ConvexKind::empty: return false;
    case ConvexKind::point: return p == v[0];
    case ConvexKind::segment: return sgn(gmcc::orientation(v[0], v[1], p)) == 0 && !(p < v[0]) && !(v[1] < p);
    case ConvexKind::polygon: {
      mpz_class D;
      mpz_lcm(D.get_mpz_t(), p.x.get_den_mpz_t(), p.y.get_den_mpz_t());
      const mpz_class X = p.x.get_num() * (D / p.x.get_den()), Y = p.y.get_num() * (D / p.y.get_den());
      for (std::size_t i = 0; i < v.size(); ++i) {
        const Point2& a = v[i];
        const Point2& b = v[(i + 1) % v.size()];
        const Rational dx = b.x - a.x, dy = b.y - a.y, k = dx * a.y - dy * a.x;
        mpz_class L;
        mpz_lcm(L.get_mpz_t(), dx.get_den_mpz_t(), dy.get_den_mpz_t());
        mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), k.get_den_mpz_t());
        const mpz_class A = dx.get_num() * (L / dx.get_den()), B = dy.get_num() * (L / dy.get_den()),
                        K = k.get_num() * (L / k.get_den());
        if (sgn(mpz_class(A * Y - B * X - K * D)) < 0) return false;
      }
      return true;
    }
  }
  return false;
}

// m ⊙ q ∈ G for every q: the definition of the feasible set.
inline bool feasible(const ConvexSet2& G, const std::vector<Point2>& image, const Point2& m) {
  for (const Point2& q : image)
    if (!inside(G, {Rational(m.x * q.x), Rational(m.y * q.y)})) return false;
  return true;
}

// Does the closed box [lo0, hi0] × [lo1, hi1] meet the convex set F? Two compact convex
// polygons (degenerate ones too) are disjoint iff their projections on one of their edge
// normals are disjoint (separating axis theorem); the box's normals are the coordinate axes.
inline bool box_meets(const ConvexSet2& F, const Rational (&lo)[2], const Rational (&hi)[2]) {
  std::vector<Point2> axes{{1, 0}, {0, 1}};
  const auto& v = F.vertices;
  for (std::size_t i = 0; v.size() >= 2 && i < v.size(); ++i) {
    const Point2& p = v[i];
    const Point2& q = v[(i + 1) % v.size()];
    axes.push_back({Rational(p.y - q.y), Rational(q.x - p.x)});
  }
  const Point2 corners[4] = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
  for (const Point2& a : axes) {
    auto dot = [&a](const Point2& p) { return Rational(a.x * p.x + a.y * p.y); };
    Rational f_lo = dot(v[0]), f_hi = f_lo, b_lo = dot(corners[0]), b_hi = b_lo;
    for (const Point2& p : v) f_lo = std::min(f_lo, dot(p)), f_hi = std::max(f_hi, dot(p));
    for (const Point2& p : corners) b_lo = std::min(b_lo, dot(p)), b_hi = std::max(b_hi, dot(p));
    if (f_hi < b_lo || b_hi < f_lo) return false;
  }
  return true;
}

inline bool finite_doubles(const ConvexSet2& F) {
  for (const Point2& v : F.vertices) {
    const auto d = gmcc::to_double_nearest(v);
    if (!std::isfinite(d[0]) || !std::isfinite(d[1])) return false;
  }
  return true;
}

inline bool positive(const Point2& p) { return sgn(p.x) > 0 && sgn(p.y) > 0; }

// The real number x lies in mid ± rad (exactly: the enclosure's own claim, not its lo()/hi()).
inline bool in_enclosure(const Rational& x, const gmcc::Enclosure& e) {
  if (!e.finite()) return false;
  const Rational d = x - gmcc::rational_from_double(e.mid);
  return abs(d) <= gmcc::rational_from_double(e.rad);
}

// A long double as an exact rational: x = m·2^e with |m| in [0.5, 1), so m = k/2^64 exactly.
inline Rational exact_long(long double x) {
  int e = 0;
  const long double m = std::frexp(x, &e);
  const auto k = static_cast<unsigned long long>(std::ldexp(std::fabs(m), 64));
  Rational r(mpz_class(std::to_string(k)));
  if (e - 64 >= 0) r *= Rational(power_of_two(static_cast<unsigned>(e - 64)));
  else r /= Rational(power_of_two(static_cast<unsigned>(64 - e)));
  return x < 0 ? Rational(-r) : r;
}

// x lies in mid ± rad exactly, and rad is at most a relative 2^-60 of mid (the promised 2^-61,
// with room for the radius's own rounding up).
inline bool in_long_enclosure(const Rational& x, const gmcc::LongEnclosure& e) {
  if (!e.finite()) return false;
  if (!(e.rad <= std::fabs(e.mid) * 0x1p-60L + std::numeric_limits<long double>::min())) return false;
  return abs(Rational(x - exact_long(e.mid))) <= exact_long(e.rad);
}

// Extended precision is there (x87, 64-bit GMP limbs, full precision control; numerics/platform.h):
// extended_vertices() is then never empty for an enclosed P.
inline bool extended_expected() { return gmcc::numerics::extended_precision_active(); }

// The certified vertices and edges of an enclosed P against F's exact vertices: some rotation r
// puts F's vertex i in enclosure (i + r) mod n and in extended enclosure (i + r) mod n, and makes
// edge (i + r) the line from F's vertex i to i + 1, each coefficient within a relative 6u of the
// same positive multiple of the exact line's (so with its exact sign).
inline void check_enclosed(const gmcc::FeasiblePolygon& P, const ConvexSet2& F) {
  const auto& ev = P.vertices();
  const auto& el = P.edges();
  const auto& xv = P.extended_vertices();
  FUZZ_CHECK(xv.size() == ev.size() || (!extended_expected() && xv.empty()),
             "enclosed: " + std::to_string(xv.size()) + " extended enclosures for " + std::to_string(ev.size()) +
                 " vertices");
  const auto& v = F.vertices;
  const std::size_t n = v.size();
  FUZZ_CHECK(F.kind == ConvexKind::polygon && ev.size() == n && el.size() == n,
             "enclosed: " + std::to_string(ev.size()) + " enclosures, " + std::to_string(el.size()) +
                 " edges for " + std::to_string(n) + " vertices");
  const Rational six_u(6, power_of_two(53));
  auto edge_ok = [&](const gmcc::ApproximateLine& l, const Point2& p, const Point2& q) {
    // p → q counter-clockwise: F lies left of it, in (q.y − p.y)·x + (p.x − q.x)·y <= c.
    const Rational ea(q.y - p.y), eb(p.x - q.x), ec(ea * p.x + eb * p.y);
    const double approx[3] = {l.a, l.b, l.c};
    const Rational* exact[3] = {&ea, &eb, &ec};
    std::optional<Rational> lo, hi;
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(approx[k])) return false;
      const Rational a = gmcc::rational_from_double(approx[k]);
      if (sgn(a) != sgn(*exact[k])) return false;
      if (sgn(a) == 0) continue;
      const Rational ratio(a / *exact[k]);
      if (!lo || ratio < *lo) lo = ratio;
      if (!hi || *hi < ratio) hi = ratio;
    }
    // Some λ > 0 with every ratio in [λ(1 − 6u), λ(1 + 6u)].
    return lo && sgn(*lo) > 0 && *hi * (1 - six_u) <= *lo * (1 + six_u);
  };
  bool vertices_fit = false, extended_fit = false;
  for (std::size_t r = 0; r < n; ++r) {
    bool fit = true;
    for (std::size_t i = 0; i < n && fit; ++i)
      fit = in_enclosure(v[i].x, ev[(i + r) % n].x) && in_enclosure(v[i].y, ev[(i + r) % n].y);
    if (!fit) continue;
    vertices_fit = true;
    for (std::size_t i = 0; i < xv.size() && fit; ++i)
      fit = in_long_enclosure(v[i].x, xv[(i + r) % n].x) && in_long_enclosure(v[i].y, xv[(i + r) % n].y);
    if (!fit) continue;
    extended_fit = true;
    bool edges_fit = true;
    for (std::size_t i = 0; i < n && edges_fit; ++i) edges_fit = edge_ok(el[(i + r) % n], v[i], v[(i + 1) % n]);
    if (edges_fit) return;
  }
  FUZZ_CHECK(false, extended_fit ? "enclosed: an approximate edge line is not within 6u of its exact line"
                    : vertices_fit
                        ? "enclosed: no rotation that fits vertices() puts every vertex of F in its extended enclosure"
                        : "enclosed: no rotation puts every vertex of F in its enclosure");
}

// A worst case w is the maximum of `angle` over F: at least its value at every point given.
// Both are MPFR values rounded to double; when two points' angles agree to ~2^-100 their
// roundings may be a unit apart, hence the relative allowance.
template <class Angle>
inline void check_worst(double w, const std::vector<Point2>& in_F, Angle angle, const std::string& what) {
  FUZZ_CHECK(std::isfinite(w) && w >= 0 && w <= 180, what + " = " + std::to_string(w));
  for (const Point2& x : in_F) {
    const double a = angle(x);
    FUZZ_CHECK(a <= w + 1e-12 * (1 + w), what + " " + std::to_string(w) + " below the angle " +
                                             std::to_string(a) + " at " + text(x));
  }
}

}  // namespace gmcc::fuzz
