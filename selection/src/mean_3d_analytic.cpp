#include <gmcc/selection/mean_3d_analytic.h>

#include <gmcc/numerics/dw_atan.h>
#include <gmcc/numerics/dw_rounding.h>

#include "internal/closed_form.h"
#include "internal/dw_rational.h"
#include "internal/interval.h"
#include "internal/ld_interval.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

namespace gmcc {
namespace {
using internal::LDInterval;
using internal::Interval;
using numerics::DWEnclosure;
using Vec3 = std::array<Rational, 3>;

// The precision reported by the double-word stage: a double-word significand.
constexpr unsigned double_word_bits = 106;

Vec3 lift(const Point2& p) { return {p.x, p.y, Rational(1)}; }
Vec3 cross(const Vec3& u, const Vec3& v) {
  return {Rational(u[1] * v[2] - u[2] * v[1]), Rational(u[2] * v[0] - u[0] * v[2]),
          Rational(u[0] * v[1] - u[1] * v[0])};
}
Rational dot(const Vec3& u, const Vec3& v) {
  return Rational(u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
}

// floor(log2 |x|) for x != 0, from the sizes of numerator and denominator (±1).
long log2_size(const Rational& x) {
  return static_cast<long>(mpz_sizeinbase(x.get_num_mpz_t(), 2)) -
         static_cast<long>(mpz_sizeinbase(x.get_den_mpz_t(), 2));
}

// Bits the closed form needs: the edge terms are O(ε) and τ is O(ε²) for a polygon of angular
// width ε (docs/derivations.md §1.6), so 2·log2(1/ε) bits cancel; add 53 for the answer and 40
// guard bits.
unsigned automatic_precision(const std::vector<Point2>& v) {
  Rational width2 = 0;
  for (const Point2& p : v)
    width2 = std::max(width2, Rational((p.x - v[0].x) * (p.x - v[0].x) +
                                       (p.y - v[0].y) * (p.y - v[0].y)));
  const Rational norm2 = 1 + v[0].x * v[0].x + v[0].y * v[0].y;
  const long cancel = std::max(0L, log2_size(norm2) - log2_size(width2) + 2);
  return static_cast<unsigned>(53 + 40 + cancel);
}

// The map's direction (τ1/τ3, τ2/τ3) for a polygon, the bisector's perspective for a segment, in
// interval kind I from exact products: c_i = p_i × p_{i+1}, |c_i|² and p_i·p_{i+1} formed exactly,
// then enclosed by `make`. The sum is closed_form.h's, as for every other kind.
template <class I, class Make>
std::array<I, 2> direction_map(const ConvexSet2& F, Make make) {
  const auto& v = F.vertices;
  if (F.kind == ConvexKind::segment) {
    // û1 + û2: the bisector of the end rays (docs/derivations.md §1.5).
    std::array<I, 3> dir{make(Rational(0)), make(Rational(0)), make(Rational(0))};
    for (const Point2& p : v) {
      const Vec3 u = lift(p);
      const I inv_norm = make(Rational(1)) / sqrt(make(dot(u, u)));
      for (int k = 0; k < 3; ++k) dir[k] = dir[k] + inv_norm * make(u[k]);
    }
    return internal::tau_direction(dir);
  }
  const auto tau = internal::tau_sum<I>(v.size(), make(Rational(0)), [&](std::size_t i) {
    const Vec3 p = lift(v[i]), q = lift(v[(i + 1) % v.size()]);
    const Vec3 c = cross(p, q);  // exact
    return internal::TauTerm<I>{{make(c[0]), make(c[1]), make(c[2])},
                                internal::theta_over_norm(sqrt(make(dot(c, c))), make(dot(p, q)))};
  });
  return internal::tau_direction(*tau);
}

// The same map from enclosures of the vertices (c_i and p_i·p_{i+1} in interval arithmetic:
// cheap, with no exact rational products, but on thin polygons too wide to be kept). `make`
// encloses an exact rational.
template <class I, class Make>
std::array<I, 2> direction_map_from_vertices(const ConvexSet2& F, Make make) {
  const auto& v = F.vertices;
  const std::size_t n = v.size();
  std::vector<I> a, b;
  a.reserve(n), b.reserve(n);
  for (std::size_t i = 0; i < n; ++i) a.push_back(make(v[i].x)), b.push_back(make(v[i].y));
  const I one = make(Rational(1));
  if (F.kind == ConvexKind::segment) {
    std::array<I, 3> dir{make(Rational(0)), make(Rational(0)), make(Rational(0))};
    for (std::size_t i = 0; i < 2; ++i) {
      const I inv_norm = one / sqrt(sqr(a[i]) + sqr(b[i]) + one);
      dir = {dir[0] + inv_norm * a[i], dir[1] + inv_norm * b[i], dir[2] + inv_norm};
    }
    return internal::tau_direction(dir);
  }
  const auto tau = internal::tau_sum<I>(n, make(Rational(0)), [&](std::size_t i) {
    const std::size_t j = (i + 1) % n;
    const std::array<I, 3> c = internal::cross_from_vertices(a[i], b[i], a[j], b[j]);
    return internal::TauTerm<I>{c, internal::theta_over_norm(c, a[i] * a[j] + b[i] * b[j] + one)};
  });
  return internal::tau_direction(*tau);
}

// In x87 extended-precision intervals.
std::array<LDInterval, 2> direction_map_fast(const ConvexSet2& F) {
  return direction_map_from_vertices<LDInterval>(F, [](const Rational& q) { return internal::enclose_ld(q); });
}

// The same with each edge vector e_i = v_{i+1} − v_i enclosed from its exact value (one integer
// cross-multiplication per coordinate, no gcd), and c_i = p_i × p_{i+1} = p_i × (e_i, 0)
// = (−e_y, e_x, a_i·e_y − b_i·e_x) formed from it: no cancellation in c_i, so on a polygon of
// width w the enclosure loses log2(1/w) bits instead of 2·log2(1/w). Polygons only. `make`
// encloses a rational, `quotient` an integer quotient num/den (den > 0).
template <class I, class Make, class Quotient>
std::array<I, 2> direction_map_edges(const ConvexSet2& F, Make make, Quotient quotient) {
  const auto& v = F.vertices;
  const std::size_t n = v.size();
  auto difference = [&quotient](const Rational& p, const Rational& q) {  // p − q
    const mpz_class num = p.get_num() * q.get_den() - q.get_num() * p.get_den();
    const mpz_class den = p.get_den() * q.get_den();
    return quotient(num.get_mpz_t(), den.get_mpz_t());
  };
  const I one = make(Rational(1));
  I a_i = make(v[0].x), b_i = make(v[0].y);
  const auto tau = internal::tau_sum<I>(n, make(Rational(0)), [&](std::size_t i) {
    const std::size_t j = (i + 1) % n;
    const I a_j = make(v[j].x), b_j = make(v[j].y);
    const std::array<I, 3> c =
        internal::cross_from_edge(a_i, b_i, difference(v[j].x, v[i].x), difference(v[j].y, v[i].y));
    const internal::TauTerm<I> t{c, internal::theta_over_norm(c, a_i * a_j + b_i * b_j + one)};
    a_i = a_j, b_i = b_j;
    return t;
  });
  return internal::tau_direction(*tau);
}

std::array<LDInterval, 2> direction_map_fast_edges(const ConvexSet2& F) {
  return direction_map_edges<LDInterval>(
      F, [](const Rational& q) { return internal::enclose_ld(q); },
      [](mpz_srcptr num, mpz_srcptr den) { return internal::enclose_ld(num, den); });
}

// In double-word enclosures (docs/math.md "The double-word stage"): from vertex enclosures, and
// from exactly formed edges.
GMCC_DW_FMA_CLONES std::array<DWEnclosure, 2> direction_map_dw(const ConvexSet2& F) {
  return direction_map_from_vertices<DWEnclosure>(F, [](const Rational& q) { return internal::enclose_dw(q); });
}
GMCC_DW_FMA_CLONES std::array<DWEnclosure, 2> direction_map_dw_edges(const ConvexSet2& F) {
  return direction_map_edges<DWEnclosure>(
      F, [](const Rational& q) { return internal::enclose_dw(q); },
      [](mpz_srcptr num, mpz_srcptr den) { return internal::enclose_dw(num, den); });
}

// The double-word stage's answer when both components' enclosures round to one double each
// (numerics::round_to_double): that double (the correctly rounded map), the enclosure's bound
// and outward ends, at the double-word precision.
bool report_if_rounded(MapEstimate& e, const std::array<DWEnclosure, 2>& m) {
  const std::optional<numerics::DWRounding> r0 = numerics::round_to_double(m[0]);
  if (!r0) return false;
  const std::optional<numerics::DWRounding> r1 = numerics::round_to_double(m[1]);
  if (!r1) return false;
  e.precision_bits = double_word_bits;
  for (int k = 0; k < 2; ++k) {
    const numerics::DWRounding& r = k == 0 ? *r0 : *r1;
    e.map[k] = r.value;
    e.error_bounds[k] = r.bound;
    e.correctly_rounded[k] = true;
    (*e.enclosure)[k] = {r.lo, r.hi};
  }
  e.error_bound = std::max(e.error_bounds[0], e.error_bounds[1]);
  return true;
}

// The double that every point of an extended-precision enclosure rounds to, if there is one
// (the ends are long doubles: each conversion rounds once, to nearest).
std::optional<double> single_rounding(const LDInterval& x) {
  if (!std::isfinite(x.lo) || !std::isfinite(x.hi)) return std::nullopt;
  const double a = static_cast<double>(x.lo), b = static_cast<double>(x.hi);
  if (a != b || !std::isfinite(a)) return std::nullopt;
  return a;
}

// Component k from an extended-precision enclosure x that rounds to one double: the double,
// the farther end's distance from it (rounded up), the enclosure rounded outward.
void report(MapEstimate& e, int k, const LDInterval& x, double value) {
  const long double reach = std::max(value - x.lo, x.hi - value);
  e.map[k] = value;
  e.error_bounds[k] = std::nextafter(static_cast<double>(LDInterval::up(reach)), INFINITY);
  e.correctly_rounded[k] = true;
  double lo = static_cast<double>(x.lo), hi = static_cast<double>(x.hi);
  if (lo > x.lo) lo = std::nextafter(lo, -INFINITY);
  if (hi < x.hi) hi = std::nextafter(hi, INFINITY);
  (*e.enclosure)[k] = {lo, hi};
}

// Both components from certified MPFI enclosures at `bits`: each reported as one double
// (correctly rounded when its enclosure allows), with its bound and outward enclosure.
void report(MapEstimate& e, const std::array<Interval, 2>& m, unsigned bits) {
  e.precision_bits = bits;
  for (int k = 0; k < 2; ++k) {
    const auto [lo, hi] = internal::outward_doubles(m[k]);
    (*e.enclosure)[k] = {lo, hi};
    const internal::RoundedEnclosure r = internal::round_to_double(m[k]);
    e.map[k] = r.value;
    e.error_bounds[k] = r.bound;
    e.correctly_rounded[k] = r.correctly_rounded;
  }
  e.error_bound = std::max(e.error_bounds[0], e.error_bounds[1]);
}

// The fast path's answer when both components' enclosures round to one double each.
bool report_if_rounded(MapEstimate& e, const std::array<LDInterval, 2>& m) {
  const std::optional<double> r0 = single_rounding(m[0]), r1 = single_rounding(m[1]);
  if (!r0 || !r1) return false;
  e.precision_bits = 64;  // the x87 extended significand
  report(e, 0, m[0], *r0);
  report(e, 1, m[1], *r1);
  e.error_bound = std::max(e.error_bounds[0], e.error_bounds[1]);
  return true;
}

// Correct rounding: the precision doubles until each enclosure lies inside one rounding
// interval of the doubles, up to this many bits (or 4× the starting precision, if larger).
// Only a map within about 2^-8000 of a midpoint between two doubles — in practice one exactly
// at a midpoint, such as a symmetric segment's — reaches the cap.
constexpr unsigned rounding_cap_bits = 8192;
// The precision of the stage between the x87 fast path and the exact-product MPFI loop: 80 bits,
// and more on polygons of many vertices. From vertex enclosures, each edge's c_i loses about
// log2(n) bits to cancellation (its edges are about 1/n of F's size), so the enclosure's width
// grows like n·2^-bits: about 2^-62 of the map at n = 10^4 and 80 bits. 73 + log2(n) bits keep it
// near 2^-63 (a rounding boundary inside about once in 2^10 calls) instead of letting a
// 10^5–10^6-vertex F (a many-vertex canonical gamut, docs/performance-history.md "Many-vertex canonical
// gamuts (issue 13)") fall through to the exact products, 5–10× slower; below 128 vertices it is
// 80 as before. MPFR's cost is the same up to 128 bits (two limbs).
unsigned middle_stage_bits(std::size_t n) {
  unsigned log2n = 0;
  while ((std::size_t(1) << log2n) < n) ++log2n;
  return std::max(80u, 73 + log2n);
}

// The stages before the exact-product MPFI loop, for an automatic precision: true when one of
// them decided the rounding and filled e.
bool decided_early(MapEstimate& e, const ConvexSet2& F) {
  // First stage: double-word enclosures (about 2^-100 relative per operation, every bound
  // proven), kept only when each component's enclosure rounds to a single double, from vertex
  // enclosures and then, for thin polygons, from exactly formed edges. The reported bound and
  // precision are this stage's (docs/cli.md "JSON output"); the map is the correctly rounded one
  // whichever stage decides it.
  // Its error-free transformations need doubles evaluated as doubles (FLT_EVAL_METHOD 0: SSE2,
  // not the x87's double rounding).
  if (FLT_EVAL_METHOD == 0) {
    if (report_if_rounded(e, direction_map_dw(F))) return true;
    if (F.kind == ConvexKind::polygon && report_if_rounded(e, direction_map_dw_edges(F))) return true;
  }
  // Then rigorous extended-precision intervals, kept only when each component's enclosure
  // rounds to a single double (which is then the correctly rounded map).
  if (numerics::extended_precision_active()) {
    if (report_if_rounded(e, direction_map_fast(F))) return true;
    // Small or thin polygons: the same arithmetic from exactly formed edge vectors.
    if (F.kind == ConvexKind::polygon && report_if_rounded(e, direction_map_fast_edges(F))) return true;
    // The x87 enclosures are about an ulp wide (2^-50 … 2^-52 relative on feasible sets of
    // the synthetic experiment's size), so a rounding boundary usually falls inside. MPFI from
    // vertex enclosures at 80 bits (~2^-70 wide: a boundary falls inside about once in 2^17
    // calls), before the exact products, whose gcds dominate on long rationals.
    const unsigned bits = middle_stage_bits(F.vertices.size());
    const auto m = direction_map_from_vertices<Interval>(F, [bits](const Rational& q) { return Interval(q, bits); });
    if (internal::single_rounding(m[0]) && internal::single_rounding(m[1])) {
      report(e, m, bits);
      return true;
    }
  }
  return false;
}

}  // namespace

MapEstimate mean_3d_analytic(const ConvexSet2& F, const AnalyticOptions& options) {
  if (F.kind == ConvexKind::empty) throw std::invalid_argument("mean_3d: empty feasible set");
  // A point is its own mean, exactly.
  MapEstimate e = F.kind == ConvexKind::point ? exact_map_estimate("mean_3d", F.vertices[0])
                                              : MapEstimate{};
  e.rule = "mean_3d";
  e.method = "analytic";
  if (F.kind == ConvexKind::point) return e;
  e.enclosure.emplace();

  if (options.precision_bits == 0 && decided_early(e, F)) return e;
  // MPFI: precision chosen from the polygon's size, then doubled until each component's
  // certified enclosure rounds to one double (a forced precision is used once, as given).
  // Far from the origin τ3 is small against its terms; too few bits leave it straddling 0 (or
  // barely above it) and the quotients unbounded or beyond the doubles (found by
  // fuzz/fuzz_geometry and fuzz/fuzz_select): the automatic precision doubles past that, up to
  // max_bits; a forced one too low says so instead of reporting NaN or infinity.
  constexpr unsigned max_bits = 1u << 20;
  const bool forced = options.precision_bits != 0;
  unsigned bits = forced ? options.precision_bits : automatic_precision(F.vertices);
  const unsigned cap = std::max(rounding_cap_bits, 4 * bits);
  for (;; bits *= 2) {
    const auto m = direction_map<Interval>(F, [bits](const Rational& q) { return Interval(q, bits); });
    bool bounded = true, rounded = true, beyond = false;
    for (int k = 0; k < 2; ++k) {
      const auto [lo, hi] = internal::bounded(m[k]) ? internal::outward_doubles(m[k])
                                                    : std::pair<double, double>(NAN, NAN);
      bounded = bounded && std::isfinite(lo) && std::isfinite(hi);
      rounded = rounded && internal::single_rounding(m[k]).has_value();
      // A finite enclosure wholly beyond the largest double: no precision gives a double map.
      beyond = beyond || internal::beyond_doubles(m[k]);
    }
    if (beyond) {
      e.precision_bits = bits;
      e.valid = false;
      e.enclosure.reset();
      e.note = "the 3-D mean lies beyond the range of doubles (above 1.8e308): it has no map to "
               "report";
      return e;
    }
    if (!forced && !(bounded && rounded) && bits < (bounded ? cap : max_bits)) continue;
    e.precision_bits = bits;
    if (!bounded) {
      e.valid = false;
      e.enclosure.reset();
      e.note = "the closed form's enclosure at " + std::to_string(bits) +
               " bits is too wide to give a map (its third component is not separated "
               "from 0): raise the precision, or leave it automatic";
      return e;
    }
    report(e, m, bits);
    if (!e.correctly_rounded[0] || !e.correctly_rounded[1])
      e.note = forced ? "at the forced precision of " + std::to_string(bits) +
                            " bits the enclosure does not decide the nearest double: the map "
                            "is within error_bounds of the truth but may not be correctly rounded"
                      : "the map lies within 2^-" + std::to_string(bits) +
                            " (relative) of a midpoint between two doubles (the correct-rounding "
                            "cap): it is one of the two, within error_bounds of the truth, and "
                            "may not be the nearest";
    return e;
  }
}

}  // namespace gmcc
