#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>

#include "internal/canonical_lines.h"
#include "internal/half_plane.h"
#include "internal/integer_line.h"

#include <algorithm>
#include <memory>

namespace gmcc {

using internal::approx_line;
using internal::in_filter_range;
using internal::integer_line;
using internal::Line;
using internal::top_bits;

CanonicalConstraints::CanonicalConstraints(const ConvexSet2& canonical) {
  if (canonical.kind == ConvexKind::empty)
    throw std::invalid_argument("feasible_set: the canonical gamut is empty");
  auto impl = std::make_shared<internal::CanonicalLines>();
  internal::CanonicalLines& g = *impl;
  for (const internal::HalfPlane& h : internal::half_planes(canonical)) {
    g.lines.push_back(integer_line(h));
    ApproximateLine a{};
    g.filtered = g.filtered && approx_line(g.lines.back(), a);
    g.approx.push_back(a);
    const Line& l = g.lines.back();
    const auto la = top_bits(l.a.get_mpz_t()), lb = top_bits(l.b.get_mpz_t()), lc = top_bits(l.c.get_mpz_t());
    if (la && lb && lc) g.long_lines.push_back({*la, *lb, *lc});
  }
  if (!numerics::extended_precision_compiled || g.long_lines.size() != g.lines.size()) g.long_lines.clear();
  g.polygon = canonical.kind == ConvexKind::polygon;
  g.x_max = canonical.vertices.front().x, g.y_max = canonical.vertices.front().y;
  for (const Point2& p : canonical.vertices) g.x_max = std::max(g.x_max, p.x), g.y_max = std::max(g.y_max, p.y);
  lines_ = std::move(impl);
}

CanonicalConstraints::CanonicalConstraints(const ConvexSet2& canonical, const ConvexSet2& map_constraint)
    : CanonicalConstraints(canonical) {
  auto impl = std::make_shared<internal::CanonicalLines>(*lines_);
  impl->extra_empty = map_constraint.kind == ConvexKind::empty;
  for (const internal::HalfPlane& h : internal::half_planes(map_constraint)) {
    impl->extra_lines.push_back(integer_line(h));
    ApproximateLine a{};
    impl->extra_filtered = impl->extra_filtered && approx_line(impl->extra_lines.back(), a) &&
                           in_filter_range(a.a) && in_filter_range(a.b) && in_filter_range(a.c);
    impl->extra_approx.push_back(a);
  }
  lines_ = std::move(impl);
}

ConvexSet2 feasible_set(const CanonicalConstraints& canonical, const std::vector<Point2>& image) {
  return feasible_polygon(canonical, image).exact();
}

ConvexSet2 feasible_set(const ConvexSet2& canonical, const std::vector<Point2>& image) {
  return feasible_set(CanonicalConstraints(canonical), image);
}

}  // namespace gmcc
