#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/geometry/integers_over_lcm.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/worst_case_illuminant.h>
#include <gmcc/numerics/internal_check.h>

#include "internal/illuminant_filters.h"
#include "internal/integer_polynomial.h"
#include "internal/interval.h"
#include "internal/worst_case_illuminant_route.h"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace gmcc {
namespace {

// The edge quartics' algebra: internal/integer_polynomial.h.
using Poly = internal::IntegerPolynomial;
using internal::add;
using internal::derivative;
using internal::mul;
using internal::no_root_in_open_unit_interval;
using internal::roots_in_unit_interval;
using internal::scaled;
using internal::sub;
using internal::trim;
using internal::closeness_of;
using internal::edge_cannot_be_worst;
using internal::edge_skippable;
using internal::no_stationary_point;

// The filters below only skip work whose exact result is known not to matter, so the answer is
// the exact route's, bit for bit; they make a feasible set of 10^5–10^6 vertices (a many-vertex
// canonical gamut, docs/performance-history.md "Many-vertex canonical gamuts (issue 13)") cost
// floating-point operations per vertex and edge instead of exact polynomial algebra.

// The second filter, on what the first leaves (issue 13: a feasible set of 1942 vertices within
// 2^-53 of one another, where no double enclosure decides anything). It works on
// s(x) = |e × w|² / |w|², w = c ⊘ (x, 1), instead of the closeness: by Lagrange's identity
// (e·w)² + |e × w|² = |e|²|w|², so closeness = |e|² − s and the least closeness is the greatest s,
// with the same ties. Written in δ = x − m (exact) the cross product has no cancellation:
//   e × w = (c2·c3·δ2 / (m2·x2), −c1·c3·δ1 / (m1·x1), c1·c2·(m2·δ1 − m1·δ2) / (m1·m2·x1·x2)),
// so s is enclosed to a relative width of a few units of the precision however close the angles
// are to one another, and over an edge (its bounding box in x and in δ) to within a first-order
// term in the edge's length. MPFI at 128 bits, doubling while it decides more (at most 8192).
// A vertex whose s is certainly below some vertex's, and an edge whose s is certainly below it
// everywhere, cannot hold the worst case (which the exact route takes at the first candidate of
// least closeness, and at an edge's point only where strictly below every vertex's): they are
// dropped. The order of the rest is kept.
using internal::Interval;

class SineFilter {
 public:
  SineFilter(const std::vector<Point2>& vs, const Point2& m, const Colour& c) : vs_(vs), m_(m), c_(c) {}

  // Returns the last precision used.
  unsigned refine(std::vector<std::size_t>& candidates, std::vector<std::size_t>& edges) {
    const std::size_t n = vs_.size();
    std::vector<std::size_t> needed = candidates;
    for (std::size_t i : edges) needed.insert(needed.end(), {i, (i + 1) % n});
    std::sort(needed.begin(), needed.end());
    needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
    std::vector<std::array<Rational, 2>> delta;  // δ = x − m of needed[k], exact
    for (std::size_t i : needed) delta.push_back({Rational(vs_[i].x - m_.x), Rational(vs_[i].y - m_.y)});
    for (mpfr_prec_t bits = 128;; bits *= 2) {
      set_constants(bits);
      // Vertex i as the point box (x1, x2, δ1, δ2), enclosed afresh (only what is left is kept).
      auto point = [&](std::size_t i) {
        const std::size_t k = static_cast<std::size_t>(std::lower_bound(needed.begin(), needed.end(), i) - needed.begin());
        return std::array<Interval, 4>{Interval(vs_[i].x, bits), Interval(vs_[i].y, bits), Interval(delta[k][0], bits),
                                       Interval(delta[k][1], bits)};
      };
      std::vector<Interval> at_vertex;  // s at candidates[k]
      for (std::size_t i : candidates) at_vertex.push_back(sine(point(i)));
      // The greatest lower end among the candidates: some vertex has s at least this.
      std::size_t best = 0;
      for (std::size_t k = 1; k < at_vertex.size(); ++k)
        if (mpfr_cmp(&at_vertex[k].get()->left, &at_vertex[best].get()->left) > 0) best = k;
      mpfr_srcptr floor = &at_vertex[best].get()->left;
      const std::size_t before = candidates.size() + edges.size();
      bool precise = true;  // every candidate's s enclosed to a relative 2^-(bits/2)
      std::vector<std::size_t> kept;
      for (std::size_t k = 0; k < candidates.size(); ++k) {
        if (mpfr_cmp(&at_vertex[k].get()->right, floor) < 0) continue;
        kept.push_back(candidates[k]);
        precise = precise && tight(at_vertex[k], static_cast<int>(bits / 2));
      }
      candidates = std::move(kept);
      kept.clear();
      std::optional<std::pair<std::size_t, std::array<Interval, 4>>> last;  // the last edge's end
      for (std::size_t i : edges) {
        std::array<Interval, 4> box = last && last->first == i ? last->second : point(i);
        const std::size_t j = (i + 1) % n;
        last.emplace(j, point(j));
        for (int c = 0; c < 4; ++c) mpfi_union(box[c].get(), box[c].get(), last->second[c].get());
        if (mpfr_cmp(&sine(box).get()->right, floor) >= 0) kept.push_back(i);
      }
      edges = std::move(kept);
      const std::size_t after = candidates.size() + edges.size();
      // Enough: one candidate left; or nothing decided at a precision that was not the limit
      // (the boxes are); or the cap.
      if (after <= 1 || (after == before && precise) || bits >= 8192) return static_cast<unsigned>(bits);
    }
  }

 private:
  void set_constants(mpfr_prec_t bits) {
    c1_.emplace(c_.r, bits), c2_.emplace(c_.g, bits), c3_.emplace(c_.b, bits);
    m1_.emplace(m_.x, bits), m2_.emplace(m_.y, bits);
    c2c3_.emplace(*c2_ * *c3_), c1c3_.emplace(*c1_ * *c3_), c1c2_.emplace(*c1_ * *c2_), c3c3_.emplace(sqr(*c3_));
  }

  // s over the box x ∈ b[0] × b[1], δ ∈ b[2] × b[3] (a point's or an edge's).
  Interval sine(const std::array<Interval, 4>& b) const {
    const Interval& x1 = b[0];
    const Interval& x2 = b[1];
    const Interval& d1 = b[2];
    const Interval& d2 = b[3];
    const Interval mx1 = *m1_ * x1, mx2 = *m2_ * x2;
    const Interval u = *c2c3_ * d2 / mx2, v = *c1c3_ * d1 / mx1;
    const Interval w = *c1c2_ * (*m2_ * d1 - *m1_ * d2) / (mx1 * mx2);
    const Interval cross = sqr(u) + sqr(v) + sqr(w);
    return cross / (sqr(*c1_ / x1) + sqr(*c2_ / x2) + *c3c3_);
  }

  const std::vector<Point2>& vs_;
  const Point2& m_;
  const Colour& c_;
  std::optional<Interval> c1_, c2_, c3_, m1_, m2_, c2c3_, c1c3_, c1c2_, c3c3_;
};

// worst_case_illuminant's preconditions (std::invalid_argument when one fails).
void check_input(const ConvexSet2& F, const Point2& m, const Colour& c) {
  if (F.kind == ConvexKind::empty)
    throw std::invalid_argument("worst_case_illuminant: empty feasible set");
  for (const Rational* x : {&m.x, &m.y, &c.r, &c.g, &c.b})
    if (sgn(*x) <= 0)
      throw std::invalid_argument("worst_case_illuminant: map and illuminant must be > 0");
  for (const Point2& v : F.vertices)
    if (sgn(v.x) <= 0 || sgn(v.y) <= 0)
      throw std::invalid_argument("worst_case_illuminant: feasible maps must be > 0");
}

// Along the edge x(t) = p + t·(da, db), t ∈ [0, 1], the numerator of d/dt of the angle's cosine
// (a quartic in t; e_int the estimate's illuminant direction in integers).
Poly stationary_polynomial(const Point2& p, const Rational& da, const Rational& db, const Colour& c,
                           const std::vector<mpz_class>& e_int) {
  // v(t) = a·b · (c ⊘ (a, b, 1)) = (c1·b, c2·a, c3·a·b) with a = p.x + t·da, b = p.y + t·db,
  // scaled by a positive integer to integer coefficients (the angle's stationary points are
  // unchanged by positive scalings of v and of e).
  const std::vector<mpz_class> k = integers_over_lcm(std::vector<Rational>{
      c.r * p.y, c.r * db, c.g * p.x, c.g * da, c.b * p.x * p.y,
       c.b * (p.x * db + da * p.y), c.b * da * db});
  std::array<Poly, 3> v{Poly{k[0], k[1]}, Poly{k[2], k[3]}, Poly{k[4], k[5], k[6]}};
  for (Poly& vj : v) trim(vj);
  const std::array<Poly, 3> dv{derivative(v[0]), derivative(v[1]), derivative(v[2])};
  Poly e_v, e_dv, v_v, v_dv;
  for (int j = 0; j < 3; ++j) {
    e_v = add(e_v, scaled(v[j], e_int[j]));
    e_dv = add(e_dv, scaled(dv[j], e_int[j]));
    v_v = add(v_v, mul(v[j], v[j]));
    v_dv = add(v_dv, mul(v[j], dv[j]));
  }
  // d/dt (e·v)/|v| = [(e·v′)|v|² − (e·v)(v·v′)] / |v|³. The product is degree 5 term by term;
  // the t⁵ terms cancel (both are 2·e3·c3³·(Δa·Δb)³), which we check rather than assume.
  const Poly stationary = sub(mul(e_dv, v_v), mul(e_v, v_dv));
  GMCC_CHECK(stationary.size() <= 5, "worst_case_illuminant: the edge polynomial is a quartic");
  return stationary;
}

// The vertices and edges that may hold the worst case, after the double filters (and, on the
// certified route, the sine filter): the rest certainly lose to one of these.
struct Survivors {
  std::vector<std::size_t> vertices, edges;
  unsigned sine_bits = 0;
};
Survivors filter_candidates(const ConvexSet2& F, const Point2& m, const Colour& c, const std::array<Rational, 3>& e,
                            bool filtered, bool certified) {
  const auto& vs = F.vertices;
  Survivors out;
  // The vertices in enclosures: only those whose closeness may be the least need the exact
  // comparison. The first vertex attaining the least exact closeness is among them (its lower
  // end is at most every upper end), and is still found first, in order.
  const std::array<Enclosure, 3> ce{enclose_rational(c.r), enclose_rational(c.g), enclose_rational(c.b)};
  const std::array<Enclosure, 3> ee{enclose_rational(e[0]), enclose_rational(e[1]), enclose_rational(e[2])};
  std::vector<std::array<Enclosure, 2>> ve;  // the vertices' enclosures (when filtered)
  std::vector<double> lower(vs.size(), -Enclosure::unbounded);
  double least_upper = Enclosure::unbounded;
  if (filtered) {
    ve.resize(vs.size());
    for (std::size_t i = 0; i < vs.size(); ++i) {
      ve[i] = {enclose_rational(vs[i].x), enclose_rational(vs[i].y)};
      const Enclosure k = closeness_of(ee, ce, ve[i][0], ve[i][1]);
      if (!k.finite()) continue;
      lower[i] = k.lo();
      least_upper = std::min(least_upper, k.hi());
    }
  }
  std::vector<std::size_t>& candidates = out.vertices;
  for (std::size_t i = 0; i < vs.size(); ++i)
    if (!(lower[i] > least_upper)) candidates.push_back(i);
  // A segment has one edge, a polygon n, a point none; those the double filters leave.
  const std::size_t n_edges =
      F.kind == ConvexKind::polygon ? vs.size() : F.kind == ConvexKind::segment ? 1 : 0;
  std::vector<std::size_t>& edges = out.edges;
  for (std::size_t i = 0; i < n_edges; ++i) {
    const std::size_t j = (i + 1) % vs.size();
    if (filtered && (edge_cannot_be_worst(ee, ce, ve[i][0], ve[i][1], ve[j][0], ve[j][1], least_upper) ||
                     no_stationary_point(ee, ce, ve[i][0], ve[i][1], ve[j][0], ve[j][1]) ||
                     edge_skippable(ee, ce, ve[i][0], ve[i][1], ve[j][0] - ve[i][0], ve[j][1] - ve[i][1],
                                    0, 1, least_upper, 8)))
      continue;
    edges.push_back(i);
  }
  if (certified && candidates.size() + edges.size() > 1)
    out.sine_bits = SineFilter(vs, m, c).refine(candidates, edges);
  return out;
}

}  // namespace

IlluminantWorstCase internal::worst_case_illuminant(const ConvexSet2& F, const Point2& m, const Colour& c,
                                                    IlluminantRoute route, IlluminantRouteWork* work) {
  IlluminantRouteWork tally;
  const bool filtered = route != IlluminantRoute::exact;
  const bool certified = route == IlluminantRoute::certified;
  check_input(F, m, c);

  // e: the estimate's illuminant c ⊘ (m, 1). A candidate x implies the direction c ⊘ (x, 1); the
  // angle grows as cos²/|e|² = (e·w)²/|w|² falls, compared exactly (e·w > 0: all positive).
  const std::array<Rational, 3> e{Rational(c.r / m.x), Rational(c.g / m.y), c.b};
  // In integers: a positive common factor, which changes no sign and no root.
  const std::vector<mpz_class> e_int = integers_over_lcm(e);
  const std::array<Rational, 3> c_q{c.r, c.g, c.b};
  auto closeness = [&](const Point2& x) { return closeness_of(e, c_q, x.x, x.y); };
  const auto& vs = F.vertices;
  const Survivors survivors = filter_candidates(F, m, c, e, filtered, certified);
  const std::vector<std::size_t>& candidates = survivors.vertices;
  const std::vector<std::size_t>& edges = survivors.edges;
  tally.sine_bits = survivors.sine_bits;
  tally.exact_vertices = candidates.size();
  tally.exact_edges = edges.size();

  IlluminantWorstCase worst;
  worst.location = vs[candidates.front()];
  Rational worst_closeness = closeness(worst.location);
  auto consider = [&](Point2 x, bool at_vertex) {
    Rational k = closeness(x);
    if (k < worst_closeness) {
      worst_closeness = std::move(k);
      worst.location = std::move(x);
      worst.at_vertex = at_vertex;
    }
  };
  for (std::size_t i : candidates) consider(vs[i], true);

  for (std::size_t i : edges) {
    const Point2& p = vs[i];
    const Point2& q = vs[(i + 1) % vs.size()];
    const Rational da = q.x - p.x, db = q.y - p.y;
    const Poly stationary = stationary_polynomial(p, da, db, c, e_int);
    if (stationary.empty()) continue;  // constant angle along the edge: its ends suffice
    // No stationary point inside the edge: roots_in_unit_interval would find at most t = 1,
    // the vertex q, which is no new candidate.
    if (certified && no_root_in_open_unit_interval(stationary)) continue;
    ++tally.sturm_edges;
    for (const Rational& t : roots_in_unit_interval(stationary)) {
      if (t == 1) continue;  // the vertex q, already a candidate
      consider({Rational(p.x + t * da), Rational(p.y + t * db)}, false);
    }
  }
  worst.angle_deg = illuminant_angular_error_deg(m, worst.location, c);
  if (work) *work = tally;
  return worst;
}

IlluminantWorstCase worst_case_illuminant(const ConvexSet2& F, const Point2& m, const Colour& c) {
  return internal::worst_case_illuminant(F, m, c, internal::IlluminantRoute::certified);
}

double worst_case_illuminant_deg(const ConvexSet2& F, const Point2& m, const Colour& c) {
  return worst_case_illuminant(F, m, c).angle_deg;
}

}  // namespace gmcc
