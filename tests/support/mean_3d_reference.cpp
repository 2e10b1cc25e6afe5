// The independent MPFR reference of the 3-D mean (Finlayson & Hordley 1999 §3.2;
// docs/math.md §2, "Closed form"), written from the formula only: exact rational edge data, then plain MPFR
// (round to nearest at one precision throughout), then a P-vs-2P self-check.
#include "mean_3d_reference.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace gmcc::test {

// ---- Mpfr ---------------------------------------------------------------------------------

Mpfr::Mpfr(mpfr_prec_t precision) {
  mpfr_init2(value_, precision);
  mpfr_set_zero(value_, 1);
}
Mpfr::Mpfr(const Mpfr& other) {
  mpfr_init2(value_, mpfr_get_prec(other.value_));
  mpfr_set(value_, other.value_, MPFR_RNDN);
}
Mpfr::Mpfr(Mpfr&& other) noexcept {
  mpfr_init2(value_, MPFR_PREC_MIN);
  mpfr_swap(value_, other.value_);  // swaps precisions too
}
Mpfr& Mpfr::operator=(const Mpfr& other) {
  if (this != &other) {
    mpfr_set_prec(value_, mpfr_get_prec(other.value_));
    mpfr_set(value_, other.value_, MPFR_RNDN);
  }
  return *this;
}
Mpfr& Mpfr::operator=(Mpfr&& other) noexcept {
  if (this != &other) mpfr_swap(value_, other.value_);
  return *this;
}
Mpfr::~Mpfr() { mpfr_clear(value_); }

namespace {

// q rounded to nearest at x's precision.
void set_rational(Mpfr& x, const Rational& q) { mpfr_set_q(x.get(), q.get_mpq_t(), MPFR_RNDN); }

std::string to_text(mpfr_srcptr x, int digits = 25) {
  std::string buffer(digits + 40, '\0');
  mpfr_snprintf(&buffer[0], buffer.size(), "%.*Rg", digits, x);
  buffer.resize(std::char_traits<char>::length(buffer.c_str()));
  return buffer;
}

// Polygon, the closed form of docs/math.md §2 (Lambert; Arvo 1995): τ = Σ_i θ_i c_i/|c_i| with the
// edge data c_i = p_i × p_{i+1}, d_i = p_i·p_{i+1} and |c_i|² exact in ℚ. The common factor ½
// and the orientation sign cancel in the map (τ1/τ3, τ2/τ3).
std::array<Mpfr, 2> polygon_mean(const std::vector<Point2>& v, mpfr_prec_t prec) {
  std::array<Mpfr, 3> tau{Mpfr(prec), Mpfr(prec), Mpfr(prec)};
  Mpfr length(prec), dot(prec), theta(prec), weight(prec), component(prec);
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& p = v[i];
    const Point2& q = v[(i + 1) % n];
    // (a_p, b_p, 1) × (a_q, b_q, 1)
    const std::array<Rational, 3> c{Rational(p.y - q.y), Rational(q.x - p.x),
                                    Rational(p.x * q.y - q.x * p.y)};
    const Rational d = p.x * q.x + p.y * q.y + 1;
    const Rational c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    set_rational(length, c2);
    mpfr_sqrt(length.get(), length.get(), MPFR_RNDN);       // |c_i|
    set_rational(dot, d);
    mpfr_atan2(theta.get(), length.get(), dot.get(), MPFR_RNDN);  // θ_i
    mpfr_div(weight.get(), theta.get(), length.get(), MPFR_RNDN); // θ_i/|c_i|
    for (int j = 0; j < 3; ++j) {
      set_rational(component, c[j]);
      mpfr_mul(component.get(), component.get(), weight.get(), MPFR_RNDN);
      mpfr_add(tau[j].get(), tau[j].get(), component.get(), MPFR_RNDN);
    }
  }
  if (mpfr_zero_p(tau[2].get())) throw std::runtime_error("mean_3d_reference: tau3 is 0");
  std::array<Mpfr, 2> m{Mpfr(prec), Mpfr(prec)};
  mpfr_div(m[0].get(), tau[0].get(), tau[2].get(), MPFR_RNDN);
  mpfr_div(m[1].get(), tau[1].get(), tau[2].get(), MPFR_RNDN);
  return m;
}

// Segment, docs/math.md §2, degenerate F: the perspective of û1 + û2, û = u/|u|, u = (a, b, 1);
// with w = 1/|u| (|u|² exact in ℚ): ((a1·w1 + a2·w2)/(w1 + w2), (b1·w1 + b2·w2)/(w1 + w2)).
std::array<Mpfr, 2> segment_mean(const Point2& u1, const Point2& u2, mpfr_prec_t prec) {
  Mpfr w1(prec), w2(prec), s(prec), t(prec);
  set_rational(w1, Rational(u1.x * u1.x + u1.y * u1.y + 1));
  mpfr_rec_sqrt(w1.get(), w1.get(), MPFR_RNDN);
  set_rational(w2, Rational(u2.x * u2.x + u2.y * u2.y + 1));
  mpfr_rec_sqrt(w2.get(), w2.get(), MPFR_RNDN);
  Mpfr third(prec);
  mpfr_add(third.get(), w1.get(), w2.get(), MPFR_RNDN);
  std::array<Mpfr, 2> m{Mpfr(prec), Mpfr(prec)};
  const std::array<const Rational*, 2> a1{&u1.x, &u1.y}, a2{&u2.x, &u2.y};
  for (int k = 0; k < 2; ++k) {
    set_rational(s, *a1[k]);
    mpfr_mul(s.get(), s.get(), w1.get(), MPFR_RNDN);
    set_rational(t, *a2[k]);
    mpfr_mul(t.get(), t.get(), w2.get(), MPFR_RNDN);
    mpfr_add(s.get(), s.get(), t.get(), MPFR_RNDN);
    mpfr_div(m[k].get(), s.get(), third.get(), MPFR_RNDN);
  }
  return m;
}

}  // namespace

// ---- Mean3dReference ------------------------------------------------------------------------

Mpfr Mean3dReference::uncertainty(int k) const {
  Mpfr delta(mpfr_get_prec(map[k].get()));
  if (exact[k]) return delta;  // 0
  mpfr_abs(delta.get(), map[k].get(), MPFR_RNDU);
  mpfr_mul_2si(delta.get(), delta.get(), uncertainty_log2(), MPFR_RNDU);
  return delta;
}

double Mean3dReference::nearest_double(int k) const { return mpfr_get_d(map[k].get(), MPFR_RNDN); }

bool Mean3dReference::nearest_is_certain(int k) const {
  const mpfr_prec_t prec = mpfr_get_prec(map[k].get());
  const Mpfr delta = uncertainty(k);
  Mpfr lo(prec), hi(prec);
  mpfr_sub(lo.get(), map[k].get(), delta.get(), MPFR_RNDD);
  mpfr_add(hi.get(), map[k].get(), delta.get(), MPFR_RNDU);
  return mpfr_get_d(lo.get(), MPFR_RNDN) == mpfr_get_d(hi.get(), MPFR_RNDN);
}

Mpfr Mean3dReference::abs_error(double x, int k) const {
  const mpfr_prec_t prec = mpfr_get_prec(map[k].get()) + 64;
  Mpfr xe(64), e(prec);
  mpfr_set_d(xe.get(), x, MPFR_RNDN);  // exact: a double has 53 bits
  mpfr_sub(e.get(), xe.get(), map[k].get(), MPFR_RNDN);
  mpfr_abs(e.get(), e.get(), MPFR_RNDU);
  return e;
}

double Mean3dReference::error_ratio(double x, double bound, int k) const {
  const Mpfr e = abs_error(x, k);
  if (mpfr_zero_p(e.get())) return 0;
  if (bound <= 0) return std::numeric_limits<double>::infinity();
  Mpfr r(64);
  mpfr_div_d(r.get(), e.get(), bound, MPFR_RNDU);
  return mpfr_get_d(r.get(), MPFR_RNDU);
}

Coverage Mean3dReference::covers(double x, double bound, int k) const {
  const Mpfr e = abs_error(x, k);
  const mpfr_prec_t prec = mpfr_get_prec(e.get());
  const Mpfr delta = uncertainty(k);
  Mpfr hi(prec), lo(prec), b(64);
  mpfr_add(hi.get(), e.get(), delta.get(), MPFR_RNDU);
  mpfr_sub(lo.get(), e.get(), delta.get(), MPFR_RNDD);
  mpfr_set_d(b.get(), bound, MPFR_RNDN);  // exact
  if (mpfr_lessequal_p(hi.get(), b.get())) return Coverage::covered;
  if (mpfr_greater_p(lo.get(), b.get())) return Coverage::exceeded;
  return Coverage::undecided;
}

Coverage Mean3dReference::inside(double lo, double hi, int k) const {
  const mpfr_prec_t prec = mpfr_get_prec(map[k].get());
  const Mpfr delta = uncertainty(k);
  Mpfr below(prec), above(prec);
  mpfr_sub(below.get(), map[k].get(), delta.get(), MPFR_RNDD);
  mpfr_add(above.get(), map[k].get(), delta.get(), MPFR_RNDU);
  // mpfr_cmp_d compares exactly.
  if (mpfr_cmp_d(below.get(), lo) >= 0 && mpfr_cmp_d(above.get(), hi) <= 0) return Coverage::covered;
  if (mpfr_cmp_d(above.get(), lo) < 0 || mpfr_cmp_d(below.get(), hi) > 0) return Coverage::exceeded;
  return Coverage::undecided;
}

// ---- evaluation -----------------------------------------------------------------------------

// Finlayson & Hordley 1999 §3.2: the centroid of cone(F) ∩ unit ball, projected to d3 = 1, by
// the closed form of docs/math.md §2 (polygon), its segment convention, or the point.
Mean3dReference mean_3d_reference(const ConvexSet2& F, unsigned precision_bits) {
  const mpfr_prec_t prec = static_cast<mpfr_prec_t>(precision_bits);
  Mean3dReference r{{Mpfr(prec), Mpfr(prec)}, precision_bits, {false, false}};
  switch (F.kind) {
    case ConvexKind::empty:
      throw std::invalid_argument("mean_3d_reference: empty set");
    case ConvexKind::point:
      r.exact[0] = mpfr_set_q(r.map[0].get(), F.vertices.at(0).x.get_mpq_t(), MPFR_RNDN) == 0;
      r.exact[1] = mpfr_set_q(r.map[1].get(), F.vertices.at(0).y.get_mpq_t(), MPFR_RNDN) == 0;
      break;
    case ConvexKind::segment:
      r.map = segment_mean(F.vertices.at(0), F.vertices.at(1), prec);
      break;
    case ConvexKind::polygon:
      r.map = polygon_mean(F.vertices, prec);
      break;
  }
  return r;
}

// The self-check: P and 2P evaluations agree within 2^-(P-200) relative, per coordinate.
Mean3dReference mean_3d_reference_checked(const ConvexSet2& F, unsigned precision_bits) {
  const Mean3dReference lo = mean_3d_reference(F, precision_bits);
  Mean3dReference hi = mean_3d_reference(F, 2 * precision_bits);
  const mpfr_prec_t prec = 2 * static_cast<mpfr_prec_t>(precision_bits);
  for (int k = 0; k < 2; ++k) {
    Mpfr diff(prec), scale(prec);
    mpfr_sub(diff.get(), lo.map[k].get(), hi.map[k].get(), MPFR_RNDN);
    mpfr_abs(diff.get(), diff.get(), MPFR_RNDU);
    mpfr_abs(scale.get(), hi.map[k].get(), MPFR_RNDD);
    mpfr_mul_2si(scale.get(), scale.get(), -static_cast<long>(precision_bits) + 200, MPFR_RNDD);
    if (mpfr_greater_p(diff.get(), scale.get()) || mpfr_nan_p(diff.get())) {
      std::ostringstream os;
      os << "mean_3d_reference: coordinate " << k << " at " << precision_bits << " bits ("
         << to_text(lo.map[k].get()) << ") and at " << 2 * precision_bits << " bits ("
         << to_text(hi.map[k].get()) << ") differ by " << to_text(diff.get(), 6)
         << ", more than 2^-" << precision_bits - 200 << " relative";
      throw std::runtime_error(os.str());
    }
  }
  hi.precision_bits = precision_bits;
  for (int k = 0; k < 2; ++k) hi.exact[k] = hi.exact[k] && lo.exact[k];
  return hi;
}

}  // namespace gmcc::test
