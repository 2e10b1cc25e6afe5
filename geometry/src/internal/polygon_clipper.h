#pragma once
// One clipping run of feasible_polygon: the lines met so far (approximate always, exact on
// demand) and the filtered exact predicates on vertices kept symbolically as pairs of lines
// (docs/derivations.md §4.3, docs/math.md §1a′). Internal to gmcc::geometry.

#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/numerics/filter_bounds.h>

#include "internal/canonical_lines.h"
#include "internal/extended_value.h"
#include "internal/image_hull.h"
#include "internal/integer_line.h"

#include <array>
#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace gmcc::internal {

// One clipping run: the lines met so far (approximate always, exact on demand) and the
// predicates on vertices given as pairs of lines.
class PolygonClipper {
 public:
  struct Vertex {
    std::size_t p, q;  // the vertex is the meet of lines p and q (not parallel)
    int w_sign;        // the sign of det[(a_p, b_p); (a_q, b_q)], the homogeneous weight
    std::size_t out;   // the line carrying the edge from this vertex to the next
    double lo[2], hi[2];  // certain bounds of its coordinates (infinite when unknown)
  };

  PolygonClipper(std::shared_ptr<const internal::CanonicalLines> g, const std::vector<ImagePoint>& qs, std::size_t lines)
      : keep_(std::move(g)), g_(*keep_), hq_(qs.size()) {
    lines_.reserve(lines);
    filtered_ = g_.filtered;
    long_ = !g_.long_lines.empty() && numerics::extended_precision_active();
    qs_.reserve(qs.size());
    for (const ImagePoint& q : qs) {
      qs_.push_back(q.exact);
      long_ = long_ && q.extended;
      q_long_.push_back(q.l);
      filtered_ = filtered_ && q.filtered;
      q_approx_.push_back(q.f);
    }
  }

  // A line given exactly (the box's sides).
  std::size_t add_exact(Line l) {
    ApproximateLine a{};
    filtered_ = filtered_ && approx_line(l, a) && in_range(a);
    lines_.push_back({a, npos, npos, nullptr});
    exact_.resize(lines_.size());
    exact_.back() = std::move(l);
    return lines_.size() - 1;
  }
  // Line j of the prepared map constraint (exact and approximate lines made once).
  std::size_t add_fixed(std::size_t j) {
    filtered_ = filtered_ && g_.extra_filtered;
    lines_.push_back({g_.extra_approx[j], npos, npos, &g_.extra_lines[j]});
    return lines_.size() - 1;
  }
  // The line (n_e ⊙ q)·m <= k_e of canonical half-plane e and image vertex k. Its approximation
  // is (a_e·q1, b_e·q2, c_e) from the truncated q and the scaled, truncated gamut line: three
  // relative errors below 2u, 2u and u (the product's rounding) give less than 5.01u, within the
  // 6u every approximate line is allowed. It is the exact line (a_e·X, b_e·Y, c_e·W) times
  // 2^-E/W > 0 up to those errors.
  ApproximateLine scaled_approx(std::size_t e, std::size_t k) const {
    const ApproximateLine& ge = g_.approx[e];
    return {ge.a * q_approx_[k][0], ge.b * q_approx_[k][1], ge.c};
  }
  std::size_t add_scaled(std::size_t e, std::size_t k) {
    const ApproximateLine a = scaled_approx(e, k);
    filtered_ = filtered_ && in_range(a);
    lines_.push_back({a, e, k, nullptr});
    return lines_.size() - 1;
  }
  // Forgets the line added last: one that did not cut, which no vertex refers to (clip_convex
  // tries every line, and keeps only those it clips by).
  void drop_last() {
    lines_.pop_back();
    if (exact_.size() > lines_.size()) exact_.resize(lines_.size());
  }

  Vertex vertex(std::size_t p, std::size_t q, std::size_t out) {
    Vertex v{p, q, weight_sign(p, q), out, {-HUGE_VAL, -HUGE_VAL}, {HUGE_VAL, HUGE_VAL}};
    if (filtered_) {
      const EnclosedVertex e = enclose_double(v);
      if (std::isfinite(e.x.rad) && std::isfinite(e.y.rad))
        v.lo[0] = e.x.lo(), v.hi[0] = e.x.hi(), v.lo[1] = e.y.lo(), v.hi[1] = e.y.hi();
    }
    return v;
  }

  // The sign of a·x + b·y − c over vertex v's box of certain bounds, when it is the same all over
  // the box (0: not decided here), for an approximation within 6u of a positive multiple of the
  // exact line: a·x + b·y is largest at the corner the normal points to and least at the opposite
  // one, and a·x + b·y − c at a corner is within 16u of its computed magnitude sum (the bound of
  // side_of_point, for exact corner coordinates). Underflow cannot fool it: a filtered line with
  // c != 0 lies at least about 2^-291 from the origin, so a vertex is the origin (its box
  // straddles 0: no strict decision) or has a coordinate of at least about 2^-292, whose product
  // is normal; infinite or NaN bounds never pass the strict comparisons.
  static int box_side(const ApproximateLine& l, const Vertex& v) {
    const int ia = l.a > 0, ib = l.b > 0;
    const double x_hi = l.a * (ia ? v.hi[0] : v.lo[0]), y_hi = l.b * (ib ? v.hi[1] : v.lo[1]);
    const double top = x_hi + y_hi - l.c;
    if (top < -numerics::filter_bound::clip_point_side * (std::fabs(x_hi) + std::fabs(y_hi) + std::fabs(l.c))) return -1;
    const double x_lo = l.a * (ia ? v.lo[0] : v.hi[0]), y_lo = l.b * (ib ? v.lo[1] : v.hi[1]);
    const double bottom = x_lo + y_lo - l.c;
    if (bottom > numerics::filter_bound::clip_point_side * (std::fabs(x_lo) + std::fabs(y_lo) + std::fabs(l.c))) return 1;
    return 0;
  }

  // True when every vertex of the cycle lies strictly inside the half-plane a·x + b·y <= c (then
  // clipping by it changes nothing), decided from the vertices' boxes.
  bool all_inside(const ApproximateLine& l, const std::vector<Vertex>& cycle) const {
    if (!filtered_ || !in_range(l)) return false;
    for (const Vertex& v : cycle)
      if (box_side(l, v) != -1) return false;
    return true;
  }

  // The sign of a·x + b·y − c at vertex v for line h (v's weight taken positive).
  int side(std::size_t h, const Vertex& v) {
    if (h == v.p || h == v.q) return 0;  // on its own lines: symbolically, no arithmetic
    // First from the vertex's box (cheaper than the 3×3 determinant). That is the geometric side,
    // which is side_raw·w_sign; an exact 0 is never decided there.
    if (filtered_)
      if (const int b = box_side(lines_[h].approx, v)) return b;
    return side_raw(v.p, v.q, h) * v.w_sign;
  }

  // sign det[(a_p, b_p); (a_q, b_q)]. Each coefficient is within a relative 6u of a positive
  // multiple of the exact one (row by row, which keeps the sign), so each product is within
  // (1+6u)² − 1 < 12.01u; evaluating a·b − c·d adds at most 2.01u of |ab| + |cd| (two rounded
  // products and a rounded difference). 16u of the computed magnitude covers both.
  int weight_sign(std::size_t i, std::size_t j) {
    if (filtered_) {
      const ApproximateLine &p = lines_[i].approx, &q = lines_[j].approx;
      const double l = p.a * q.b, r = q.a * p.b;
      const numerics::UncertainSign w = numerics::sign_within(l - r, numerics::filter_bound::clip_weight * (std::fabs(l) + std::fabs(r)));
      if (w.is_certain()) return w.lo;
    }
    const Line &p = exact(i), &q = exact(j);
    return sgn(mpz_class(p.a * q.b - q.a * p.b));
  }

  bool same_point(const Vertex& v, const Vertex& w) { return side(w.p, v) == 0 && side(w.q, v) == 0; }

  // True when the cycle (no repeats) turns strictly left at every vertex: each next vertex lies
  // strictly inside the line carrying the edge into the current one.
  bool strictly_convex(const std::vector<Vertex>& v) {
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n; ++i)
      if (side(v[(i + n - 1) % n].out, v[(i + 1) % n]) >= 0) return false;
    return true;
  }

  bool filtered() const { return filtered_; }
  const ApproximateLine& approximate(std::size_t h) const { return lines_[h].approx; }

  // Certified enclosures of vertex v's coordinates: x = (c_p b_q − c_q b_p)/w,
  // y = (a_p c_q − a_q c_p)/w, w = a_p b_q − a_q b_p, all invariant under positive scalings of
  // the lines. From extended-precision lines where available (then the double rounding of the
  // result dominates the radius), else from the double lines (only when filtered()).
  EnclosedVertex enclose(const Vertex& v) {
    const auto lp = long_ ? long_line(v.p) : std::nullopt, lq = long_ ? long_line(v.q) : std::nullopt;
    if (lp && lq) {
      const LongLine &p = *lp, &q = *lq;
      // Each 2×2 determinant: products within (1+ρ)²(1+2^-64) − 1 < 1.07·2^-60 of the exact
      // (scaled) terms for ρ = 2^-61, the difference rounds by 2^-64 of the magnitude sum: 2^-59
      // of the computed magnitude covers both.
      struct Det {
        long double value, bound;
      };
      auto det = [](long double a, long double d, long double b, long double c) {
        const long double l = a * d, r = b * c;
        return Det{l - r, 0x1p-59L * (std::fabs(l) + std::fabs(r))};
      };
      const Det w = det(p.a, q.b, q.a, p.b);
      const long double gap = std::fabs(w.value) - w.bound;
      // |exact − n/w| <= (e_n + |n/w|·e_w)/(|w| − e_w); then x rounds by 2^-64 (and xd by u).
      auto coordinate = [&](const Det& n) -> LongEnclosure {
        if (!(gap > 0)) return {0, LongEnclosure::unbounded};
        const long double x = n.value / w.value;
        const long double spread = (n.bound + std::fabs(x) * (1 + 0x1p-62L) * w.bound) / gap;
        return {x, LongEnclosure::round_up(spread * (1 + 0x1p-60L) + 0x1p-63L * std::fabs(x))};
      };
      auto to_double = [](const LongEnclosure& x) -> Enclosure {
        const double xd = static_cast<double>(x.mid);
        return {xd, Enclosure::round_up(static_cast<double>(x.rad) + u * std::fabs(xd))};
      };
      return {to_double(coordinate(det(p.c, q.b, q.c, p.b))), to_double(coordinate(det(p.a, q.c, q.a, p.c)))};
    }
    return enclose_double(v);
  }

  // Extended-precision enclosures from the exact lines: the Cramer numerators and the weight in
  // integers, then each quotient from their top 64 bits (2^-63 each) and one rounded division
  // (2^-64): within a relative 2^-61.5 however ill-conditioned the meet (nearly parallel lines).
  LongEnclosedVertex enclose_exactly(const Vertex& v) {
    const Line &p = exact(v.p), &q = exact(v.q);
    const mpz_class w = p.a * q.b - q.a * p.b, x = p.c * q.b - q.c * p.b, y = p.a * q.c - q.a * p.c;
    auto quotient = [&w](const mpz_class& n) -> LongEnclosure {
      const auto a = top_bits(n.get_mpz_t()), b = top_bits(w.get_mpz_t());
      if (!a || !b || *b == 0) return {0, LongEnclosure::unbounded};
      return LongEnclosure::relative(*a / *b, 0x1p-61L);
    };
    return {quotient(x), quotient(y)};
  }

  // The same from the double lines: each 2×2 determinant within 16u of its computed magnitude
  // sum (the bound of weight_sign, the same expression shape). Only when filtered().
  EnclosedVertex enclose_double(const Vertex& v) const {
    const ApproximateLine &p = lines_[v.p].approx, &q = lines_[v.q].approx;
    auto det = [](double a, double d, double b, double c) {  // a·d − b·c
      const double l = a * d, r = b * c;
      return Enclosure{l - r, Enclosure::round_up(numerics::filter_bound::clip_weight * (std::fabs(l) + std::fabs(r)))};
    };
    const Enclosure w = det(p.a, q.b, q.a, p.b);
    return {det(p.c, q.b, q.c, p.b) / w, det(p.a, q.c, q.a, p.c) / w};
  }

  // The sign of a·m1 + b·m2 − c for line h at the exact point m, with fm its truncation to
  // doubles (each within 2u) when in the filter's range. Filter: each product is within
  // (1+6u)(1+2u)(1+u) − 1 < 9.01u of the exact (scaled) term and the two additions add at most
  // 2.01u of the magnitude sum: 16u of the computed magnitude covers it.
  int side_of_point(std::size_t h, const Point2& m, const std::optional<std::array<double, 2>>& fm) {
    if (filtered_ && fm) {
      const ApproximateLine& l = lines_[h].approx;
      const double x = l.a * (*fm)[0], y = l.b * (*fm)[1];
      const numerics::UncertainSign s =
          numerics::sign_within(x + y - l.c, numerics::filter_bound::clip_point_side * (std::fabs(x) + std::fabs(y) + std::fabs(l.c)));
      if (s.is_certain()) return s.lo;
    }
    const Line& l = exact(h);
    return sgn(Rational(l.a * m.x + l.b * m.y - l.c));
  }

  // The exact vertex, reduced.
  Point2 point(const Vertex& v) {
    const Line& p = exact(v.p);
    const Line& q = exact(v.q);
    mpz_class x = p.c * q.b - q.c * p.b, y = p.a * q.c - q.a * p.c, w = p.a * q.b - q.a * p.b;
    if (sgn(w) < 0) x = -x, y = -y, w = -w;
    Rational rx(x, w), ry(y, w);
    rx.canonicalize();
    ry.canonicalize();
    return {std::move(rx), std::move(ry)};
  }

 private:
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  struct Entry {
    ApproximateLine approx;
    std::size_t gamut_edge, image_vertex;  // its source, when not given exactly
    const Line* fixed;  // or a prepared exact line (the map constraint's)
  };

  // The extended-precision line: the gamut line's coefficients times the image vertex's
  // coordinates (each factor within 2^-63 resp. 2^-61.6, the product rounds by 2^-64: within
  // 2^-61 of (a·X, b·Y, c·W)/W), or the exact box line truncated.
  std::optional<LongLine> long_line(std::size_t i) {
    const Entry& l = lines_[i];
    if (l.gamut_edge == npos) {
      const Line& e = l.fixed ? *l.fixed : *exact_[i];
      const auto a = top_bits(e.a.get_mpz_t()), b = top_bits(e.b.get_mpz_t()), c = top_bits(e.c.get_mpz_t());
      if (!a || !b || !c) return std::nullopt;
      return LongLine{*a, *b, *c};
    }
    const LongLine& g = g_.long_lines[l.gamut_edge];
    return LongLine{g.a * q_long_[l.image_vertex][0], g.b * q_long_[l.image_vertex][1], g.c};
  }

  static bool in_range(const ApproximateLine& a) { return in_filter_range(a.a) && in_filter_range(a.b) && in_filter_range(a.c); }

  const Line& exact(std::size_t i) {
    const Entry& l = lines_[i];
    if (l.fixed) return *l.fixed;
    // A deque: growing it keeps references to earlier lines valid (callers hold several).
    if (exact_.size() <= i) exact_.resize(lines_.size());
    std::optional<Line>& built = exact_[i];
    if (!built) {
      if (!hq_[l.image_vertex]) hq_[l.image_vertex] = homogeneous(*qs_[l.image_vertex]);
      const HomogeneousPoint& q = *hq_[l.image_vertex];
      const Line& g = g_.lines[l.gamut_edge];
      // m ⊙ q ∈ {a·x + b·y <= c}  ⟺  (a·X)·m1 + (b·Y)·m2 <= c·W for q = (X/W, Y/W), W > 0.
      built = Line{g.a * q.x, g.b * q.y, g.c * q.w};
    }
    return *built;
  }

  // sign of h_a·(p_c q_b − q_c p_b) + h_b·(p_a q_c − q_a p_c) − h_c·(p_a q_b − q_a p_b): the side of
  // the unnormalised meet of p and q, a 3×3 determinant. Filter: each of its six triple products
  // is within (1+6u)³ − 1 < 18.01u of the exact (scaled) one, and the evaluation below rounds each
  // term at most six times (γ6 < 6.01u), for at most 24.1u of the exact magnitude sum, which is at
  // most (1+6u)³(1+4u) times the computed one: 32u of the computed magnitude covers it.
  int side_raw(std::size_t pi, std::size_t qi, std::size_t hi) {
    if (filtered_) {
      const ApproximateLine &p = lines_[pi].approx, &q = lines_[qi].approx, &h = lines_[hi].approx;
      const double x1 = p.c * q.b, x2 = q.c * p.b, y1 = p.a * q.c, y2 = q.a * p.c, w1 = p.a * q.b, w2 = q.a * p.b;
      const double s = h.a * (x1 - x2) + h.b * (y1 - y2) - h.c * (w1 - w2);
      const double mag = std::fabs(h.a) * (std::fabs(x1) + std::fabs(x2)) +
                         std::fabs(h.b) * (std::fabs(y1) + std::fabs(y2)) +
                         std::fabs(h.c) * (std::fabs(w1) + std::fabs(w2));
      const numerics::UncertainSign filtered = numerics::sign_within(s, numerics::filter_bound::clip_vertex_side * mag);
      if (filtered.is_certain()) return filtered.lo;
      if (mag == 0) return 0;  // every term has an exactly zero factor (no underflow in range)
    }
    const Line &p = exact(pi), &q = exact(qi), &h = exact(hi);
    return sgn(mpz_class(h.a * (p.c * q.b - q.c * p.b) + h.b * (p.a * q.c - q.a * p.c) -
                         h.c * (p.a * q.b - q.a * p.b)));
  }

  std::shared_ptr<const internal::CanonicalLines> keep_;
  const internal::CanonicalLines& g_;
  std::vector<const Point2*> qs_;  // the image hull's vertices (owned by the caller or State)
  std::vector<std::optional<HomogeneousPoint>> hq_;
  std::vector<std::array<double, 2>> q_approx_;
  std::vector<std::array<long double, 2>> q_long_;
  bool long_ = false;
  std::vector<Entry> lines_;
  std::deque<std::optional<Line>> exact_;  // exact lines, built on demand (index: line)
  bool filtered_ = true;
};

using Vertex = PolygonClipper::Vertex;

}  // namespace gmcc::internal
