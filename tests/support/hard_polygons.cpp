// The seeded generator of hard convex sets for the 3-D mean (Finlayson & Hordley 1999 §3.2;
// docs/math.md §2 and docs/accuracy.md "Reading" on why thin and far sets are hard: the edge terms of the closed
// form are O(w) while τ is O(w²), and quadrature's integrand varies on the scale √(1 + |x|²)).
//
// Everything is exact and platform-independent:
// - integers: uniform_below (rejection, then v mod n) on std::mt19937_64's raw 64-bit outputs;
// - magnitudes: (M/1000)·10^e with M in [1000, 9999] and e an integer, exactly;
// - shapes: points of the unit circle from the rational parametrisation
//   ((1 − t²)/(1 + t²), 2t/(1 + t²)), t = K/2^m (exactly on the circle, so in strictly convex
//   position), placed by an exact affine map c + r·(x·d + y·ε·n), which keeps convex position;
// - arcs: (s, h·(1 − s²)), a strictly concave curve over its chord.
// No floating-point function is called.
#include "hard_polygons.h"

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <utility>

namespace gmcc::test {

using Rng = std::mt19937_64;

std::uint64_t uniform_below(Rng& rng, std::uint64_t n) {
  if (n == 0) throw std::invalid_argument("uniform_below: n = 0");
  static_assert(Rng::min() == 0 && Rng::max() == ~std::uint64_t{0}, "64-bit raw outputs");
  // 2^64 mod n, computed without 2^64: (2^64 − n) mod n.
  const std::uint64_t excess = (std::uint64_t{0} - n) % n;
  const std::uint64_t limit = std::uint64_t{0} - excess;  // 2^64 − excess (0 means 2^64)
  for (;;) {
    const std::uint64_t v = rng();
    if (excess == 0 || v < limit) return v % n;
  }
}

namespace {

// Integer uniform on [lo, hi].
long uniform_int(Rng& rng, long lo, long hi) {
  return lo + static_cast<long>(uniform_below(rng, static_cast<std::uint64_t>(hi - lo) + 1));
}

Rational power_of_ten(int k) {
  mpz_class p;
  mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(k < 0 ? -k : k));
  return k < 0 ? Rational(mpz_class(1), p) : Rational(p);
}

// (M/1000)·10^e, M in [1000, 9999], e in [e_lo, e_hi − 1]: a value in [10^e_lo, 10^e_hi).
Rational log_uniform(Rng& rng, int e_lo, int e_hi) {
  const long m = uniform_int(rng, 1000, 9999);
  const int e = static_cast<int>(uniform_int(rng, e_lo, e_hi - 1));
  Rational r = Rational(m) * power_of_ten(e - 3);
  r.canonicalize();
  return r;
}

Rational dyadic(long k, int bits) {
  Rational r(k, 1);
  r /= Rational(mpz_class(1) << bits);
  r.canonicalize();
  return r;
}

// The unit circle point of parameter t (tan of half the angle), mirrored to x < 0 when `left`.
Point2 circle_point(const Rational& t, bool left) {
  const Rational den = 1 + t * t;
  Rational x = (1 - t * t) / den, y = 2 * t / den;
  if (left) x = -x;
  return {x, y};
}

// A random unit-circle point: t = K/2^16 with K in [−2^16, 2^16], either half.
Point2 random_circle_point(Rng& rng) {
  const Rational t = dyadic(uniform_int(rng, -(1L << 16), 1L << 16), 16);
  return circle_point(t, uniform_below(rng, 2) == 1);
}

Rational abs(const Rational& x) { return x < 0 ? Rational(-x) : x; }
Rational linf(const Point2& p) { return std::max(abs(p.x), abs(p.y)); }

// An exact affine frame: point (x, y) ↦ c + r·(x·d + y·n). |x|, |y| ≤ 1 stays within
// r·(|d|∞ + |n|∞) of c in each coordinate.
struct Frame {
  Point2 c, d, n;
  Rational r;
  Point2 at(const Rational& x, const Rational& y) const {
    return {Rational(c.x + r * (x * d.x + y * n.x)), Rational(c.y + r * (x * d.y + y * n.y))};
  }
  Point2 at(const Point2& p) const { return at(p.x, p.y); }
  // The largest r keeping every image of the unit square within 9/10 of the way to the axes.
  Rational max_radius() const {
    return Rational(9, 10) * std::min(c.x, c.y) / (linf(d) + linf(n));
  }
};

// Directions: a random one (integers in [−1000, 1000], scaled to |d|∞ = 1), the radial one
// (along c) or the transverse one (perpendicular to c). n is d turned by 90°, so the width
// ratio of (x·d + y·ε·n) is exactly ε.
Point2 direction(Rng& rng, const Point2& c, unsigned mode) {
  Point2 d;
  if (mode == 1) {
    d = c;
  } else if (mode == 2) {
    d = {Rational(-c.y), c.x};
  } else {
    long dx = 0, dy = 0;
    while (dx == 0 && dy == 0) {
      dx = uniform_int(rng, -1000, 1000);
      dy = uniform_int(rng, -1000, 1000);
    }
    d = {Rational(dx), Rational(dy)};
  }
  const Rational s = linf(d);
  return {Rational(d.x / s), Rational(d.y / s)};
}
Point2 turned(const Point2& d, const Rational& scale) {
  return {Rational(-d.y * scale), Rational(d.x * scale)};
}

// n distinct integers in [lo, hi], sorted.
std::vector<long> distinct_integers(Rng& rng, unsigned n, long lo, long hi) {
  std::set<long> s;
  while (s.size() < n) s.insert(uniform_int(rng, lo, hi));
  return {s.begin(), s.end()};
}

ConvexSet2 hull_of(const Frame& f, const std::vector<Point2>& unit_points) {
  std::vector<Point2> p;
  p.reserve(unit_points.size());
  for (const Point2& u : unit_points) p.push_back(f.at(u));
  return convex_hull(p);
}

// n random circle points (duplicates possible: the hull drops them; at least 3 distinct).
std::vector<Point2> circle_points(Rng& rng, unsigned n) {
  for (;;) {
    std::vector<Point2> p;
    for (unsigned i = 0; i < n; ++i) p.push_back(random_circle_point(rng));
    std::vector<Point2> q = p;
    std::sort(q.begin(), q.end());
    if (std::unique(q.begin(), q.end()) - q.begin() >= 3) return p;
  }
}

// A frame of given centre and direction mode, aspect ε (n = ε·d⊥), radius = fraction·max.
Frame frame(Rng& rng, const Point2& c, unsigned dir_mode, const Rational& eps,
            const Rational& fraction) {
  Frame f{c, direction(rng, c, dir_mode), {}, 0};
  f.n = turned(f.d, eps);
  f.r = fraction * f.max_radius();
  return f;
}

// random: 3–12 vertices, diameter 0.1–10, centre 0.1–10 (a coordinate too small for the size
// is raised until the set fits in the quadrant, so a few centres reach about 12).
ConvexSet2 random_set(Rng& rng) {
  const unsigned n = static_cast<unsigned>(uniform_int(rng, 3, 12));
  Point2 c{log_uniform(rng, -1, 1), log_uniform(rng, -1, 1)};
  const Rational size = log_uniform(rng, -1, 1);
  const unsigned mode = static_cast<unsigned>(uniform_below(rng, 3));
  const Rational aspect(uniform_int(rng, 2, 8), 8);
  Frame f{c, {1, 0}, {0, aspect}, 0};
  if (mode == 1) f = frame(rng, c, 0, aspect, 1);
  f.r = size / 2;
  const Rational room = Rational(10, 9) * f.r * (linf(f.d) + linf(f.n));
  f.c.x = std::max(f.c.x, room);
  f.c.y = std::max(f.c.y, room);
  if (mode < 2) return hull_of(f, circle_points(rng, n));
  for (;;) {  // mode 2: the hull of n random points of the square (fewer vertices, odd shapes)
    std::vector<Point2> p;
    for (unsigned i = 0; i < n; ++i)
      p.push_back({dyadic(uniform_int(rng, -(1 << 20), 1 << 20), 20),
                   dyadic(uniform_int(rng, -(1 << 20), 1 << 20), 20)});
    const ConvexSet2 F = hull_of(f, p);
    if (F.kind == ConvexKind::polygon) return F;
  }
}

// A frame of relative thickness `thin` around a centre near 1 (decimal exponent in [-1, 1)),
// along a random, radial or transverse direction, with a radius of 10^-2 … 10 halved, capped
// so the set stays in the quadrant (the slivers' and the nearly collinear sets' common part).
Frame thin_frame(Rng& rng, const Rational& thin) {
  const Point2 c{log_uniform(rng, -1, 1), log_uniform(rng, -1, 1)};
  const unsigned dir = static_cast<unsigned>(uniform_below(rng, 3));
  Frame f = frame(rng, c, dir, thin, 1);
  f.r = std::min(Rational(log_uniform(rng, -2, 1) / 2), f.max_radius());
  return f;
}

// sliver: 3–40 vertices, c + r·(x·d + y·ε·n), ε = 10^-k with k in [6, 15], along a random,
// radial or transverse direction.
ConvexSet2 sliver_set(Rng& rng) {
  const unsigned n = static_cast<unsigned>(uniform_int(rng, 3, 40));
  const Rational eps = power_of_ten(-static_cast<int>(uniform_int(rng, 6, 15)));
  const Frame f = thin_frame(rng, eps);  // drawn before the points (argument order is unspecified)
  return hull_of(f, circle_points(rng, n));
}

// far / small: 3–12 vertices around a centre whose coordinates have decimal exponents in
// [e_lo, e_hi) (far: one coordinate may be ordinary instead), radius a fraction
// 10^-10 … 1 (far) or 10^-6 … 1 (small) of the largest that keeps the set in the quadrant.
ConvexSet2 far_or_small_set(Rng& rng, bool far) {
  const unsigned n = static_cast<unsigned>(uniform_int(rng, 3, 12));
  Point2 c;
  if (far) {
    c = {log_uniform(rng, 6, 12), log_uniform(rng, 6, 12)};
    const unsigned mixed = static_cast<unsigned>(uniform_below(rng, 4));  // 0, 1: one ordinary
    if (mixed == 0) c.x = log_uniform(rng, -1, 1);
    if (mixed == 1) c.y = log_uniform(rng, -1, 1);
  } else {
    c = {log_uniform(rng, -12, -6), log_uniform(rng, -12, -6)};
  }
  const Rational fraction = log_uniform(rng, far ? -10 : -6, 0);
  const Rational aspect(uniform_int(rng, 1, 8), 8);
  const unsigned dir = static_cast<unsigned>(uniform_below(rng, 3));
  return hull_of(frame(rng, c, dir, aspect, fraction), circle_points(rng, n));
}

// collinear: 3–30 vertices (s, h·(1 − s²)), s = 2t − 1 for distinct t = K/2^20 including both
// ends, bulge h = 10^-k with k in [3, 14]: nearly on a chord, like a thin image hull.
ConvexSet2 collinear_set(Rng& rng) {
  const unsigned n = static_cast<unsigned>(uniform_int(rng, 3, 30));
  const Rational h = power_of_ten(-static_cast<int>(uniform_int(rng, 3, 14)));
  const Frame f = thin_frame(rng, h);
  std::set<long> ks{0, 1 << 20};
  while (ks.size() < n) ks.insert(uniform_int(rng, 1, (1 << 20) - 1));
  std::vector<Point2> p;
  for (long k : ks) {
    const Rational s = 2 * dyadic(k, 20) - 1;
    p.push_back({s, Rational(1 - s * s)});  // n already carries the factor h
  }
  return hull_of(f, p);
}

// many: 28–200 vertices on an ellipse (a third of the cases the whole ellipse, else an arc
// t in [−A/256, B/256] of its right half and the chord), half of them thin (aspect 10^-k,
// k in [1, 12]).
ConvexSet2 many_set(Rng& rng) {
  const unsigned n = static_cast<unsigned>(uniform_int(rng, 28, 200));
  const bool full = uniform_below(rng, 3) == 0;
  const bool thin = uniform_below(rng, 2) == 0;
  const Rational aspect = thin ? power_of_ten(-static_cast<int>(uniform_int(rng, 1, 12)))
                               : Rational(uniform_int(rng, 2, 8), 8);
  const Point2 c{log_uniform(rng, -1, 1), log_uniform(rng, -1, 1)};
  const unsigned dir = static_cast<unsigned>(uniform_below(rng, 3));
  Frame f = frame(rng, c, dir, aspect, 1);
  f.r = std::min(Rational(log_uniform(rng, -2, 1) / 2), f.max_radius());
  std::vector<Point2> p;
  constexpr int bits = 24;
  if (full) {
    // t in (−1, 1) on each half: distinct points, the left half at x < 0.
    std::set<std::pair<long, bool>> s;
    while (s.size() < n)
      s.insert({uniform_int(rng, -(1L << bits) + 1, (1L << bits) - 1), uniform_below(rng, 2) == 1});
    for (const auto& [k, left] : s) p.push_back(circle_point(dyadic(k, bits), left));
  } else {
    long a = 0, b = 0;
    while (a + b < 64) {  // arc at least a quarter of t's range
      a = uniform_int(rng, 0, 256);
      b = uniform_int(rng, 0, 256);
    }
    const long lo = -(a << (bits - 8)), hi = b << (bits - 8);
    for (long k : distinct_integers(rng, n, lo, hi)) p.push_back(circle_point(dyadic(k, bits), false));
  }
  return hull_of(f, p);
}

// segment: two points, by mode: random in [0.1, 10)²; short (half-length 10^-k of the room,
// k in [1, 15]) along a random direction; far; small; short and radial.
ConvexSet2 segment_set(Rng& rng) {
  const unsigned mode = static_cast<unsigned>(uniform_below(rng, 5));
  if (mode == 0) {
    for (;;) {
      const Point2 a{log_uniform(rng, -1, 1), log_uniform(rng, -1, 1)};
      const Point2 b{log_uniform(rng, -1, 1), log_uniform(rng, -1, 1)};
      if (a != b) return convex_hull({a, b});
    }
  }
  Point2 c{log_uniform(rng, -1, 1), log_uniform(rng, -1, 1)};
  Rational fraction = power_of_ten(-static_cast<int>(uniform_int(rng, 1, 15)));
  unsigned dir = 0;
  if (mode == 2) {
    c = {log_uniform(rng, 6, 12), log_uniform(rng, 6, 12)};
    fraction = log_uniform(rng, -10, 0);
  } else if (mode == 3) {
    c = {log_uniform(rng, -12, -6), log_uniform(rng, -12, -6)};
    fraction = log_uniform(rng, -6, 0);
  } else if (mode == 4) {
    dir = 1;
  }
  const Frame f = frame(rng, c, dir, 0, fraction);
  return convex_hull({f.at(-1, 0), f.at(1, 0)});
}

// point: (P/Q, P'/Q') with Q, Q' odd-ish (non-dyadic), magnitudes 1e-12 … 1e12, or a decimal.
ConvexSet2 point_set(Rng& rng) {
  Point2 p;
  if (uniform_below(rng, 2) == 0) {
    p = {log_uniform(rng, -12, 12), log_uniform(rng, -12, 12)};
  } else {
    const auto ratio = [&rng] {
      Rational r(uniform_int(rng, 1, 1000000), 2 * uniform_int(rng, 1, 500000) + 1);
      r.canonicalize();
      return Rational(r * power_of_ten(static_cast<int>(uniform_int(rng, -6, 6))));
    };
    p = {ratio(), ratio()};
  }
  return convex_hull({p});
}

std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::vector<Point2> chromaticities(const std::vector<std::array<const char*, 3>>& rgb) {
  std::vector<Point2> q;
  for (const auto& c : rgb)
    q.push_back(perspective_chromaticity({parse_rational(c[0]), parse_rational(c[1]),
                                          parse_rational(c[2])}));
  return q;
}

}  // namespace

const std::vector<HardCategory>& hard_categories() {
  static const std::vector<HardCategory> all{
      HardCategory::random,    HardCategory::sliver, HardCategory::far,     HardCategory::small,
      HardCategory::collinear, HardCategory::many,   HardCategory::segment, HardCategory::point};
  return all;
}

std::string to_string(HardCategory category) {
  switch (category) {
    case HardCategory::random: return "random";
    case HardCategory::sliver: return "sliver";
    case HardCategory::far: return "far";
    case HardCategory::small: return "small";
    case HardCategory::collinear: return "collinear";
    case HardCategory::many: return "many";
    case HardCategory::segment: return "segment";
    case HardCategory::point: return "point";
  }
  return "?";
}

HardCase make_hard_case(HardCategory category, std::uint64_t seed, unsigned index) {
  Rng rng(splitmix64(splitmix64(splitmix64(seed) ^ static_cast<std::uint64_t>(category)) ^ index));
  ConvexSet2 F;
  switch (category) {
    case HardCategory::random: F = random_set(rng); break;
    case HardCategory::sliver: F = sliver_set(rng); break;
    case HardCategory::far: F = far_or_small_set(rng, true); break;
    case HardCategory::small: F = far_or_small_set(rng, false); break;
    case HardCategory::collinear: F = collinear_set(rng); break;
    case HardCategory::many: F = many_set(rng); break;
    case HardCategory::segment: F = segment_set(rng); break;
    case HardCategory::point: F = point_set(rng); break;
  }
  for (const Point2& v : F.vertices)
    if (v.x <= 0 || v.y <= 0) throw std::logic_error("hard_polygons: vertex outside the quadrant");
  return {to_string(category) + "#" + std::to_string(index), to_string(category), std::move(F)};
}

std::vector<HardCase> hard_cases(std::uint64_t seed, unsigned count) {
  const auto& all = hard_categories();
  std::vector<HardCase> cases;
  cases.reserve(count);
  for (unsigned i = 0; i < count; ++i)
    cases.push_back(make_hard_case(all[i % all.size()], seed, i / static_cast<unsigned>(all.size())));
  return cases;
}

HardCase make_wide_case(std::uint64_t seed, unsigned index) {
  Rng rng(splitmix64(splitmix64(splitmix64(seed) ^ 0x77696465ULL) ^ index));  // "wide"
  const unsigned n = static_cast<unsigned>(uniform_int(rng, 3, 12));
  const Point2 c{Rational(uniform_int(rng, 500, 1500), 1000), Rational(uniform_int(rng, 500, 1500), 1000)};
  const Rational aspect(uniform_int(rng, 4, 8), 8);
  const Rational fraction(uniform_int(rng, 6, 8), 8);
  // Axis-aligned, so the room is exactly (9/10)·min(c.x, c.y/aspect).
  const Frame f{c, {1, 0}, {0, aspect}, fraction * Rational(9, 10) * std::min(c.x, Rational(c.y / aspect))};
  const ConvexSet2 F = hull_of(f, circle_points(rng, n));
  return {"wide#" + std::to_string(index), "wide", F};
}

HardCase reproducer_thin_triangle() {
  const std::vector<Point2> canonical =
      chromaticities({{"1", "1", "1"}, {"2", "3", "1"}, {"3/2", "2.000000000000001", "1"}});
  const std::vector<Point2> image = chromaticities({{"1", "1", "1"}});
  return {"reproducer-a", "reproducer", feasible_set(convex_hull(canonical), image)};
}

HardCase reproducer_feasible_set() {
  const std::vector<Point2> canonical = chromaticities({{"4259/625", "12317/2500", "1"},
                                                        {"1897/5000", "6479/1000", "1"},
                                                        {"17621/2500", "281/40", "1"},
                                                        {"11147/2500", "35671/5000", "1"},
                                                        {"2167/500", "749/625", "1"},
                                                        {"11491/5000", "2863/1250", "1"}});
  const std::vector<Point2> image =
      chromaticities({{"76518/78125", "297531/312500", "117/125"},
                      {"2372193/2500000", "1278647/1250000", "853/1000"},
                      {"378191369991/500000000000", "389911170267/500000000000", "699/1000"}});
  return {"reproducer-b", "reproducer", feasible_set(convex_hull(canonical), image)};
}

}  // namespace gmcc::test
