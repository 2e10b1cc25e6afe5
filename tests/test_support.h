#pragma once
// Shared test fixtures: seeded generators of exact inputs and the definition of feasibility.
// Every random test names its generator and seed, so a failure reproduces.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/input/image_file.h>

#include <ostream>
#include <random>
#include <vector>

namespace gmcc {
// Printers so that failed assertions show exact values.
inline std::ostream& operator<<(std::ostream& os, ConvexKind k) { return os << to_string(k); }
inline std::ostream& operator<<(std::ostream& os, const Point2& p) {
  return os << "(" << to_string(p.x) << ", " << to_string(p.y) << ")";
}
inline std::ostream& operator<<(std::ostream& os, const ConvexSet2& s) {
  os << to_string(s.kind) << " [";
  for (const Point2& p : s.vertices) os << " " << p;
  return os << " ]";
}
}  // namespace gmcc

namespace gmcc::test {

/// The tests' named generator: 64-bit Mersenne Twister, seeded per test.
using Rng = std::mt19937_64;

/// A rational num/den with num in [lo, hi] and den in [1, max_den].
inline Rational random_rational(Rng& rng, long lo, long hi, long max_den) {
  std::uniform_int_distribution<long> num(lo, hi), den(1, max_den);
  Rational r(num(rng), den(rng));
  r.canonicalize();
  return r;
}

/// n points whose coordinates are k/max_den with k uniform in [lo, hi·max_den]: values in
/// [lo/max_den, hi] on a grid of step 1/max_den (so duplicates and collinear triples occur).
inline std::vector<Point2> random_points(Rng& rng, int n, long lo, long hi, long max_den) {
  std::uniform_int_distribution<long> k(lo, hi * max_den);
  std::vector<Point2> p;
  for (int i = 0; i < n; ++i) {
    Rational x(k(rng), max_den), y(k(rng), max_den);
    x.canonicalize();
    y.canonicalize();
    p.push_back({x, y});
  }
  return p;
}

/// (x, y), each random_rational(rng, lo, hi, max_den), x drawn first.
inline Point2 random_point(Rng& rng, long lo, long hi, long max_den) {
  Rational x = random_rational(rng, lo, hi, max_den);
  return {x, random_rational(rng, lo, hi, max_den)};
}

/// (x, y, z) likewise, in that order.
inline Point3 random_point3(Rng& rng, long lo, long hi, long max_den) {
  Rational x = random_rational(rng, lo, hi, max_den), y = random_rational(rng, lo, hi, max_den);
  return {x, y, random_rational(rng, lo, hi, max_den)};
}

/// `n` colours with channels random_rational(rng, lo, hi, max_den), drawn r, g, b in that order.
inline std::vector<Colour> random_colours(Rng& rng, int n, long lo, long hi, long max_den) {
  std::vector<Colour> out;
  for (int i = 0; i < n; ++i) {
    Rational r = random_rational(rng, lo, hi, max_den), g = random_rational(rng, lo, hi, max_den);
    out.push_back({r, g, random_rational(rng, lo, hi, max_den)});
  }
  return out;
}

/// q ⊘ d componentwise: what a noise-free scene under the map d shows of the canonical q.
inline Point2 divided(const Point2& q, const Point2& d) { return {Rational(q.x / d.x), Rational(q.y / d.y)}; }
/// The same in 3-D.
inline Point3 divided(const Point3& q, const Point3& d) {
  return {Rational(q.x / d.x), Rational(q.y / d.y), Rational(q.z / d.z)};
}
/// The same for a colour (r, g, b) under d = (d1, d2, d3).
inline Colour divided(const Colour& q, const Point3& d) {
  return {Rational(q.r / d.x), Rational(q.g / d.y), Rational(q.b / d.z)};
}

/// m ⊙ q, componentwise.
inline Point2 times(const Point2& m, const Point2& q) {
  return {Rational(m.x * q.x), Rational(m.y * q.y)};
}

/// The definition of the feasible set (docs/math.md §1): m is feasible iff m ⊙ q ∈ G_c for every q.
inline bool feasible_by_definition(const ConvexSet2& gamut, const std::vector<Point2>& image,
                                   const Point2& m) {
  for (const Point2& q : image)
    if (!contains(gamut, times(m, q))) return false;
  return true;
}

/// A w × h image of `bits`-bit samples (8 or 16) that differ from pixel to pixel and channel to
/// channel: sample i is (7919·i + 13) mod 2^bits, deterministic.
inline RgbImage ramp(std::size_t w, std::size_t h, int bits) {
  RgbImage im;
  im.width = w;
  im.height = h;
  im.bits = bits;
  for (std::size_t i = 0; i < w * h * 3; ++i)
    im.samples.push_back(static_cast<std::uint16_t>((i * 7919 + 13) % (bits == 8 ? 256 : 65536)));
  return im;
}

}  // namespace gmcc::test
