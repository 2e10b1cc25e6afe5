// The 2-D hull: a filtered monotone chain. CGAL's convex_hull_2, which it replaced, is the tests'
// and bench_hull's oracle in tests/support/cgal_references.h, not part of the library.
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/rational_enclosure.h>

#include "internal/monotone_chain.h"

#include <algorithm>
#include <numeric>

namespace gmcc {
namespace {

// The sign of a − b, from the enclosures when they are apart, else exactly (mpq_cmp, no gcd).
int compare(const Rational& a, const Rational& b, const Enclosure& ea, const Enclosure& eb) {
  if (ea.hi() < eb.lo()) return -1;
  if (ea.lo() > eb.hi()) return 1;
  return cmp(a, b);
}

struct Approx {
  Enclosure x, y;
};

// The sign of orientation(a, b, c) = (b − a) × (c − a). Filter: the determinant enclosed from
// the coordinates' enclosures. The differences' radii are about u times the coordinates, not
// times the differences, so for close, nearly collinear points (a many-vertex gamut on a curve:
// determinants near 10^-18 at 10^6 points of a unit parabola) the enclosure stays about u·|b − a|
// wide and decides; exact rationals otherwise.
int turn(const Point2& a, const Point2& b, const Point2& c, const Approx& ea, const Approx& eb, const Approx& ec) {
  const Enclosure d = (eb.x - ea.x) * (ec.y - ea.y) - (eb.y - ea.y) * (ec.x - ea.x);
  if (d.finite()) {
    if (certainly_positive(d)) return 1;
    if (certainly_negative(d)) return -1;
  }
  return sgn(orientation(a, b, c));
}
}  // namespace

// Andrew's monotone chain on indices, with filtered predicates. CGAL's lazy exact kernel spent
// about 17 µs a point on its lazy numbers' allocations (19 s for the 10^6-point parabola of
// issue 13); this spends well under 1 µs where the filters decide (docs/performance-history.md,
// "Many-vertex canonical gamuts (issue 13)").
ConvexSet2 convex_hull(const std::vector<Point2>& points) {
  const std::size_t n = points.size();
  std::vector<Approx> e(n);
  for (std::size_t i = 0; i < n; ++i) e[i] = {enclose_rational(points[i].x), enclose_rational(points[i].y)};
  auto order = [&](std::size_t i, std::size_t j) {  // lexicographic: x, then y
    const int x = compare(points[i].x, points[j].x, e[i].x, e[j].x);
    return x ? x : compare(points[i].y, points[j].y, e[i].y, e[j].y);
  };
  std::vector<std::size_t> p(n);
  std::iota(p.begin(), p.end(), std::size_t(0));
  std::sort(p.begin(), p.end(), [&](std::size_t i, std::size_t j) { return order(i, j) < 0; });
  p.erase(std::unique(p.begin(), p.end(), [&](std::size_t i, std::size_t j) { return order(i, j) == 0; }), p.end());
  const std::size_t m = p.size();
  if (m < 3) {  // empty, a point or a segment
    std::vector<Point2> few;
    for (std::size_t i : p) few.push_back(points[i]);
    return canonical_convex_set(std::move(few));
  }
  const std::vector<std::size_t> h = internal::monotone_chain(m, [&](std::size_t i, std::size_t j, std::size_t k) {
    return turn(points[p[i]], points[p[j]], points[p[k]], e[p[i]], e[p[j]], e[p[k]]) > 0;
  });
  std::vector<Point2> cycle;
  cycle.reserve(h.size());
  for (std::size_t i : h) cycle.push_back(points[p[i]]);
  if (cycle.size() < 3) return canonical_convex_set(std::move(cycle));  // all collinear: a segment
  // Every kept turn is strictly left, the cycle runs counter-clockwise from the lexicographically
  // smallest point: already canonical.
  ConvexSet2 out;
  out.kind = ConvexKind::polygon;
  out.vertices = std::move(cycle);
  return out;
}

}  // namespace gmcc
