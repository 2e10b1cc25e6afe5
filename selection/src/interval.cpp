#include "internal/interval.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gmcc::internal {
namespace {
struct Mpfr {
  explicit Mpfr(mpfr_prec_t bits) { mpfr_init2(v, bits); }
  ~Mpfr() { mpfr_clear(v); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
  mpfr_t v;
};
}  // namespace

Interval::Interval(long double lo, long double hi, mpfr_prec_t bits) : Interval(bits) {
  Mpfr a(bits), b(bits);
  mpfr_set_ld(a.v, lo, MPFR_RNDD);
  mpfr_set_ld(b.v, hi, MPFR_RNDU);
  mpfi_interv_fr(v_, a.v, b.v);
}

RoundedEnclosure round_to_double(const Interval& x) {
  const std::optional<double> r = single_rounding(x);
  const auto [value, bound] = r ? bound_from(x, *r) : nearest_with_bound(x);
  return {value, bound, r.has_value()};
}

Interval atan2(const Interval& y, const Interval& x) {
  const mpfr_prec_t p = y.precision();
  Interval r(p);
  Mpfr x_lo(p), y_lo(p);
  mpfi_get_left(x_lo.v, x.get());
  mpfi_get_left(y_lo.v, y.get());
  if (!bounded(x) || !bounded(y) || mpfr_sgn(x_lo.v) <= 0 || mpfr_sgn(y_lo.v) < 0) {
    mpfi_atan2(r.get(), y.get(), x.get());
    return r;
  }
  Interval t = y / x;  // >= 0
  Mpfr mid(p), lo(p), hi(p), rad(p), theta(p), theta_lo(p), theta_hi(p);
  mpfi_mid(mid.v, t.get());
  mpfi_get_left(lo.v, t.get());
  mpfi_get_right(hi.v, t.get());
  mpfr_sub(lo.v, mid.v, lo.v, MPFR_RNDU);  // mid − lo
  mpfr_sub(hi.v, hi.v, mid.v, MPFR_RNDU);  // hi − mid
  mpfr_max(rad.v, lo.v, hi.v, MPFR_RNDU);
  mpfr_atan(theta.v, mid.v, MPFR_RNDN);    // within half an ulp of atan(mid)
  if (!mpfr_zero_p(theta.v)) {
    Mpfr ulp(p);
    mpfr_set_ui_2exp(ulp.v, 1, mpfr_get_exp(theta.v) - p, MPFR_RNDU);
    mpfr_add(rad.v, rad.v, ulp.v, MPFR_RNDU);
  }
  mpfr_sub(theta_lo.v, theta.v, rad.v, MPFR_RNDD);
  mpfr_add(theta_hi.v, theta.v, rad.v, MPFR_RNDU);
  mpfi_interv_fr(r.get(), theta_lo.v, theta_hi.v);
  return r;
}

std::pair<double, double> nearest_with_bound(const Interval& x) {
  Mpfr mid(x.precision());
  mpfi_mid(mid.v, x.get());
  return bound_from(x, mpfr_get_d(mid.v, MPFR_RNDN));
}

std::pair<double, double> bound_from(const Interval& x, double value) {
  const mpfr_prec_t p = std::max<mpfr_prec_t>(x.precision(), 53);
  Mpfr lo(p), hi(p), d_lo(p), d_hi(p);
  mpfi_get_left(lo.v, x.get());
  mpfi_get_right(hi.v, x.get());
  // |value − lo| and |hi − value|, each rounded up; value is exact in p >= 53 bits.
  mpfr_sub_d(d_lo.v, lo.v, value, MPFR_RNDD);  // lo − value <= 0 (usually)
  mpfr_neg(d_lo.v, d_lo.v, MPFR_RNDU);
  mpfr_sub_d(d_hi.v, hi.v, value, MPFR_RNDU);
  const double bound =
      std::max({mpfr_get_d(d_lo.v, MPFR_RNDU), mpfr_get_d(d_hi.v, MPFR_RNDU), 0.0});
  return {value, bound};
}

std::pair<double, double> outward_doubles(const Interval& x) {
  Mpfr lo(x.precision()), hi(x.precision());
  mpfi_get_left(lo.v, x.get());
  mpfi_get_right(hi.v, x.get());
  return {mpfr_get_d(lo.v, MPFR_RNDD), mpfr_get_d(hi.v, MPFR_RNDU)};
}

std::optional<double> single_rounding(const Interval& x) {
  if (!bounded(x)) return std::nullopt;
  Mpfr lo(x.precision()), hi(x.precision());
  mpfi_get_left(lo.v, x.get());
  mpfi_get_right(hi.v, x.get());
  const double a = mpfr_get_d(lo.v, MPFR_RNDN), b = mpfr_get_d(hi.v, MPFR_RNDN);
  if (a != b || !std::isfinite(a)) return std::nullopt;
  return a;
}

bool beyond_doubles(const Interval& x) {
  if (!bounded(x)) return false;
  Mpfr lo(x.precision()), hi(x.precision());
  mpfi_get_left(lo.v, x.get());
  mpfi_get_right(hi.v, x.get());
  const double largest = std::numeric_limits<double>::max();
  return mpfr_cmp_d(lo.v, largest) > 0 || mpfr_cmp_d(hi.v, -largest) < 0;
}

bool bounded(const Interval& x) { return !mpfi_nan_p(x.get()) && mpfi_bounded_p(x.get()); }

numerics::UncertainSign sign(const Interval& x) {
  if (mpfi_nan_p(x.get())) return numerics::UncertainSign::indeterminate();  // mpfr_sgn(NaN) is 0
  const int l = mpfr_sgn(&x.get()->left), h = mpfr_sgn(&x.get()->right);
  return {l, h};  // the ends' signs: every point's sign lies between them
}

numerics::UncertainSign compare(const Interval& x, const Rational& q) {
  return sign(x - Interval(q, x.precision()));
}

numerics::UncertainSign compare(const Interval& x, const Interval& y) { return sign(x - y); }

bool tight(const Interval& x, int bits) {
  if (!bounded(x)) return false;
  const mpfr_prec_t p = x.precision();
  Mpfr width(p), mag(p);
  mpfi_diam_abs(width.v, x.get());
  if (mpfr_zero_p(width.v)) return true;
  mpfi_mag(mag.v, x.get());
  mpfr_mul_2si(mag.v, mag.v, -bits, MPFR_RNDD);
  return mpfr_lessequal_p(width.v, mag.v) != 0;
}

}  // namespace gmcc::internal

#include "internal/ld_interval.h"

#include <gmcc/numerics/rational_to_float.h>

#include <limits>
#include <optional>

namespace gmcc::internal {

LDInterval enclose_ld(mpz_srcptr num, mpz_srcptr den) {
  if (mpz_sgn(num) == 0) return {0, 0};
  const std::optional<long double> v = numerics::certified_extended(num, den);
  if (!v) {  // outside the range policy (numerics/rational_to_float.h): the whole line
    const long double inf = std::numeric_limits<long double>::infinity();
    return {-inf, inf};
  }
  // One-limb numerator and denominator are exact: only the division rounds (2^-64).
  const bool exact_parts = mpz_size(num) <= 1 && mpz_size(den) <= 1;
  return LDInterval::around(*v, *v, exact_parts ? LDInterval::push : 0x1p-60L);
}

LDInterval enclose_ld(const Rational& q) { return enclose_ld(q.get_num_mpz_t(), q.get_den_mpz_t()); }

}  // namespace gmcc::internal
