#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/integers_over_lcm.h>

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

namespace {
// The vertices over one common denominator d (the lcm of theirs): v_i = (x_i/d, y_i/d) with
// integers, so sums of products need no gcd until the single final division.
struct ScaledVertices {
  std::vector<mpz_class> x, y;
  mpz_class d = 1;
};
ScaledVertices scaled(const std::vector<Point2>& v) {
  ScaledVertices s;
  for (const Point2& p : v) include_denominator(s.d, p.x), include_denominator(s.d, p.y);
  for (const Point2& p : v) {
    s.x.push_back(times_lcm(p.x, s.d));
    s.y.push_back(times_lcm(p.y, s.d));
  }
  return s;
}
// Sign of orientation(v_i, v_j, v_k), in integers.
int turn(const ScaledVertices& s, std::size_t i, std::size_t j, std::size_t k) {
  return sgn((s.x[j] - s.x[i]) * (s.y[k] - s.y[i]) - (s.y[j] - s.y[i]) * (s.x[k] - s.x[i]));
}
// Twice the signed area of fan triangle (0, i, i+1), times d².
mpz_class fan_weight(const ScaledVertices& s, std::size_t i) {
  return (s.x[i] - s.x[0]) * (s.y[i + 1] - s.y[0]) - (s.y[i] - s.y[0]) * (s.x[i + 1] - s.x[0]);
}
}  // namespace

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
  const ScaledVertices s = scaled(v);
  bool collinear = true;
  for (std::size_t k = 2; k < v.size() && collinear; ++k) collinear = turn(s, 0, 1, k) == 0;
  if (v.size() == 2 || collinear) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    out.kind = ConvexKind::segment;
    out.vertices = {*lo, *hi};
    return out;
  }
  // 3. A proper polygon: drop vertices where the boundary goes straight on.
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (turn(s, (i + n - 1) % n, i, (i + 1) % n) != 0) out.vertices.push_back(v[i]);
  // 4. Canonical start: the lexicographically smallest vertex.
  std::rotate(out.vertices.begin(),
              std::min_element(out.vertices.begin(), out.vertices.end()), out.vertices.end());
  out.kind = ConvexKind::polygon;
  return out;
}

Rational area(const ConvexSet2& set) {
  if (set.kind != ConvexKind::polygon) return 0;
  const ScaledVertices s = scaled(set.vertices);
  mpz_class twice = 0;
  for (std::size_t i = 1; i + 1 < s.x.size(); ++i) twice += fan_weight(s, i);
  Rational a(twice, 2 * s.d * s.d);
  a.canonicalize();
  return a;
}

bool contains(const ConvexSet2& set, const Point2& p) {
  const auto& v = set.vertices;
  switch (set.kind) {
    case ConvexKind::empty: return false;
    case ConvexKind::point: return v[0] == p;
    case ConvexKind::segment:
      return sgn(orientation(v[0], v[1], p)) == 0 && !(p < v[0]) && !(v[1] < p);
    case ConvexKind::polygon: {
      // Orientation tests with p scaled by the same denominator as the vertices: integers only.
      const ScaledVertices s = scaled(v);
      const mpz_class pd = lcm_of_denominators_of(p.x, p.y);
      const mpz_class px = times_lcm(p.x, pd), py = times_lcm(p.y, pd);
      // p = (px/pd, py/pd): orientation(v_i, v_j, p)·d²·pd = (xj−xi)(py·d − yi·pd) − (yj−yi)(px·d − xi·pd)
      const mpz_class pxd = px * s.d, pyd = py * s.d;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const std::size_t j = (i + 1) % v.size();
        if (sgn((s.x[j] - s.x[i]) * (pyd - s.y[i] * pd) - (s.y[j] - s.y[i]) * (pxd - s.x[i] * pd)) < 0)
          return false;
      }
      return true;
    }
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
  // Σ w_i (a + b + c)/3 / Σ w_i with w_i twice the signed area of fan triangle (v0, vi, vi+1),
  // in integers over the common denominator, divided once at the end.
  const ScaledVertices s = scaled(v);
  mpz_class w_sum = 0, x_sum = 0, y_sum = 0;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const mpz_class w = fan_weight(s, i);
    w_sum += w;
    x_sum += w * (s.x[0] + s.x[i] + s.x[i + 1]);
    y_sum += w * (s.y[0] + s.y[i] + s.y[i + 1]);
  }
  const mpz_class den = 3 * s.d * w_sum;
  Rational cx(x_sum, den), cy(y_sum, den);
  cx.canonicalize();
  cy.canonicalize();
  return {cx, cy};
}

}  // namespace gmcc
