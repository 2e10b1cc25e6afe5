#include <gmcc/geometry/convex_set.h>

#include <algorithm>
#include <stdexcept>

namespace gmcc {

std::string to_string(ConvexKind kind) {
  switch (kind) {
    case ConvexKind::polygon: return "polygon";
    case ConvexKind::segment: return "segment";
    case ConvexKind::point: return "point";
    case ConvexKind::empty: return "empty";
  }
  return "empty";
}

ConvexSet2 canonical_convex_set(std::vector<Point2> cycle) {
  // 1. Drop repeated consecutive vertices, cyclically.
  std::vector<Point2> v;
  v.reserve(cycle.size());
  for (Point2& p : cycle)
    if (v.empty() || v.back() != p) v.push_back(std::move(p));
  while (v.size() > 1 && v.back() == v.front()) v.pop_back();

  ConvexSet2 out;
  if (v.empty()) return out;
  if (v.size() == 1) {
    out.kind = ConvexKind::point;
    out.vertices = std::move(v);
    return out;
  }
  // 2. All collinear: a segment between the extreme vertices.
  const bool collinear = std::all_of(v.begin() + 2, v.end(), [&](const Point2& p) {
    return sgn(orientation(v[0], v[1], p)) == 0;
  });
  if (v.size() == 2 || collinear) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    out.kind = ConvexKind::segment;
    out.vertices = {*lo, *hi};
    return out;
  }
  // 3. A proper polygon: drop vertices where the boundary goes straight on.
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (sgn(orientation(v[(i + n - 1) % n], v[i], v[(i + 1) % n])) != 0)
      out.vertices.push_back(v[i]);
  // 4. Canonical start: the lexicographically smallest vertex.
  std::rotate(out.vertices.begin(),
              std::min_element(out.vertices.begin(), out.vertices.end()), out.vertices.end());
  out.kind = ConvexKind::polygon;
  return out;
}

Rational area(const ConvexSet2& set) {
  if (set.kind != ConvexKind::polygon) return 0;
  const auto& v = set.vertices;
  Rational twice = 0;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) twice += orientation(v[0], v[i], v[i + 1]);
  return Rational(twice / 2);
}

bool contains(const ConvexSet2& set, const Point2& p) {
  const auto& v = set.vertices;
  switch (set.kind) {
    case ConvexKind::empty: return false;
    case ConvexKind::point: return v[0] == p;
    case ConvexKind::segment:
      return sgn(orientation(v[0], v[1], p)) == 0 && !(p < v[0]) && !(v[1] < p);
    case ConvexKind::polygon:
      for (std::size_t i = 0; i < v.size(); ++i)
        if (sgn(orientation(v[i], v[(i + 1) % v.size()], p)) < 0) return false;
      return true;
  }
  return false;
}

}  // namespace gmcc

namespace gmcc {

Point2 centroid(const ConvexSet2& set) {
  const auto& v = set.vertices;
  switch (set.kind) {
    case ConvexKind::empty: throw std::invalid_argument("centroid of an empty set");
    case ConvexKind::point: return v[0];
    case ConvexKind::segment:
      return {Rational((v[0].x + v[1].x) / 2), Rational((v[0].y + v[1].y) / 2)};
    case ConvexKind::polygon: break;
  }
  // Σ w_i (a + b + c)/3 / Σ w_i with w_i twice the signed area of fan triangle (v0, vi, vi+1).
  Rational w_sum = 0, x_sum = 0, y_sum = 0;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const Rational w = orientation(v[0], v[i], v[i + 1]);
    w_sum += w;
    x_sum += w * (v[0].x + v[i].x + v[i + 1].x);
    y_sum += w * (v[0].y + v[i].y + v[i + 1].y);
  }
  return {Rational(x_sum / (3 * w_sum)), Rational(y_sum / (3 * w_sum))};
}

}  // namespace gmcc
