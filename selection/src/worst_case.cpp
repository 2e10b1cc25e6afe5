#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/worst_case.h>
#include <gmcc/numerics/may_be_largest.h>

#include "internal/angle.h"
#include "internal/ld_interval.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace gmcc {
namespace {
bool nonnegative(const Point2& p) { return sgn(p.x) >= 0 && sgn(p.y) >= 0; }
}  // namespace

double worst_case_map_deg(const ConvexSet2& F, const Point2& m) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("worst_case_map_deg: empty set");
  // u = (m, 1), v(x) = (x, 1).
  auto dot_m = [&](const Point2& v) { return Rational(m.x * v.x + m.y * v.y + 1); };
  // With u·v > 0 at every vertex (always so for m >= 0 and F in the quadrant) every angle on F is
  // below 90°, where the angle is quasi-convex, so a vertex attains the maximum
  // (docs/derivations.md §3.1). Otherwise (an estimate outside the quadrant: the closed form at a
  // forced low precision; found by fuzz_geometry) an edge can hold it inside: on v = p + t·d, d/dt
  // (u·v)/|v| ∝ (u·d)|v|² − (u·v)(v·d) is linear in t (the t² terms cancel), so each edge adds at
  // most one rational candidate.
  const auto& vs = F.vertices;
  bool acute = nonnegative(m) && std::all_of(vs.begin(), vs.end(), nonnegative);
  if (!acute) {
    acute = true;
    for (const Point2& v : vs) acute = acute && sgn(dot_m(v)) > 0;
  }
  std::vector<Point2> candidates = vs;
  const std::size_t edges = acute ? 0 : F.kind == ConvexKind::polygon ? vs.size()
                                     : F.kind == ConvexKind::segment ? 1 : 0;
  auto norm2 = [](const Point2& v) { return Rational(v.x * v.x + v.y * v.y + 1); };
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
  // The largest of the candidates' angles, each evaluated from the exact values (angle_deg is
  // within a relative 2^-50 of the true angle).
  const std::array<Rational, 3> lifted_m{m.x, m.y, Rational(1)};
  auto lifted = [](const Point2& v) { return std::array<Rational, 3>{v.x, v.y, Rational(1)}; };
  double worst = 0;
  if (!numerics::extended_precision_active()) {
    for (const Point2& v : candidates) worst = std::max(worst, internal::angle_deg(lifted_m, lifted(v)));
    return worst;
  }
  // Cheap enclosures first; a candidate whose angle is certainly below another's by a relative
  // 2^-40 cannot be the maximum, and its rounded angle cannot exceed the winner's either, so it
  // is not evaluated.
  std::vector<internal::LDInterval> enclosures;
  enclosures.reserve(candidates.size());
  const internal::LDInterval mx = internal::enclose_ld(m.x), my = internal::enclose_ld(m.y);
  for (const Point2& v : candidates)
    enclosures.push_back(internal::angle_deg_enclosure(
        {mx, my, {1, 1}}, {internal::enclose_ld(v.x), internal::enclose_ld(v.y), {1, 1}}));
  for (std::size_t i : numerics::may_be_largest(enclosures, 0x1p-40))
    worst = std::max(worst, internal::angle_deg(lifted_m, lifted(candidates[i])));
  return worst;
}

}  // namespace gmcc
