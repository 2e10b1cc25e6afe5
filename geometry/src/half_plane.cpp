#include "internal/half_plane.h"
#include "internal/sutherland_hodgman.h"

namespace gmcc::internal {

std::vector<HalfPlane> half_planes(const ConvexSet2& set) {
  std::vector<HalfPlane> out;
  const auto& v = set.vertices;
  auto both_ways = [&out](const Rational& a, const Rational& b, const Rational& c) {
    out.push_back({a, b, c});
    out.push_back({Rational(-a), Rational(-b), Rational(-c)});
  };
  switch (set.kind) {
    case ConvexKind::empty: break;
    case ConvexKind::point:
      both_ways(1, 0, v[0].x);
      both_ways(0, 1, v[0].y);
      break;
    case ConvexKind::segment: {
      const Rational dx = v[1].x - v[0].x, dy = v[1].y - v[0].y;
      both_ways(dy, Rational(-dx), Rational(dy * v[0].x - dx * v[0].y));  // the supporting line
      out.push_back({dx, dy, Rational(dx * v[1].x + dy * v[1].y)});       // not beyond v[1]
      out.push_back({Rational(-dx), Rational(-dy), Rational(-(dx * v[0].x + dy * v[0].y))});
      break;
    }
    case ConvexKind::polygon:
      for (std::size_t i = 0; i < v.size(); ++i) {
        const Point2& p = v[i];
        const Point2& q = v[(i + 1) % v.size()];
        const Rational a = q.y - p.y, b = p.x - q.x;  // outward normal of a CCW edge
        out.push_back({a, b, Rational(a * p.x + b * p.y)});
      }
      break;
  }
  return out;
}

std::vector<Point2> clip(const std::vector<Point2>& cycle, const HalfPlane& h) {
  const std::size_t n = cycle.size();
  std::vector<Rational> value(n);  // a·x + b·y − c: the side, and where an edge crosses
  std::vector<int> side(n);
  for (std::size_t i = 0; i < n; ++i) {
    value[i] = h.a * cycle[i].x + h.b * cycle[i].y - h.c;
    side[i] = sgn(value[i]);
  }
  std::vector<Point2> out;
  out.reserve(n + 1);
  const bool clipped = sutherland_hodgman(
      side, [&](std::size_t i, std::size_t) { out.push_back(cycle[i]); },
      [&](std::size_t i, std::size_t j) {  // the crossing point, at t = value_i/(value_i − value_j)
        const Rational t = value[i] / (value[i] - value[j]);
        out.push_back({Rational(cycle[i].x + t * (cycle[j].x - cycle[i].x)),
                       Rational(cycle[i].y + t * (cycle[j].y - cycle[i].y))});
      });
  return clipped ? out : cycle;
}

}  // namespace gmcc::internal
