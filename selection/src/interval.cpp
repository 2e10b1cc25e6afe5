#include "internal/interval.h"

#include <algorithm>

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

std::pair<double, double> nearest_with_bound(const Interval& x) {
  const mpfr_prec_t p = x.precision();
  Mpfr mid(p), lo(p), hi(p), d_lo(p), d_hi(p);
  mpfi_mid(mid.v, x.get());
  const double value = mpfr_get_d(mid.v, MPFR_RNDN);
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

bool tight(const Interval& x, int bits) {
  const mpfr_prec_t p = x.precision();
  Mpfr width(p), mag(p);
  mpfi_diam_abs(width.v, x.get());
  if (mpfr_zero_p(width.v)) return true;
  mpfi_mag(mag.v, x.get());
  mpfr_mul_2si(mag.v, mag.v, -bits, MPFR_RNDD);
  return mpfr_lessequal_p(width.v, mag.v) != 0;
}

}  // namespace gmcc::internal
