#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/grow_canonical.h>
#include <gmcc/geometry/intersection.h>

#include <stdexcept>

namespace gmcc {

GrownFeasibleSet grow_canonical_until_feasible(const std::vector<Point2>& chromaticities,
                                               const std::vector<Point2>& image,
                                               const std::optional<ConvexSet2>& constraint,
                                               const GrowCanonicalOptions& o) {
  if (sgn(o.precision) <= 0) throw std::invalid_argument("grow_canonical: precision must be > 0");
  if (sgn(o.start) < 0) throw std::invalid_argument("grow_canonical: start must be >= 0");
  // The hull's vertices expand to the same gamut as all the points, and are fewer.
  const std::vector<Point2> hull = convex_hull(chromaticities).vertices;
  auto at = [&](const Rational& factor) {
    GrownFeasibleSet g;
    g.factor = factor;
    g.canonical = canonical_gamut(
        hull, {sgn(factor) == 0 ? ExpansionPolicy::none : ExpansionPolicy::multiplicative, factor});
    g.feasible = feasible_set(g.canonical, image);
    if (constraint) g.feasible = intersection(g.feasible, *constraint);
    g.found = g.feasible.kind != ConvexKind::empty;
    return g;
  };

  GrownFeasibleSet hi = at(o.start);
  if (hi.found) return hi;
  Rational lo = o.start;
  Rational f = o.start * 2;
  if (f < 1) f = 1;
  for (;; f *= 2) {
    if (f > o.max_factor) f = o.max_factor;
    hi = at(f);
    if (hi.found) break;
    lo = f;
    if (f == o.max_factor) {
      hi.empty_below = lo;
      return hi;  // found == false
    }
  }
  while (hi.factor - lo > o.precision) {
    const Rational mid = (lo + hi.factor) / 2;
    GrownFeasibleSet g = at(mid);
    if (g.found)
      hi = std::move(g);
    else
      lo = mid;
  }
  hi.empty_below = lo;
  return hi;
}

}  // namespace gmcc
