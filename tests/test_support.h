#pragma once
// Shared test fixtures: seeded generators of exact inputs and the definition of feasibility.
// Every random test names its generator and seed, so a failure reproduces.

#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/convex_set.h>

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

}  // namespace gmcc::test
