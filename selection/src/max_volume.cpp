#include <gmcc/selection/max_volume.h>
#include <gmcc/numerics/internal_check.h>

#include "internal/interval.h"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace gmcc {
namespace {
using internal::Interval;

Point3 sub(const Point3& a, const Point3& b) { return {Rational(a.x - b.x), Rational(a.y - b.y), Rational(a.z - b.z)}; }
Point3 cross(const Point3& a, const Point3& b) {
  return {Rational(a.y * b.z - a.z * b.y), Rational(a.z * b.x - a.x * b.z), Rational(a.x * b.y - a.y * b.x)};
}
Rational dot(const Point3& a, const Point3& b) { return Rational(a.x * b.x + a.y * b.y + a.z * b.z); }
Rational product(const Point3& d) { return Rational(d.x * d.y * d.z); }
Point3 along(const Point3& p, const Point3& u, const Rational& t) {
  return {Rational(p.x + t * u.x), Rational(p.y + t * u.y), Rational(p.z + t * u.z)};
}

// The exact square root of a non-negative rational, when it is rational.
std::optional<Rational> rational_sqrt(const Rational& x) {
  if (!mpz_perfect_square_p(x.get_num_mpz_t()) || !mpz_perfect_square_p(x.get_den_mpz_t()))
    return std::nullopt;
  mpz_class n, d;
  mpz_sqrt(n.get_mpz_t(), x.get_num_mpz_t());
  mpz_sqrt(d.get_mpz_t(), x.get_den_mpz_t());
  Rational r(n, d);
  r.canonicalize();
  return r;
}

// An irrational edge candidate: p + t·u with t = (−b + sign·√disc)/(2a).
struct EdgeRoot {
  Point3 p, u;
  Rational a, b, disc;
  int sign;
  Interval t(mpfr_prec_t bits) const {
    const Interval s = sqrt(Interval(disc, bits));
    Interval num = Interval(Rational(-b), bits) + (sign > 0 ? s : Interval(0, bits) - s);
    return num / Interval(Rational(2 * a), bits);
  }
  std::array<Interval, 3> point(mpfr_prec_t bits) const {
    const Interval tt = t(bits);
    return {Interval(p.x, bits) + tt * u.x, Interval(p.y, bits) + tt * u.y,
            Interval(p.z, bits) + tt * u.z};
  }
};

int compare_with(const Interval& x, const Rational& q);
bool interval_lt(const Interval& x, const Interval& y) {  // every point of x < every point of y
  return compare_with(y - x, 0) > 0;
}
int compare_with(const Interval& x, const Rational& q) {  // −1: x < q surely, +1: x > q, 0: unsure
  const Interval d = x - Interval(q, x.precision());
  if (mpfr_sgn(&d.get()->left) > 0) return 1;
  if (mpfr_sgn(&d.get()->right) < 0) return -1;
  return 0;
}

// The candidates for the maximum of d1·d2·d3 on F: rational ones (vertices, facet stationary
// points, rational edge roots) and the edges' irrational roots.
struct Candidates {
  std::vector<Point3> rational;
  std::vector<EdgeRoot> irrational;
};
Candidates candidates(const ConvexSet3& F) {
  const auto& v = F.vertices;
  Candidates out{{v.begin(), v.end()}, {}};
  std::vector<Point3>& rational = out.rational;
  std::vector<EdgeRoot>& irrational = out.irrational;
  std::vector<std::vector<std::size_t>> planes = F.faces;  // polytope facets, or the polygon
  for (const auto& f : planes) {
    const Point3 n = cross(sub(v[f[1]], v[f[0]]), sub(v[f[2]], v[f[0]]));
    const Rational k = dot(n, v[f[0]]);
    if (sgn(n.x) == 0 || sgn(n.y) == 0 || sgn(n.z) == 0) continue;
    if (sgn(k) * sgn(n.x) <= 0 || sgn(k) * sgn(n.y) <= 0 || sgn(k) * sgn(n.z) <= 0) continue;
    const Point3 d{Rational(k / (3 * n.x)), Rational(k / (3 * n.y)), Rational(k / (3 * n.z))};
    if (contains(F, d)) rational.push_back(d);
  }
  std::set<std::pair<std::size_t, std::size_t>> edges;
  for (const auto& f : F.faces)
    for (std::size_t i = 0; i < f.size(); ++i)
      edges.insert(std::minmax(f[i], f[(i + 1) % f.size()]));
  if (F.kind == ConvexKind3::segment) edges.insert({0, 1});
  for (const auto& [i, j] : edges) {
    const Point3& p = v[i];
    const Point3 u = sub(v[j], p);
    // f(t) = A t³ + B t² + C t + D; f'(t) = 3A t² + 2B t + C.
    const Rational A = u.x * u.y * u.z;
    const Rational B = p.x * u.y * u.z + u.x * p.y * u.z + u.x * u.y * p.z;
    const Rational C = p.x * p.y * u.z + p.x * u.y * p.z + u.x * p.y * p.z;
    const Rational a = 3 * A, b = 2 * B, c = C;
    auto consider = [&](const Rational& t) {
      if (sgn(t) > 0 && t < 1) rational.push_back(along(p, u, t));
    };
    if (sgn(a) == 0) {
      if (sgn(b) != 0) consider(Rational(-c / b));
      continue;
    }
    const Rational disc = b * b - 4 * a * c;
    if (sgn(disc) < 0) continue;
    if (const auto r = rational_sqrt(disc)) {
      consider(Rational((-b + *r) / (2 * a)));
      consider(Rational((-b - *r) / (2 * a)));
      continue;
    }
    for (int sign : {1, -1}) irrational.push_back({p, u, a, b, disc, sign});
  }
  return out;
}

// An irrational winner's map enclosed tightly enough for a double (at least `bits`), reported
// with its exact form.
MapEstimate3 edge_root_estimate(const EdgeRoot& e, mpfr_prec_t bits) {
  const auto d = e.point(std::max<mpfr_prec_t>(bits, 256));
  MapEstimate3 out;
  out.rule = "max_volume";
  out.method = "certified";
  for (int k = 0; k < 3; ++k) {
    const auto [m, bound] = internal::nearest_with_bound(d[k]);
    const auto [lo, hi] = internal::outward_doubles(d[k]);
    out.map[k] = m;
    out.error_bound = std::max(out.error_bound, bound);
    out.enclosure[k] = {lo, hi};
  }
  out.edge_root = MapEstimate3::EdgeRoot{e.p, along(e.p, e.u, 1), e.a, e.b,
                                          Rational((e.b * e.b - e.disc) / (4 * e.a)), e.sign};
  return out;
}

}  // namespace

MapEstimate3 max_volume(const ConvexSet3& F) {
  if (F.kind == ConvexKind3::empty) throw std::invalid_argument("max_volume: empty feasible set");

  Candidates c = candidates(F);
  std::vector<Point3>& rational = c.rational;
  std::vector<EdgeRoot>& irrational = c.irrational;

  // The best rational candidate, exactly (ties: the lexicographically smallest).
  Point3 best = rational.front();
  Rational best_value = product(best);
  for (const Point3& d : rational) {
    const Rational value = product(d);
    if (value > best_value || (value == best_value && d < best)) best = d, best_value = value;
  }

  // Irrational candidates: drop those outside (0, 1), then separate the winner.
  for (mpfr_prec_t bits = 128; !irrational.empty(); bits *= 2) {
    GMCC_CHECK(bits <= (1 << 16), "max_volume: distinct candidates separate below 2^16 bits");
    std::vector<EdgeRoot> inside;
    bool unsure = false;
    for (const EdgeRoot& e : irrational) {
      const Interval t = e.t(bits);
      if (compare_with(t, 0) > 0 && compare_with(t, 1) < 0) inside.push_back(e);
      else if (compare_with(t, 0) == 0 || compare_with(t, 1) == 0) unsure = true, inside.push_back(e);
    }
    if (unsure) continue;
    irrational = std::move(inside);
    if (irrational.empty()) break;
    std::vector<Interval> value;
    for (const EdgeRoot& e : irrational) {
      const auto d = e.point(bits);
      value.push_back(d[0] * d[1] * d[2]);
    }
    // Rational winner: every irrational value surely below best_value.
    bool all_below = true;
    for (const Interval& x : value) all_below = all_below && compare_with(x, best_value) < 0;
    if (all_below) break;
    // Irrational winner: above best_value and above every other irrational candidate.
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (compare_with(value[i], best_value) <= 0) continue;
      bool wins = true;
      for (std::size_t j = 0; j < value.size() && wins; ++j)
        wins = j == i || interval_lt(value[j], value[i]);
      if (!wins) continue;
      return edge_root_estimate(irrational[i], bits);
    }
  }
  return exact_map_estimate_3("max_volume", best);
}

}  // namespace gmcc
