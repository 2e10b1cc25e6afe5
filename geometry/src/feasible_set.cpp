#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>

#include <gmcc/numerics/platform.h>
#include <gmcc/numerics/top_bits.h>

#include "internal/feasible_polygon_route.h"
#include "internal/half_plane.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <deque>
#include <limits>
#include <optional>

namespace gmcc {
namespace {

// Exact clipping in homogeneous integer coordinates, with filtered predicates. A line (a, b, c)
// means a·x + b·y <= c with integer coefficients. A vertex is kept *symbolically*, as the pair of
// input lines it is the intersection of (docs/derivations.md §4.3: every vertex is the meet of two
// input lines, so constructions never nest). Every decision is the sign of a small determinant of
// line coefficients: it is first evaluated in double from rounded coefficients with a rigorous
// error bound, and only when |value| does not exceed the bound in exact integer arithmetic (GMP),
// from exact lines built on demand. Exact coordinates are constructed only for the final vertices.
struct Line {
  mpz_class a, b, c;
};
// A positive multiple s·(a, b, c) of an exact line with each coefficient rounded: within a
// relative 6u of s·a, s·b, s·c (u = 2^-53; see ApproxLine construction below for the count).
struct ApproxLine {
  double a, b, c;
};

// u = 2^-53, the unit roundoff of double.
constexpr double u = 0x1p-53;
// Magnitudes allowed in filtered evaluation: every non-zero coefficient in [2^-300, 2^300], so
// that products of up to three stay normal (no underflow or overflow) and the error bounds
// below, which are relative, hold. Inputs outside this range take the exact path.
constexpr double filter_min = 0x1p-300, filter_max = 0x1p300;
bool in_filter_range(double x) { return x == 0 || (std::fabs(x) >= filter_min && std::fabs(x) <= filter_max); }

Line integer_line(const internal::HalfPlane& h) {
  mpz_class l;
  mpz_lcm(l.get_mpz_t(), h.a.get_den_mpz_t(), h.b.get_den_mpz_t());
  mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), h.c.get_den_mpz_t());
  Line line{h.a.get_num() * (l / h.a.get_den()), h.b.get_num() * (l / h.b.get_den()),
            h.c.get_num() * (l / h.c.get_den())};
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), line.a.get_mpz_t(), line.b.get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), line.c.get_mpz_t());
  if (g > 1) line.a /= g, line.b /= g, line.c /= g;
  return line;
}

// An integer line scaled by 2^-E (E its largest binary exponent) and truncated to doubles:
// mpz_get_d_2exp truncates to 53 bits, a relative error below 2^-52 = 2u; the scaling is exact.
// False (no filter) when a coefficient would fall below 2^-150 relative to the largest.
bool approx_line(const Line& l, ApproxLine& out) {
  long e[3];
  const double m[3] = {mpz_get_d_2exp(&e[0], l.a.get_mpz_t()), mpz_get_d_2exp(&e[1], l.b.get_mpz_t()),
                       mpz_get_d_2exp(&e[2], l.c.get_mpz_t())};
  long top = 0;
  bool any = false;
  for (int k = 0; k < 3; ++k)
    if (m[k] != 0) top = any ? std::max(top, e[k]) : e[k], any = true;
  double r[3];
  for (int k = 0; k < 3; ++k) {
    if (m[k] == 0) {
      r[k] = 0;
      continue;
    }
    if (e[k] - top < -150) return false;
    r[k] = std::ldexp(m[k], static_cast<int>(e[k] - top));
  }
  out = {r[0], r[1], r[2]};
  return true;
}

// x = (X/W, Y/W) with W the lcm of the denominators: integers, no gcd per operation after.
struct HomogeneousPoint {
  mpz_class x, y, w;
};
HomogeneousPoint homogeneous(const Point2& p) {
  HomogeneousPoint h;
  mpz_lcm(h.w.get_mpz_t(), p.x.get_den_mpz_t(), p.y.get_den_mpz_t());
  h.x = p.x.get_num() * (h.w / p.x.get_den());
  h.y = p.y.get_num() * (h.w / p.y.get_den());
  return h;
}

// 2^e, exactly, for |e| < 1000 (built from its bits: cheaper than ldexp).
double pow2(long e) {
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}
// x·2^e exactly in extended precision (no overflow or underflow there for |e| < 16000); pow2 is
// called with |e| <= 900 only.
long double scale(long double x, long e) {
  while (e > 900) x *= pow2(900), e -= 900;
  while (e < -900) x *= pow2(-900), e += 900;
  return x * pow2(e);
}

// An integer in extended precision (relative error below 2^-63), or nothing beyond 2^16000.
std::optional<long double> top_bits(mpz_srcptr z) {
  if (mpz_size(z) > 250) return std::nullopt;
  const numerics::TopBits t = numerics::top_bits(z);
  const long double v = scale(static_cast<long double>(t.mantissa), t.shift);
  return mpz_sgn(z) < 0 ? -v : v;
}

// A rational in extended precision: numerator and denominator truncated (2^-63 each) and one
// rounded division (2^-64): relative error below 2^-61.6. Nothing beyond 2^±16000.
std::optional<long double> top_bits(const Rational& q) {
  if (mpz_size(q.get_num_mpz_t()) > 250 || mpz_size(q.get_den_mpz_t()) > 250) return std::nullopt;
  const numerics::TopBits n = numerics::top_bits(q.get_num_mpz_t()), d = numerics::top_bits(q.get_den_mpz_t());
  const long double v =
      scale(static_cast<long double>(n.mantissa) / static_cast<long double>(d.mantissa), n.shift - d.shift);
  return sgn(q) < 0 ? -v : v;
}

// Extended-precision values are computed where the platform has the 64-bit significand this
// analysis assumes; the enclosures built from them are used only where the thread's x87 is at its
// full precision, checked where they are used (numerics/platform.h).
constexpr bool long_lines_compiled = numerics::extended_precision_compiled;
bool long_lines_available() { return numerics::extended_precision_active(); }

// A rational as a double within a relative 2u (u = 2^-53) of it, or nothing when it is outside
// [2^-140, 2^140] (checked from its size). From the extended-precision quotient (2^-61.6) rounded
// to double (u) where available, else mpq_get_d (truncation: below 2u in the normal range).
std::optional<double> approx(const Rational& q, const std::optional<long double>& extended) {
  if (sgn(q) == 0) return 0.0;
  const long bits = static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2)) -
                    static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 2));
  if (bits < -138 || bits > 138) return std::nullopt;
  return extended ? static_cast<double>(*extended) : mpq_get_d(q.get_mpq_t());
}
// The same, where q's extended-precision value is not at hand.
std::optional<double> approx(const Rational& q) {
  return approx(q, long_lines_compiled ? top_bits(q) : std::nullopt);
}

// An image chromaticity with its approximations, computed once: doubles within a relative 2u
// (when `filtered`) and extended-precision values within 2^-61.6 (when `extended`).
struct ImagePoint {
  const Point2* exact;
  std::array<double, 2> f;
  std::array<long double, 2> l;
  bool filtered, extended;
};
ImagePoint image_point(const Point2& q) {
  ImagePoint p{&q, {0, 0}, {0, 0}, true, long_lines_compiled};
  for (int k = 0; k < 2; ++k) {
    const Rational& c = k ? q.y : q.x;
    const auto l = long_lines_compiled ? top_bits(c) : std::nullopt;
    p.extended = p.extended && l;
    p.l[k] = l.value_or(0);
    const std::optional<double> f = approx(c, l);
    p.filtered = p.filtered && f;
    p.f[k] = f.value_or(0);
  }
  return p;
}

// A line in extended precision: each coefficient within a relative 2^-61 of the same positive
// multiple of the exact line (for vertex enclosures).
struct LongLine {
  long double a, b, c;
};

// The sign of orientation(a, b, c) = (b−a)×(c−a) of exact points, filtered: from coordinates
// truncated to double (relative error below 2u each) each difference is within 3.01u of
// |b_x| + |a_x| (and so on), each product within 6.1u of (|b_x|+|a_x|)(|c_y|+|a_y|), and the last
// product and difference round by u each: 12u of the computed magnitudes covers it.
int orientation_sign(const Point2& a, const Point2& b, const Point2& c, const std::array<double, 2>& fa,
                     const std::array<double, 2>& fb, const std::array<double, 2>& fc, bool filtered) {
  if (filtered) {
    const double l = (fb[0] - fa[0]) * (fc[1] - fa[1]), r = (fb[1] - fa[1]) * (fc[0] - fa[0]);
    const double mag = (std::fabs(fb[0]) + std::fabs(fa[0])) * (std::fabs(fc[1]) + std::fabs(fa[1])) +
                       (std::fabs(fb[1]) + std::fabs(fa[1])) * (std::fabs(fc[0]) + std::fabs(fa[0]));
    const double d = l - r, bound = 12 * u * mag;
    if (d > bound) return 1;
    if (d < -bound) return -1;
  }
  return sgn(orientation(a, b, c));
}

// The image hull's vertices (extreme points, counter-clockwise): Andrew's monotone chain with the
// lexicographic order and orientations filtered (doubles within 2u decide when they differ by
// more than their error; mpq_cmp, no gcd, otherwise). Image hulls are small (a scene's colours),
// so this beats building exact-kernel points for CGAL.
std::vector<ImagePoint> image_hull_vertices(const std::vector<const Point2*>& image) {
  std::vector<ImagePoint> p;
  p.reserve(image.size());
  bool filtered = true;
  for (const Point2* q : image) {
    p.push_back(image_point(*q));
    filtered = filtered && p.back().filtered;
  }
  // x̂ within 2u|x| of x: x̂_a − x̂_b beyond 4.01u(|x̂_a| + |x̂_b|) (with the subtraction's own
  // rounding) has the sign of x_a − x_b.
  auto compare = [filtered](const ImagePoint& a, const ImagePoint& b, int k) {
    if (filtered) {
      const double d = a.f[k] - b.f[k], bound = 5 * u * (std::fabs(a.f[k]) + std::fabs(b.f[k]));
      if (d > bound) return 1;
      if (d < -bound) return -1;
    }
    return cmp(k ? a.exact->y : a.exact->x, k ? b.exact->y : b.exact->x);
  };
  auto less = [&](const ImagePoint& a, const ImagePoint& b) {
    const int x = compare(a, b, 0);
    return x ? x < 0 : compare(a, b, 1) < 0;
  };
  auto equal = [&](const ImagePoint& a, const ImagePoint& b) { return compare(a, b, 0) == 0 && compare(a, b, 1) == 0; };
  std::sort(p.begin(), p.end(), less);
  p.erase(std::unique(p.begin(), p.end(), equal), p.end());
  if (p.size() < 3) return p;
  std::vector<std::size_t> h(2 * p.size());
  std::size_t k = 0;
  auto turn = [&](std::size_t a, std::size_t b, std::size_t c) {
    return orientation_sign(*p[a].exact, *p[b].exact, *p[c].exact, p[a].f, p[b].f, p[c].f, filtered);
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn(h[k - 2], h[k - 1], i) <= 0) --k;
    h[k++] = i;
  }
  std::vector<ImagePoint> out;
  out.reserve(k - 1);
  for (std::size_t i = 0; i + 1 < k; ++i) out.push_back(p[h[i]]);
  return out;  // all collinear: the two extreme points
}

}  // namespace

// G_c's half-planes as exact integer lines and their filters, and the bounds the box needs.
struct CanonicalConstraints::Impl {
  std::vector<Line> lines;
  std::vector<ApproxLine> approx;
  std::vector<LongLine> long_lines;  // empty when not available
  bool polygon = false;  // lines[i] carries the edge from vertex i to vertex i+1 of G_c
  // The map constraint C (F ∩ C is computed): its half-planes as exact lines and approximations.
  std::vector<Line> extra_lines;
  std::vector<ApproxLine> extra_approx;
  bool extra_filtered = true, extra_empty = false;
  bool filtered = true;  // every approximation is in the filter's range
  Rational x_max, y_max;
};

CanonicalConstraints::CanonicalConstraints(const ConvexSet2& canonical) {
  if (canonical.kind == ConvexKind::empty)
    throw std::invalid_argument("feasible_set: the canonical gamut is empty");
  auto impl = std::make_shared<Impl>();
  Impl& g = *impl;
  for (const internal::HalfPlane& h : internal::half_planes(canonical)) {
    g.lines.push_back(integer_line(h));
    ApproxLine a{};
    g.filtered = g.filtered && approx_line(g.lines.back(), a);
    g.approx.push_back(a);
    const Line& l = g.lines.back();
    const auto la = top_bits(l.a.get_mpz_t()), lb = top_bits(l.b.get_mpz_t()), lc = top_bits(l.c.get_mpz_t());
    if (la && lb && lc) g.long_lines.push_back({*la, *lb, *lc});
  }
  if (!long_lines_compiled || g.long_lines.size() != g.lines.size()) g.long_lines.clear();
  g.polygon = canonical.kind == ConvexKind::polygon;
  g.x_max = canonical.vertices.front().x, g.y_max = canonical.vertices.front().y;
  for (const Point2& p : canonical.vertices) g.x_max = std::max(g.x_max, p.x), g.y_max = std::max(g.y_max, p.y);
  impl_ = std::move(impl);
}

CanonicalConstraints::CanonicalConstraints(const ConvexSet2& canonical, const ConvexSet2& map_constraint)
    : CanonicalConstraints(canonical) {
  auto impl = std::make_shared<Impl>(*impl_);
  impl->extra_empty = map_constraint.kind == ConvexKind::empty;
  for (const internal::HalfPlane& h : internal::half_planes(map_constraint)) {
    impl->extra_lines.push_back(integer_line(h));
    ApproxLine a{};
    impl->extra_filtered = impl->extra_filtered && approx_line(impl->extra_lines.back(), a) &&
                           in_filter_range(a.a) && in_filter_range(a.b) && in_filter_range(a.c);
    impl->extra_approx.push_back(a);
  }
  impl_ = std::move(impl);
}

namespace {

// One clipping run: the lines met so far (approximate always, exact on demand) and the
// predicates on vertices given as pairs of lines.
class Clipper {
 public:
  struct Vertex {
    std::size_t p, q;  // the vertex is the meet of lines p and q (not parallel)
    int w_sign;        // the sign of det[(a_p, b_p); (a_q, b_q)], the homogeneous weight
    std::size_t out;   // the line carrying the edge from this vertex to the next
    double lo[2], hi[2];  // certain bounds of its coordinates (infinite when unknown)
  };

  Clipper(std::shared_ptr<const CanonicalConstraints::Impl> g, const std::vector<ImagePoint>& qs, std::size_t lines)
      : keep_(std::move(g)), g_(*keep_), hq_(qs.size()) {
    lines_.reserve(lines);
    filtered_ = g_.filtered;
    long_ = !g_.long_lines.empty() && long_lines_available();
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
    ApproxLine a{};
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
  ApproxLine scaled_approx(std::size_t e, std::size_t k) const {
    const ApproxLine& ge = g_.approx[e];
    return {ge.a * q_approx_[k][0], ge.b * q_approx_[k][1], ge.c};
  }
  std::size_t add_scaled(std::size_t e, std::size_t k) {
    const ApproxLine a = scaled_approx(e, k);
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
  static int box_side(const ApproxLine& l, const Vertex& v) {
    const int ia = l.a > 0, ib = l.b > 0;
    const double x_hi = l.a * (ia ? v.hi[0] : v.lo[0]), y_hi = l.b * (ib ? v.hi[1] : v.lo[1]);
    const double top = x_hi + y_hi - l.c;
    if (top < -16 * u * (std::fabs(x_hi) + std::fabs(y_hi) + std::fabs(l.c))) return -1;
    const double x_lo = l.a * (ia ? v.lo[0] : v.hi[0]), y_lo = l.b * (ib ? v.lo[1] : v.hi[1]);
    const double bottom = x_lo + y_lo - l.c;
    if (bottom > 16 * u * (std::fabs(x_lo) + std::fabs(y_lo) + std::fabs(l.c))) return 1;
    return 0;
  }

  // True when every vertex of the cycle lies strictly inside the half-plane a·x + b·y <= c (then
  // clipping by it changes nothing), decided from the vertices' boxes.
  bool all_inside(const ApproxLine& l, const std::vector<Vertex>& cycle) const {
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
      const ApproxLine &p = lines_[i].approx, &q = lines_[j].approx;
      const double l = p.a * q.b, r = q.a * p.b;
      const double w = l - r, bound = 16 * u * (std::fabs(l) + std::fabs(r));
      if (w > bound) return 1;
      if (w < -bound) return -1;
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
  const ApproxLine& approximate(std::size_t h) const { return lines_[h].approx; }

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
    const ApproxLine &p = lines_[v.p].approx, &q = lines_[v.q].approx;
    auto det = [](double a, double d, double b, double c) {  // a·d − b·c
      const double l = a * d, r = b * c;
      return Enclosure{l - r, Enclosure::round_up(16 * u * (std::fabs(l) + std::fabs(r)))};
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
      const ApproxLine& l = lines_[h].approx;
      const double x = l.a * (*fm)[0], y = l.b * (*fm)[1];
      const double s = x + y - l.c, bound = 16 * u * (std::fabs(x) + std::fabs(y) + std::fabs(l.c));
      if (s > bound) return 1;
      if (s < -bound) return -1;
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
    ApproxLine approx;
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

  static bool in_range(const ApproxLine& a) { return in_filter_range(a.a) && in_filter_range(a.b) && in_filter_range(a.c); }

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
      const ApproxLine &p = lines_[pi].approx, &q = lines_[qi].approx, &h = lines_[hi].approx;
      const double x1 = p.c * q.b, x2 = q.c * p.b, y1 = p.a * q.c, y2 = q.a * p.c, w1 = p.a * q.b, w2 = q.a * p.b;
      const double s = h.a * (x1 - x2) + h.b * (y1 - y2) - h.c * (w1 - w2);
      const double mag = std::fabs(h.a) * (std::fabs(x1) + std::fabs(x2)) +
                         std::fabs(h.b) * (std::fabs(y1) + std::fabs(y2)) +
                         std::fabs(h.c) * (std::fabs(w1) + std::fabs(w2));
      const double bound = 32 * u * mag;
      if (s > bound) return 1;
      if (s < -bound) return -1;
      if (mag == 0) return 0;  // every term has an exactly zero factor (no underflow in range)
    }
    const Line &p = exact(pi), &q = exact(qi), &h = exact(hi);
    return sgn(mpz_class(h.a * (p.c * q.b - q.c * p.b) + h.b * (p.a * q.c - q.a * p.c) -
                         h.c * (p.a * q.b - q.a * p.b)));
  }

  std::shared_ptr<const CanonicalConstraints::Impl> keep_;
  const CanonicalConstraints::Impl& g_;
  std::vector<const Point2*> qs_;  // the image hull's vertices (owned by the caller or State)
  std::vector<std::optional<HomogeneousPoint>> hq_;
  std::vector<std::array<double, 2>> q_approx_;
  std::vector<std::array<long double, 2>> q_long_;
  bool long_ = false;
  std::vector<Entry> lines_;
  std::deque<std::optional<Line>> exact_;  // exact lines, built on demand (index: line)
  bool filtered_ = true;
};

using Vertex = Clipper::Vertex;

// Sutherland–Hodgman against line `hi`, tracking each output vertex's outgoing line. `out` and
// `s` are reused buffers.
void clip(Clipper& c, const std::vector<Vertex>& cycle, std::size_t hi, std::vector<Vertex>& out,
          std::vector<int>& s) {
  const std::size_t n = cycle.size();
  s.resize(n);
  out.clear();
  bool all_inside = true;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = c.side(hi, cycle[i]);
    all_inside = all_inside && s[i] <= 0;
  }
  if (all_inside) {
    out = cycle;
    return;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const std::size_t edge = cycle[i].out;
    if (s[i] <= 0) {
      Vertex v = cycle[i];
      // Leaving the half-plane from a point on its line: the boundary follows h from here.
      if (s[i] == 0 && s[j] > 0) v.out = hi;
      out.push_back(v);
    }
    if (s[i] * s[j] < 0)  // a strict crossing: exiting continues along h, entering along the edge
      out.push_back(c.vertex(edge, hi, s[i] < 0 ? hi : edge));
  }
}

// What clip_convex did: how many lines it took, and whether the cycle is still strictly convex.
struct ConvexClip {
  std::size_t taken;
  bool strictly_convex;
};

// Clips a strictly convex counter-clockwise cycle (>= 3 vertices) by lines 0, 1, … of a family
// (add_line(e) adds line e to the Clipper and returns its index), one after another, with the
// result of clip() applied line after line: the same vertices, each with the same outgoing line,
// from another start. It stops early, leaving the rest to clip(), once the cycle degenerates
// (fewer than 3 vertices: a segment or a point) or empties, or when it finds the cycle not convex.
//
// Why it is fast (docs/performance.md, "Many-vertex canonical gamuts (issue 13)"): the vertices
// strictly outside a line form one arc around the vertex extreme in the direction of the line's
// outward normal n, and there are none when that vertex is not outside. Vertex v is extreme iff
// n lies between the normals of the edges into and out of v: weight_sign(in, h) >= 0 >=
// weight_sign(out, h), an exact test (every vertex passes for a line with a zero normal, and
// then every vertex has the same side). When n turns counter-clockwise by less than π from line
// to line, as along a convex polygon's edges (G_c ⊘ q, the map constraint), the extreme vertex
// moves forward: a pointer advances while the edge out of it comes before n, and the test
// confirms where it stops (a scan of the cycle when it does not: lines in another order, the
// first line). Each line then costs its one side test, plus the arc it removes and the at most
// two crossing vertices it inserts, in a linked cycle: O(|cycle| + lines) for a whole polygon
// instead of clip()'s O(|cycle|) per line.
template <class AddLine>
ConvexClip clip_convex(Clipper& c, std::vector<Vertex>& cycle, std::size_t count, AddLine add_line) {
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<Vertex> node = std::move(cycle);
  const std::size_t n = node.size();
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  std::size_t live = n, ptr = 0, free_list = none;
  auto finish = [&](std::size_t taken, bool strict) {
    cycle.clear();
    cycle.reserve(live);
    std::size_t i = ptr;
    do cycle.push_back(node[i]), i = next[i];
    while (i != ptr);
    return ConvexClip{taken, strict};
  };
  auto extreme = [&](std::size_t i, std::size_t h) {
    return c.weight_sign(node[prev[i]].out, h) >= 0 && c.weight_sign(node[i].out, h) <= 0;
  };
  auto link = [&](std::size_t from, std::size_t to) { next[from] = to, prev[to] = from; };
  auto allocate = [&](const Vertex& v) {
    if (free_list == none) {
      node.push_back(v), prev.push_back(none), next.push_back(none);
      return node.size() - 1;
    }
    const std::size_t i = free_list;
    free_list = next[i];
    node[i] = v;
    return i;
  };
  for (std::size_t e = 0; e < count; ++e) {
    const std::size_t h = add_line(e);
    // The vertex extreme for h: forward from the last one, else found by a scan.
    for (std::size_t steps = 0; steps < live && c.weight_sign(node[ptr].out, h) > 0; ++steps) ptr = next[ptr];
    if (!extreme(ptr, h)) {
      std::size_t k = 0;
      while (k < live && !extreme(ptr, h)) ptr = next[ptr], ++k;
      if (k == live) {  // no extreme vertex: not convex after all, clip() takes over
        c.drop_last();
        return finish(e, false);
      }
    }
    if (c.side(h, node[ptr]) <= 0) {  // no vertex outside: clip() would leave the cycle as it is
      c.drop_last();
      continue;
    }
    // The arc outside h: back to a, the last vertex before it not outside, on to b, the first after.
    std::size_t a = prev[ptr], b = next[ptr], removed = 1;
    int sa = 0, sb = 0;
    while (a != ptr && (sa = c.side(h, node[a])) > 0) a = prev[a], ++removed;
    if (a == ptr) {  // every vertex outside: F is empty
      cycle.clear();
      return {e + 1, false};
    }
    while ((sb = c.side(h, node[b])) > 0) b = next[b], ++removed;  // stops at a at the latest
    const std::size_t t = prev[b], edge_a = node[a].out, edge_t = node[t].out;
    // The arc's nodes are free for the crossing vertices (as a list through `next`).
    next[t] = free_list, free_list = next[a];
    live -= removed;
    // As clip() does: leaving h's half-plane from a point on h, the boundary follows h; a strict
    // crossing out of it continues along h, one back into it along the crossed edge.
    std::size_t last = a;
    if (sa == 0) node[a].out = h;
    auto append = [&](const Vertex& v) {
      const std::size_t i = allocate(v);
      link(last, i);
      last = i;
      ++live;
    };
    if (sa < 0) append(c.vertex(edge_a, h, h));
    ptr = last;  // its outgoing edge lies on h: extreme for h
    if (sb < 0) append(c.vertex(edge_t, h, edge_t));
    link(last, b);
    if (live < 3) return finish(e + 1, false);  // a segment or a point: clip() from here
  }
  return finish(count, true);
}

// Drop repeated and collinear vertices. Repeats: v equals w iff v lies on both lines meeting in
// w. Collinear: consecutive p, q, r with p != q are collinear iff r lies on the line carrying the
// edge p → q (p.out), so a repeat hands its outgoing line to the vertex it merges into.
std::vector<Vertex> reduced(Clipper& c, const std::vector<Vertex>& cycle) {
  std::vector<Vertex> v;
  v.reserve(cycle.size());
  for (const Vertex& p : cycle) {
    if (!v.empty() && c.same_point(v.back(), p))
      v.back().out = p.out;
    else
      v.push_back(p);
  }
  while (v.size() > 1 && c.same_point(v.back(), v.front())) v.pop_back();
  if (v.size() < 3) return v;
  std::vector<Vertex> out;
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    if (c.side(v[(i + n - 1) % n].out, v[(i + 1) % n]) != 0) out.push_back(v[i]);
  // All collinear: keep the cycle for canonical_convex_set to take the extreme points of.
  return out.size() >= 3 ? out : v;
}

}  // namespace

struct FeasiblePolygon::State {
  std::vector<Point2> owned;        // the image hull's vertices, when the caller's may not outlive F
  std::optional<Clipper> clipper;   // absent when F is empty before clipping ends
  std::vector<Vertex> cycle;        // reduced; strictly convex when enclosed
  ConvexKind kind = ConvexKind::empty;
  bool strictly_convex = false;
  std::vector<EnclosedVertex> vertices;
  std::optional<std::vector<LongEnclosedVertex>> long_vertices;  // built on first use
  std::vector<ApproximateLine> edges;
  std::optional<ConvexSet2> exact;
};

// Builds FeasiblePolygon (a friend of it and of CanonicalConstraints).
struct FeasiblePolygonBuilder {
  static FeasiblePolygon build(const CanonicalConstraints& canonical, const std::vector<const Point2*>& image,
                              bool copy_image, bool linear = true);
};

FeasiblePolygon internal::feasible_polygon(const CanonicalConstraints& canonical, const std::vector<Point2>& image,
                                           Clipping route) {
  std::vector<const Point2*> pointers;
  pointers.reserve(image.size());
  for (const Point2& q : image) pointers.push_back(&q);
  return FeasiblePolygonBuilder::build(canonical, pointers, true, route == Clipping::convex_pass);
}

FeasiblePolygon feasible_polygon(const CanonicalConstraints& canonical, const std::vector<Point2>& image) {
  return internal::feasible_polygon(canonical, image, internal::Clipping::convex_pass);
}

FeasiblePolygon feasible_polygon(const CanonicalConstraints& canonical, const std::vector<const Point2*>& image) {
  return FeasiblePolygonBuilder::build(canonical, image, false);
}

FeasiblePolygon FeasiblePolygonBuilder::build(const CanonicalConstraints& canonical,
                                             const std::vector<const Point2*>& image, bool copy_image,
                                             bool linear) {
  if (image.empty()) throw std::invalid_argument("feasible_set: no image chromaticities");
  for (const Point2* q : image)
    if (sgn(q->x) < 0 || sgn(q->y) < 0)
      throw std::invalid_argument("feasible_set: an image chromaticity is negative");
  const CanonicalConstraints::Impl& g = *canonical.impl_;

  FeasiblePolygon result;
  result.state_ = std::make_shared<FeasiblePolygon::State>();
  FeasiblePolygon::State& st = *result.state_;
  // Only the image hull's vertices constrain F (interior colours add implied constraints).
  std::vector<ImagePoint> qs = image_hull_vertices(image);
  if (copy_image) {  // F may outlive the caller's image: keep its hull's vertices
    st.owned.reserve(qs.size());
    for (ImagePoint& q : qs) st.owned.push_back(*q.exact), q.exact = &st.owned.back();
  }

  auto max_of = [](const std::vector<ImagePoint>& ps, Rational Point2::*c) {
    const Rational* m = &(ps.front().exact->*c);
    for (const ImagePoint& p : ps) m = std::max(m, &(p.exact->*c), [](auto a, auto b) { return *a < *b; });
    return *m;
  };
  const Rational q1 = max_of(qs, &Point2::x), q2 = max_of(qs, &Point2::y);
  if (sgn(q1) == 0)
    throw UnboundedFeasibleSet("every image colour has r = 0: the map's red component is "
                               "unconstrained and the feasible set is unbounded");
  if (sgn(q2) == 0)
    throw UnboundedFeasibleSet("every image colour has g = 0: the map's green component is "
                               "unconstrained and the feasible set is unbounded");

  if (g.extra_empty) {  // F ∩ ∅
    st.exact = ConvexSet2{};
    return result;
  }
  const std::size_t k_count = qs.size(), m = g.lines.size();
  // The clipping starts from G_c ⊘ q for an image vertex q > 0 when G_c is a polygon: its
  // vertices are the meets of consecutive scaled edges (a positive diagonal scaling keeps the
  // order counter-clockwise), which saves q's clips and any box.
  std::size_t first = k_count;
  if (g.polygon)
    for (std::size_t k = 0; k < k_count && first == k_count; ++k)
      if (sgn(qs[k].exact->x) > 0 && sgn(qs[k].exact->y) > 0) first = k;
  Clipper& c = st.clipper.emplace(canonical.impl_, qs, m * (k_count + 1) + 4 + g.extra_lines.size());
  std::vector<Vertex> cycle;
  if (first < k_count) {
    std::vector<std::size_t> lines(m);
    for (std::size_t e = 0; e < m; ++e) lines[e] = c.add_scaled(e, first);
    for (std::size_t e = 0; e < m; ++e) cycle.push_back(c.vertex(lines[(e + m - 1) % m], lines[e], lines[e]));
    // Consecutive parallel edges (a G_c given with collinear vertices, not in canonical form)
    // have no meet: start from the box instead, which needs no such assumption.
    for (const Vertex& v : cycle)
      if (v.w_sign == 0) first = k_count;
    if (first == k_count) cycle.clear();
  }
  if (first == k_count) {
    // The box [0, X/Q1] × [0, Y/Q2] contains F: for q with q1 = Q1 > 0, m1·Q1 is the first
    // coordinate of a point of G_c, so 0 <= m1·Q1 <= X (likewise m2). Clip it to F.
    const std::size_t bottom = c.add_exact(integer_line({0, -1, 0}));
    const std::size_t right = c.add_exact(integer_line({1, 0, Rational(g.x_max / q1)}));
    const std::size_t top = c.add_exact(integer_line({0, 1, Rational(g.y_max / q2)}));
    const std::size_t left = c.add_exact(integer_line({-1, 0, 0}));
    cycle = {c.vertex(left, bottom, bottom), c.vertex(bottom, right, right), c.vertex(right, top, top),
             c.vertex(top, left, left)};
  }
  std::vector<Vertex> next;
  std::vector<int> sides;
  // While the cycle is strictly convex, each family of lines (one image vertex's, the map
  // constraint's) is clipped by clip_convex; clip() takes the lines left once it degenerates, or
  // all of them on the route kept for comparison (internal/feasible_polygon_route.h).
  bool strict = linear && cycle.size() >= 3 && c.strictly_convex(cycle);
  auto clip_family = [&](std::size_t count, auto approximation, auto add_line) {
    std::size_t e = 0;
    if (strict) {
      const ConvexClip r = clip_convex(c, cycle, count, add_line);
      e = r.taken, strict = r.strictly_convex;
      if (cycle.empty()) return false;
    }
    for (; e < count; ++e) {
      // A line every vertex lies strictly inside of cannot cut: it is not even added.
      if (c.all_inside(approximation(e), cycle)) continue;
      clip(c, cycle, add_line(e), next, sides);
      cycle.swap(next);
      if (cycle.empty()) return false;
    }
    return true;
  };
  bool empty = false;
  for (std::size_t k = 0; k < k_count && !empty; ++k)
    if (k != first)
      empty = !clip_family(
          m, [&](std::size_t e) { return c.scaled_approx(e, k); }, [&](std::size_t e) { return c.add_scaled(e, k); });
  if (!empty)
    empty = !clip_family(
        g.extra_lines.size(), [&](std::size_t j) { return g.extra_approx[j]; },
        [&](std::size_t j) { return c.add_fixed(j); });
  if (empty) {
    st.exact = ConvexSet2{};
    return result;
  }
  st.cycle = reduced(c, cycle);
  st.strictly_convex = st.cycle.size() >= 3 && c.strictly_convex(st.cycle);
  if (!st.strictly_convex) {  // degenerate (or collinear leftovers): the exact set decides the kind
    st.kind = result.exact().kind;
    return result;
  }
  st.kind = ConvexKind::polygon;
  if (c.filtered()) {
    bool ok = true;
    for (const Vertex& v : st.cycle) {
      const EnclosedVertex e = c.enclose(v);
      ok = ok && std::isfinite(e.x.rad) && std::isfinite(e.y.rad);
      st.vertices.push_back(e);
      const ApproxLine& l = c.approximate(v.out);
      st.edges.push_back({l.a, l.b, l.c});
    }
    if (!ok) st.vertices.clear(), st.edges.clear();
  }
  return result;
}

// A default-constructed FeasiblePolygon is the empty set.
FeasiblePolygon::State& FeasiblePolygon::state() const {
  static State empty = [] {  // shared by every default object: nothing in it is ever built later
    State e;
    e.exact = ConvexSet2{};
    e.long_vertices.emplace();
    return e;
  }();
  return state_ ? *state_ : empty;
}

ConvexKind FeasiblePolygon::kind() const { return state().kind; }
bool FeasiblePolygon::enclosed() const { return !state().vertices.empty(); }
const std::vector<EnclosedVertex>& FeasiblePolygon::vertices() const { return state().vertices; }
const std::vector<ApproximateLine>& FeasiblePolygon::edges() const { return state().edges; }
const std::vector<LongEnclosedVertex>& FeasiblePolygon::extended_vertices() const {
  State& st = state();
  if (!st.long_vertices) {
    st.long_vertices.emplace();
    if (long_lines_available() && !st.vertices.empty())
      for (const Vertex& v : st.cycle) st.long_vertices->push_back(st.clipper->enclose_exactly(v));
  }
  return *st.long_vertices;
}

const ConvexSet2& FeasiblePolygon::exact() const {
  State& st = state();
  if (st.exact) return *st.exact;
  Clipper& c = *st.clipper;
  std::vector<Point2> points;
  points.reserve(st.cycle.size());
  for (const Vertex& p : st.cycle) points.push_back(c.point(p));
  if (!st.strictly_convex) return st.exact.emplace(canonical_convex_set(std::move(points)));
  // Already strictly convex and counter-clockwise: only the canonical start is left to do.
  ConvexSet2 F;
  F.kind = ConvexKind::polygon;
  std::rotate(points.begin(), std::min_element(points.begin(), points.end()), points.end());
  F.vertices = std::move(points);
  return st.exact.emplace(std::move(F));
}

bool FeasiblePolygon::contains(const Point2& m) const {
  State& st = state();
  if (st.kind == ConvexKind::empty) return false;
  if (!st.strictly_convex) return gmcc::contains(exact(), m);
  // F is the intersection of the half-planes carrying its edges.
  std::optional<std::array<double, 2>> fm;
  const auto x = approx(m.x), y = approx(m.y);
  if (x && y && in_filter_range(*x) && in_filter_range(*y)) fm = std::array<double, 2>{*x, *y};
  for (const Vertex& v : st.cycle)
    if (st.clipper->side_of_point(v.out, m, fm) > 0) return false;
  return true;
}

ConvexSet2 feasible_set(const CanonicalConstraints& canonical, const std::vector<Point2>& image) {
  return feasible_polygon(canonical, image).exact();
}

ConvexSet2 feasible_set(const ConvexSet2& canonical, const std::vector<Point2>& image) {
  return feasible_set(CanonicalConstraints(canonical), image);
}

}  // namespace gmcc
