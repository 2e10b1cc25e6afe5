#include <gmcc/selection/mean_3d_quadrature.h>

#include <gmcc/numerics/constants.h>

#include "internal/interval.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace gmcc {
namespace {

// Unit roundoff of long double (2^-64 for the x87 format, 2^-113 for binary128, 2^-53 where
// long double is double): the error analysis below is written in it, so it holds on each.
constexpr long double unit_roundoff = std::numeric_limits<long double>::epsilon() / 2;
// Deepest subdivision (docs/math.md §2 "Quadrature"): each level halves a piece, and a piece
// must shrink to the distance √(1 + |x|²) of its nearest corner, and beyond |x| ~ 10^1233 the
// weight overflows the x87 range anyway (the route then declines): 2^4200 > 10^1264.
constexpr unsigned depth_limit = 4200;
// At most 2^26 nodes (2–3 s at 30–40 ns a node): the resource limit of docs/cli.md, so no
// order or feasible set makes the route run without bound; beyond it the route declines.
constexpr std::uint64_t node_budget = std::uint64_t(1) << 26;

// Gauss–Legendre nodes and weights on [0, 1]: Newton's method on P_n in long double.
void gauss_legendre_01(unsigned n, std::vector<long double>& x, std::vector<long double>& w) {
  x.assign(n, 0);
  w.assign(n, 0);
  using numerics::pi;
  for (unsigned i = 0; i < n; ++i) {
    long double z = std::cos(pi * (i + 0.75L) / (n + 0.5L)), derivative = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      long double p0 = 1, p1 = z;
      for (unsigned k = 2; k <= n; ++k) {
        const long double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (z * p1 - p0) / (z * z - 1);
      const long double step = p1 / derivative;
      z -= step;
      if (step == 0 || std::fabs(step) <= std::fabs(z) * 2 * unit_roundoff) break;
    }
    if (n == 1) z = 0, derivative = 1;
    x[i] = (1 - z) / 2;
    w[i] = 1 / ((1 - z * z) * derivative * derivative);
  }
}

// Neumaier's compensated sum: |computed − exact| <= 2u·|exact| + 2N·u²·Σ|terms| (Higham,
// Accuracy and Stability of Numerical Algorithms, 2nd ed., §4.3), so a million rows cost no
// more accuracy than one.
struct CompensatedSum {
  long double sum = 0, correction = 0;
  void add(long double x) {
    const long double t = sum + x;
    correction += std::fabs(sum) >= std::fabs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  }
  long double value() const { return sum + correction; }
};

// The weighted sums over F, in offsets from the apex v0, with what the error bound needs. A row
// of n nodes is summed plainly (error <= γ_n·Σ|terms|, γ_n = nu/(1 − nu)) and rows are added
// with compensation, so the order n, not the number of nodes, sets the summation error.
struct Sums {
  CompensatedSum w, x, y;         // Σ W, Σ W·o_x, Σ W·o_y
  long double rows = 0;           // compensated additions
  long double position_rel = 0;   // max (|px| + |py| + δ)/r2 over the nodes (position errors)
  bool depth_exceeded = false;
  bool unresolved = false;        // a piece to split is no larger than the node position error
  bool budget_exceeded = false;   // more than node_budget nodes
  std::uint64_t nodes = 0;
  bool overflow = false;          // r2² beyond the long double's range at some node
  bool stopped() const { return depth_exceeded || unresolved || budget_exceeded; }
};

// A row's plain sums.
struct Row {
  long double w = 0, x = 0, y = 0;
};

struct Rule {
  std::vector<long double> x, w;  // Gauss–Legendre on [0, 1]
  long double ax, ay;             // the apex, nearest long double
  long double delta;              // bound on a node's absolute position error, per coordinate
};

// The weight's singularities are where 1 + a² + b² = 0 (complex), about sqrt(1 + |x|²) away from
// a real point x: a piece much larger than that converges slowly, so pieces are halved until
// their diameter² <= 1 + (smallest |x|² over their corners) (docs/math.md §2: composite rules).
bool needs_split(long double d2, long double r2_min) { return d2 > 1 + r2_min; }

long double r2_at(const Rule& r, long double ox, long double oy) {
  const long double px = r.ax + ox, py = r.ay + oy;
  return px * px + py * py;
}

// Largest r2 whose square (the weight's denominator) stays within the long double's range.
const long double max_r2 = std::sqrt(std::numeric_limits<long double>::max());

// One node: offset o, weight factor g (rule weight × Jacobian), the weight w(x) = r2^-power/2.
void node(const Rule& r, long double ox, long double oy, long double g, int power, Row& row, Sums& s) {
  const long double px = r.ax + ox, py = r.ay + oy;
  const long double r2 = 1 + px * px + py * py;
  if (!(r2 <= max_r2)) s.overflow = true;
  const long double inv = 1 / r2;
  const long double wt = power == 4 ? g * inv * inv : g * inv / std::sqrt(r2);
  row.w += wt, row.x += wt * ox, row.y += wt * oy;
  // A position error δ per coordinate moves r2 by at most 2(|px| + |py|)δ + 2δ², so the weight,
  // r2^-2 or r2^-3/2, by at most 4(|px| + |py| + δ)δ/r2 relative (first order; doubled for
  // margin): the largest (|px| + |py| + δ)/r2 is kept here, times 8δ in offset_centroid.
  s.position_rel = std::max(s.position_rel, (std::fabs(px) + std::fabs(py) + r.delta) * inv);
}

void add_row(const Row& row, Sums& s) {
  s.w.add(row.w), s.x.add(row.x), s.y.add(row.y);
  s.rows += 1;
}

// Triangle with corners (offsets) P, Q, R, of exact area·2 `jacobian` (rounded once): the
// Duffy-collapsed product rule, w = |x|^-4. Its four midpoint children each have exactly a
// quarter of its area, so every piece's Jacobian is the fan triangle's over 4^depth — exact
// scaling, not recomputed from rounded corners (on a sliver those lose the width: issue 11).
void triangle(const Rule& r, const long double P[2], const long double Q[2], const long double R[2],
              long double jacobian, unsigned depth, Sums& s) {
  auto d2 = [](const long double* a, const long double* b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
  };
  const long double diameter2 = std::max({d2(P, Q), d2(Q, R), d2(R, P)});
  const long double r2_min = std::min({r2_at(r, P[0], P[1]), r2_at(r, Q[0], Q[1]), r2_at(r, R[0], R[1])});
  if (s.stopped()) return;
  if (needs_split(diameter2, r2_min)) {
    if (depth >= depth_limit) {
      s.depth_exceeded = true;
      return;
    }
    // Halving a piece no larger than a node's position error refines nothing: without this stop
    // every child would look as close to the axis as its parent and the pieces would grow as
    // 4^depth (a triangle from the origin to 1e20 took minutes; issue 13).
    if (diameter2 <= 16 * r.delta * r.delta) {
      s.unresolved = true;
      return;
    }
    const long double PQ[2] = {(P[0] + Q[0]) / 2, (P[1] + Q[1]) / 2};
    const long double QR[2] = {(Q[0] + R[0]) / 2, (Q[1] + R[1]) / 2};
    const long double RP[2] = {(R[0] + P[0]) / 2, (R[1] + P[1]) / 2};
    const long double quarter = jacobian / 4;
    triangle(r, P, PQ, RP, quarter, depth + 1, s);
    triangle(r, PQ, Q, QR, quarter, depth + 1, s);
    triangle(r, RP, QR, R, quarter, depth + 1, s);
    triangle(r, PQ, QR, RP, quarter, depth + 1, s);
    return;
  }
  const long double ex = Q[0] - P[0], ey = Q[1] - P[1], fx = R[0] - P[0], fy = R[1] - P[1];
  const std::size_t n = r.x.size();
  if ((s.nodes += std::max<std::size_t>(n * n, 16)) > node_budget) {  // a piece costs >= 16 nodes' time
    s.budget_exceeded = true;
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    Row row;
    for (std::size_t j = 0; j < n; ++j) {
      const long double u = r.x[i], v = r.x[j] * (1 - r.x[i]);  // Duffy collapse
      node(r, P[0] + u * ex + v * fx, P[1] + u * ey + v * fy,
           r.w[i] * r.w[j] * (1 - r.x[i]) * jacobian, 4, row, s);
    }
    add_row(row, s);
  }
}

// Segment from offset P to Q of exact length `length` (rounded once): the planar fan's weight
// |x|^-3 along it (docs/math.md §2, degenerate sets); halves have exactly half the length.
void segment(const Rule& r, const long double P[2], const long double Q[2], long double length,
             unsigned depth, Sums& s) {
  const long double ex = Q[0] - P[0], ey = Q[1] - P[1];
  const long double r2_min = std::min(r2_at(r, P[0], P[1]), r2_at(r, Q[0], Q[1]));
  if (s.stopped()) return;
  if (needs_split(ex * ex + ey * ey, r2_min)) {
    if (depth >= depth_limit) {
      s.depth_exceeded = true;
      return;
    }
    if (ex * ex + ey * ey <= 16 * r.delta * r.delta) {
      s.unresolved = true;
      return;
    }
    const long double M[2] = {(P[0] + Q[0]) / 2, (P[1] + Q[1]) / 2};
    segment(r, P, M, length / 2, depth + 1, s);
    segment(r, M, Q, length / 2, depth + 1, s);
    return;
  }
  if ((s.nodes += std::max<std::size_t>(r.x.size(), 16)) > node_budget) {
    s.budget_exceeded = true;
    return;
  }
  Row row;
  for (std::size_t i = 0; i < r.x.size(); ++i)
    node(r, P[0] + r.x[i] * ex, P[1] + r.x[i] * ey, r.w[i] * length, 3, row, s);
  add_row(row, s);
}

// A long double >= the exact non-negative rational q.
long double upper_ld(const Rational& q) {
  const long double d = to_long_double_nearest(q);
  return d + std::fabs(d) * 2 * unit_roundoff + std::numeric_limits<long double>::denorm_min();
}

// The offset centroid c of F under the weight by n-point rules, and a rigorous bound on its
// rounding error per coordinate (docs/math.md §2 "Quadrature: error statement").
struct Centroid {
  long double c[2] = {0, 0};
  long double rounding[2] = {0, 0};
  bool ok = false;
  std::string why;  // when not ok
};

Centroid offset_centroid(const std::vector<Point2>& v, ConvexKind kind, unsigned n) {
  Rule rule;
  gauss_legendre_01(n, rule.x, rule.w);
  rule.ax = to_long_double_nearest(v[0].x), rule.ay = to_long_double_nearest(v[0].y);
  const long double u = unit_roundoff;
  std::vector<std::array<long double, 2>> off(v.size());
  long double largest = 0;  // max |offset coordinate|
  for (std::size_t i = 0; i < v.size(); ++i) {
    off[i] = {to_long_double_nearest(Rational(v[i].x - v[0].x)),
              to_long_double_nearest(Rational(v[i].y - v[0].y))};
    largest = std::max({largest, std::fabs(off[i][0]), std::fabs(off[i][1])});
  }
  // A node's position: offsets rounded once (u·M), midpoints exact, P + u·e + v·f three
  // roundings of terms <= 3M (9u·M with margin), the apex rounded once (u·|a|): 16u·M + 2u·|a|.
  rule.delta = u * (16 * largest + 2 * (std::fabs(rule.ax) + std::fabs(rule.ay))) +
               std::numeric_limits<long double>::min();
  Sums s;
  const long double origin[2] = {0, 0};
  if (kind == ConvexKind::segment) {
    const Rational dx(v[1].x - v[0].x), dy(v[1].y - v[0].y);
    segment(rule, origin, off[1].data(), std::sqrt(to_long_double_nearest(Rational(dx * dx + dy * dy))), 0, s);
  } else {
    for (std::size_t t = 1; t + 1 < v.size(); ++t) {
      // Twice the fan triangle's area, exactly, rounded once.
      const Rational cross((v[t].x - v[0].x) * (v[t + 1].y - v[0].y) -
                           (v[t].y - v[0].y) * (v[t + 1].x - v[0].x));
      triangle(rule, origin, off[t].data(), off[t + 1].data(), to_long_double_nearest(abs(cross)), 0, s);
    }
  }
  Centroid out;
  const long double sw = s.w.value();
  if (s.depth_exceeded) {
    out.why = "the feasible set spans more scales than the subdivision limit (" +
              std::to_string(depth_limit) + " halvings) resolves";
    return out;
  }
  if (s.unresolved) {
    out.why = "near the cone's axis the feasible set needs pieces smaller than extended precision "
              "resolves at its distance from the first vertex";
    return out;
  }
  if (s.budget_exceeded) {
    out.why = "the subdivision needs more than 2^26 nodes (its work limit) on this feasible set";
    return out;
  }
  if (s.overflow || !(sw > 0) || !std::isfinite(sw)) {
    out.why = "the weight (1 + a^2 + b^2)^-2 over- or underflows the extended-precision range "
              "on this feasible set";
    return out;
  }
  // Relative error of each weight: the node's position error, and the rule's nodes and weights,
  // the Jacobian's rounding and the arithmetic of one weight, (64 + 8n)·u with margin.
  const long double eta = 8 * rule.delta * s.position_rel + (64 + 8 * static_cast<long double>(n)) * u;
  // Summation: γ_n within each row, then Neumaier over the rows (2u + 2·rows·u²), per unit of
  // Σ|terms|; Σ W = S_w (positive terms) and Σ W·|o_k| <= S_w·max|o_k| <= S_w·(largest + δ).
  const long double nu = static_cast<long double>(n) * u;
  const long double sum_rel = nu / (1 - nu) * (1 + 2 * u) + 2 * u + 2 * s.rows * u * u;
  const long double err_w = sum_rel * sw;
  const Rational* lo[2] = {&v[0].x, &v[0].y};
  for (int k = 0; k < 2; ++k) {
    out.c[k] = (k == 0 ? s.x.value() : s.y.value()) / sw;
    // F's extent along k bounds |o − c| for every node (c and the nodes lie in F, up to δ).
    Rational min = *lo[k], max = *lo[k];
    for (const Point2& p : v) min = std::min(min, k == 0 ? p.x : p.y), max = std::max(max, k == 0 ? p.x : p.y);
    const long double extent = upper_ld(Rational(max - min)) + 2 * rule.delta;
    const long double err_sum = sum_rel * sw * (largest + rule.delta);
    const long double r = eta * extent / (1 - eta) + rule.delta +
                          (err_sum + std::fabs(out.c[k]) * err_w) / (sw - err_w) +
                          2 * u * std::fabs(out.c[k]);
    out.rounding[k] = 2 * r;  // a factor 2 for the first-order terms
    if (!std::isfinite(out.c[k]) || !std::isfinite(out.rounding[k])) {
      out.why = "the weighted sums are not finite in extended precision on this feasible set";
      return out;
    }
  }
  out.ok = true;
  return out;
}

}  // namespace

MapEstimate mean_3d_quadrature(const ConvexSet2& F, unsigned order) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("mean_3d: empty feasible set");
  if (order == 0) throw std::invalid_argument("mean_3d_quadrature: order must be >= 1");
  // A point is its own mean, exactly.
  MapEstimate e = F.kind == ConvexKind::point ? exact_map_estimate("mean_3d", F.vertices[0])
                                              : MapEstimate{};
  e.rule = "mean_3d";
  e.method = "quadrature";
  e.quadrature_order = order;
  if (F.kind == ConvexKind::point) return e;

  // The fan apex v0 is F's first vertex. (The vertex nearest the origin was tried: it makes
  // every fan triangle touch the smallest |x|, so more of them are split — 3× the time on a
  // typical 12-gon — for no accuracy the error statement needed.)
  const std::vector<Point2>& v = F.vertices;
  const Centroid coarse = offset_centroid(v, F.kind, order);
  const Centroid fine = coarse.ok ? offset_centroid(v, F.kind, 2 * order) : coarse;
  if (!coarse.ok || !fine.ok) {
    e.valid = false;
    e.note = "quadrature cannot give a map with a trustworthy error statement here: " +
             (coarse.ok ? fine.why : coarse.why) + "; use the analytic route";
    return e;
  }
  // Per coordinate: the statement covers the truncation (2·|c_n − c_2n|) and both rules'
  // rounding; v0 + c_n ± it is enclosed outward (320 bits hold v0's rounding far below it) and
  // reported as one double like the closed form's enclosures.
  for (int k = 0; k < 2; ++k) {
    const long double estimate =
        2 * std::fabs(coarse.c[k] - fine.c[k]) + coarse.rounding[k] + fine.rounding[k];
    const internal::Interval x = internal::Interval(k == 0 ? v[0].x : v[0].y, 320) +
                                 internal::Interval(coarse.c[k], coarse.c[k], 320) +
                                 internal::Interval(-estimate, estimate, 320);
    const internal::RoundedEnclosure r = internal::round_to_double(x);
    if (internal::beyond_doubles(x) || !std::isfinite(r.value)) {
      e.valid = false;
      e.note = "the 3-D mean lies beyond the range of doubles (above 1.8e308): it has no map to report";
      return e;
    }
    e.map[k] = r.value;
    e.error_bounds[k] = r.bound;
    e.correctly_rounded[k] = r.correctly_rounded;
  }
  e.error_bound = std::max(e.error_bounds[0], e.error_bounds[1]);
  return e;
}

}  // namespace gmcc
