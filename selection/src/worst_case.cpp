#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/worst_case.h>

#include <stdexcept>
#include <vector>

namespace gmcc {

double worst_case_map_deg(const ConvexSet2& F, const Point2& m) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("worst_case_map_deg: empty set");
  // u = (m, 1), v(x) = (x, 1): the angle grows as cos = u·v / (|u||v|) falls.
  auto dot_m = [&](const Point2& v) { return Rational(m.x * v.x + m.y * v.y + 1); };
  auto norm2 = [](const Point2& v) { return Rational(v.x * v.x + v.y * v.y + 1); };
  // True iff the angle at a exceeds the angle at b: compare the signed cos²-like keys
  // sgn(u·v)·(u·v)²/|v|² exactly (|u| is common).
  auto wider = [&](const Point2& a, const Point2& b) {
    const Rational da = dot_m(a), db = dot_m(b);
    const int sa = sgn(da), sb = sgn(db);
    if (sa != sb) return sa < sb;
    const Rational ka = da * da * norm2(b), kb = db * db * norm2(a);
    return sa > 0 ? ka < kb : ka > kb;
  };
  std::vector<Point2> candidates = F.vertices;
  // With u·v > 0 at every vertex (always so for m >= 0) every angle on F is below 90°, where the
  // angle is quasi-convex, so a vertex attains the maximum (MATH §1e). Otherwise (an estimate
  // outside the quadrant: the closed form at a forced low precision; found by fuzz_geometry)
  // an edge can hold it inside: on v = p + t·d, d/dt (u·v)/|v| ∝ (u·d)|v|² − (u·v)(v·d) is
  // linear in t (the t² terms cancel), so each edge adds at most one rational candidate.
  bool acute = true;
  for (const Point2& v : F.vertices) acute = acute && sgn(dot_m(v)) > 0;
  const auto& vs = F.vertices;
  const std::size_t edges = acute ? 0 : F.kind == ConvexKind::polygon ? vs.size()
                                     : F.kind == ConvexKind::segment ? 1 : 0;
  for (std::size_t i = 0; i < edges; ++i) {
    const Point2& p = vs[i];
    const Point2 d{Rational(vs[(i + 1) % vs.size()].x - p.x), Rational(vs[(i + 1) % vs.size()].y - p.y)};
    const Rational ud = m.x * d.x + m.y * d.y, up = dot_m(p), pd = p.x * d.x + p.y * d.y,
                   dd = d.x * d.x + d.y * d.y;
    const Rational a = ud * norm2(p) - up * pd, b = ud * pd - up * dd;  // a + b·t = 0
    if (sgn(b) == 0) continue;
    const Rational t = -a / b;
    if (sgn(t) > 0 && t < 1) candidates.push_back({Rational(p.x + t * d.x), Rational(p.y + t * d.y)});
  }
  const Point2* worst = &candidates.front();
  for (const Point2& v : candidates)
    if (wider(v, *worst)) worst = &v;
  return map_angular_error_deg(m, *worst);
}

}  // namespace gmcc
