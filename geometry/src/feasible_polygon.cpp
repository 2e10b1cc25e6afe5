#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_polygon.h>

#include "internal/canonical_lines.h"
#include "internal/polygon_clipper.h"
#include "internal/convex_clip.h"
#include "internal/extended_value.h"
#include "internal/feasible_polygon_route.h"
#include "internal/image_hull.h"
#include "internal/integer_line.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace gmcc {

using internal::approx;
using internal::PolygonClipper;
using internal::ConvexClip;
using internal::ImagePoint;
using internal::in_filter_range;
using internal::integer_line;
using internal::Vertex;

struct internal::FeasiblePolygonState {
  std::vector<Point2> owned;        // the image hull's vertices, when the caller's may not outlive F
  std::optional<PolygonClipper> clipper;   // absent when F is empty before clipping ends
  std::vector<Vertex> cycle;        // reduced; strictly convex when enclosed
  ConvexKind kind = ConvexKind::empty;
  bool strictly_convex = false;
  std::vector<EnclosedVertex> vertices;
  std::optional<std::vector<LongEnclosedVertex>> long_vertices;  // built on first use
  std::vector<ApproximateLine> edges;
  std::optional<ConvexSet2> exact;
};

// Builds FeasiblePolygon: the one friend of it and of CanonicalConstraints.
struct internal::FeasiblePolygonAccess {
  static FeasiblePolygon build(const CanonicalConstraints& canonical, const std::vector<const Point2*>& image,
                              bool copy_image, bool linear = true);
};

FeasiblePolygon internal::feasible_polygon(const CanonicalConstraints& canonical, const std::vector<Point2>& image,
                                           Clipping route) {
  std::vector<const Point2*> pointers;
  pointers.reserve(image.size());
  for (const Point2& q : image) pointers.push_back(&q);
  return internal::FeasiblePolygonAccess::build(canonical, pointers, true, route == Clipping::convex_pass);
}

FeasiblePolygon feasible_polygon(const CanonicalConstraints& canonical, const std::vector<Point2>& image) {
  return internal::feasible_polygon(canonical, image, internal::Clipping::convex_pass);
}

FeasiblePolygon feasible_polygon(const CanonicalConstraints& canonical, const std::vector<const Point2*>& image) {
  return internal::FeasiblePolygonAccess::build(canonical, image, false);
}

namespace {

// The image hull's vertices (only they constrain F; interior colours add implied constraints),
// checked, and the largest image chromaticity components, which bound F's box.
struct ImageHull {
  std::vector<ImagePoint> vertices;
  Rational max_x, max_y;
};

// The hull of `image`, its vertices copied into `owned` when F may outlive the caller's image.
// \throws std::invalid_argument, UnboundedFeasibleSet as feasible_set.
ImageHull checked_image_hull(const std::vector<const Point2*>& image, std::vector<Point2>* owned) {
  if (image.empty()) throw std::invalid_argument("feasible_set: no image chromaticities");
  for (const Point2* q : image)
    if (sgn(q->x) < 0 || sgn(q->y) < 0)
      throw std::invalid_argument("feasible_set: an image chromaticity is negative");
  ImageHull h{internal::image_hull_vertices(image), 0, 0};
  if (owned) {
    owned->reserve(h.vertices.size());
    for (ImagePoint& q : h.vertices) owned->push_back(*q.exact), q.exact = &owned->back();
  }
  auto max_of = [&h](Rational Point2::*c) {
    const Rational* m = &(h.vertices.front().exact->*c);
    for (const ImagePoint& p : h.vertices) m = std::max(m, &(p.exact->*c), [](auto a, auto b) { return *a < *b; });
    return *m;
  };
  h.max_x = max_of(&Point2::x), h.max_y = max_of(&Point2::y);
  if (sgn(h.max_x) == 0)
    throw UnboundedFeasibleSet("every image colour has r = 0: the map's red component is "
                               "unconstrained and the feasible set is unbounded");
  if (sgn(h.max_y) == 0)
    throw UnboundedFeasibleSet("every image colour has g = 0: the map's green component is "
                               "unconstrained and the feasible set is unbounded");
  return h;
}

// The cycle the clipping starts from. G_c ⊘ q for an image vertex q > 0 when G_c is a polygon:
// its vertices are the meets of consecutive scaled edges (a positive diagonal scaling keeps the
// order counter-clockwise), which saves q's clips and any box; `first` is then q's index, else
// the number of image vertices.
std::vector<Vertex> starting_cycle(PolygonClipper& c, const internal::CanonicalLines& g, const ImageHull& h,
                                   std::size_t& first) {
  const std::size_t k_count = h.vertices.size(), m = g.lines.size();
  first = k_count;
  if (g.polygon)
    for (std::size_t k = 0; k < k_count && first == k_count; ++k)
      if (sgn(h.vertices[k].exact->x) > 0 && sgn(h.vertices[k].exact->y) > 0) first = k;
  std::vector<Vertex> cycle;
  if (first < k_count) {
    std::vector<std::size_t> lines(m);
    for (std::size_t e = 0; e < m; ++e) lines[e] = c.add_scaled(e, first);
    for (std::size_t e = 0; e < m; ++e) cycle.push_back(c.vertex(lines[(e + m - 1) % m], lines[e], lines[e]));
    // Consecutive parallel edges (a G_c given with collinear vertices, not in canonical form)
    // have no meet: start from the box instead, which needs no such assumption.
    for (const Vertex& v : cycle)
      if (v.w_sign == 0) first = k_count;
    if (first < k_count) return cycle;
  }
  // The box [0, X/Q1] × [0, Y/Q2] contains F: for q with q1 = Q1 > 0, m1·Q1 is the first
  // coordinate of a point of G_c, so 0 <= m1·Q1 <= X (likewise m2). Clip it to F.
  const std::size_t bottom = c.add_exact(integer_line({0, -1, 0}));
  const std::size_t right = c.add_exact(integer_line({1, 0, Rational(g.x_max / h.max_x)}));
  const std::size_t top = c.add_exact(integer_line({0, 1, Rational(g.y_max / h.max_y)}));
  const std::size_t left = c.add_exact(integer_line({-1, 0, 0}));
  return {c.vertex(left, bottom, bottom), c.vertex(bottom, right, right), c.vertex(right, top, top),
          c.vertex(top, left, left)};
}

// Clips `cycle` by the lines of every image vertex but `first` (whose lines it already is), then
// by the map constraint's; false when F is empty. While the cycle is strictly convex, each family
// of lines is clipped by clip_convex (when `linear`); clip() takes the lines left once it
// degenerates, or all of them on the route kept for comparison (internal/feasible_polygon_route.h).
bool clip_every_family(PolygonClipper& c, const internal::CanonicalLines& g, std::size_t k_count, std::size_t first,
                       bool linear, std::vector<Vertex>& cycle) {
  std::vector<Vertex> next;
  std::vector<int> sides;
  bool strict = linear && cycle.size() >= 3 && c.strictly_convex(cycle);
  auto clip_family = [&](std::size_t count, auto approximation, auto add_line) {
    std::size_t e = 0;
    if (strict) {
      const ConvexClip r = clip_convex(c, cycle, count, add_line);
      e = r.taken, strict = r.strictly_convex;
      if (cycle.empty()) return false;
    }
    for (; e < count; ++e) {
      // A line every vertex lies strictly inside of cannot cut: it is not even added.
      if (c.all_inside(approximation(e), cycle)) continue;
      clip(c, cycle, add_line(e), next, sides);
      cycle.swap(next);
      if (cycle.empty()) return false;
    }
    return true;
  };
  const std::size_t m = g.lines.size();
  for (std::size_t k = 0; k < k_count; ++k)
    if (k != first &&
        !clip_family(
            m, [&](std::size_t e) { return c.scaled_approx(e, k); }, [&](std::size_t e) { return c.add_scaled(e, k); }))
      return false;
  return clip_family(
      g.extra_lines.size(), [&](std::size_t j) { return g.extra_approx[j]; },
      [&](std::size_t j) { return c.add_fixed(j); });
}

}  // namespace

FeasiblePolygon internal::FeasiblePolygonAccess::build(const CanonicalConstraints& canonical,
                                             const std::vector<const Point2*>& image, bool copy_image,
                                             bool linear) {
  const internal::CanonicalLines& g = *canonical.lines_;
  FeasiblePolygon result;
  result.state_ = std::make_shared<internal::FeasiblePolygonState>();
  internal::FeasiblePolygonState& st = *result.state_;
  const ImageHull hull = checked_image_hull(image, copy_image ? &st.owned : nullptr);
  if (g.extra_empty) {  // F ∩ ∅
    st.exact = ConvexSet2{};
    return result;
  }
  const std::size_t k_count = hull.vertices.size();
  PolygonClipper& c = st.clipper.emplace(canonical.lines_, hull.vertices, g.lines.size() * (k_count + 1) + 4 + g.extra_lines.size());
  std::size_t first = 0;
  std::vector<Vertex> cycle = starting_cycle(c, g, hull, first);
  if (!clip_every_family(c, g, k_count, first, linear, cycle)) {
    st.exact = ConvexSet2{};
    return result;
  }
  st.cycle = reduced(c, cycle);
  st.strictly_convex = st.cycle.size() >= 3 && c.strictly_convex(st.cycle);
  if (!st.strictly_convex) {  // degenerate (or collinear leftovers): the exact set decides the kind
    st.kind = result.exact().kind;
    return result;
  }
  st.kind = ConvexKind::polygon;
  if (c.filtered()) {
    bool ok = true;
    for (const Vertex& v : st.cycle) {
      const EnclosedVertex e = c.enclose(v);
      ok = ok && std::isfinite(e.x.rad) && std::isfinite(e.y.rad);
      st.vertices.push_back(e);
      const ApproximateLine& l = c.approximate(v.out);
      st.edges.push_back({l.a, l.b, l.c});
    }
    if (!ok) st.vertices.clear(), st.edges.clear();
  }
  return result;
}

// A default-constructed FeasiblePolygon is the empty set.
internal::FeasiblePolygonState& FeasiblePolygon::state() const {
  static internal::FeasiblePolygonState empty = [] {  // shared by every default object: nothing in it is ever built later
    internal::FeasiblePolygonState e;
    e.exact = ConvexSet2{};
    e.long_vertices.emplace();
    return e;
  }();
  return state_ ? *state_ : empty;
}

ConvexKind FeasiblePolygon::kind() const { return state().kind; }
bool FeasiblePolygon::enclosed() const { return !state().vertices.empty(); }
const std::vector<EnclosedVertex>& FeasiblePolygon::vertices() const { return state().vertices; }
const std::vector<ApproximateLine>& FeasiblePolygon::edges() const { return state().edges; }
const std::vector<LongEnclosedVertex>& FeasiblePolygon::extended_vertices() const {
  internal::FeasiblePolygonState& st = state();
  if (!st.long_vertices) {
    st.long_vertices.emplace();
    if (numerics::extended_precision_active() && !st.vertices.empty())
      for (const Vertex& v : st.cycle) st.long_vertices->push_back(st.clipper->enclose_exactly(v));
  }
  return *st.long_vertices;
}

const ConvexSet2& FeasiblePolygon::exact() const {
  internal::FeasiblePolygonState& st = state();
  if (st.exact) return *st.exact;
  PolygonClipper& c = *st.clipper;
  std::vector<Point2> points;
  points.reserve(st.cycle.size());
  for (const Vertex& p : st.cycle) points.push_back(c.point(p));
  if (!st.strictly_convex) return st.exact.emplace(canonical_convex_set(std::move(points)));
  // Already strictly convex and counter-clockwise: only the canonical start is left to do.
  ConvexSet2 F;
  F.kind = ConvexKind::polygon;
  std::rotate(points.begin(), std::min_element(points.begin(), points.end()), points.end());
  F.vertices = std::move(points);
  return st.exact.emplace(std::move(F));
}

bool FeasiblePolygon::contains(const Point2& m) const {
  internal::FeasiblePolygonState& st = state();
  if (st.kind == ConvexKind::empty) return false;
  if (!st.strictly_convex) return gmcc::contains(exact(), m);
  // F is the intersection of the half-planes carrying its edges.
  std::optional<std::array<double, 2>> fm;
  const auto x = approx(m.x), y = approx(m.y);
  if (x && y && in_filter_range(*x) && in_filter_range(*y)) fm = std::array<double, 2>{*x, *y};
  for (const Vertex& v : st.cycle)
    if (st.clipper->side_of_point(v.out, m, fm) > 0) return false;
  return true;
}


}  // namespace gmcc
