#include <gmcc/selection/map_estimate.h>
#include <gmcc/selection/map_estimate_3.h>

#include "internal/rounded_component.h"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gmcc {
namespace internal {
namespace {
// q rounded to a double in the direction `rounding`.
double rounded(const Rational& q, mpfr_rnd_t rounding) {
  mpfr_t v;
  mpfr_init2(v, 53);
  mpfr_set_q(v, q.get_mpq_t(), rounding);
  const double d = mpfr_get_d(v, rounding);
  mpfr_clear(v);
  return d;
}

// num/den (den > 0, not necessarily coprime) rounded up to a double, as rounded() rounds the
// same value: mpfr_set_q reads the numerator and denominator as they are, so the quotient need
// not be in lowest terms.
double rounded_up(const mpz_class& num, const mpz_class& den) {
  mpq_t q;  // a read-only view of (num, den)
  *mpq_numref(q) = *num.get_mpz_t();
  *mpq_denref(q) = *den.get_mpz_t();
  mpfr_t v;
  mpfr_init2(v, 53);
  mpfr_set_q(v, q, MPFR_RNDU);
  const double d = mpfr_get_d(v, MPFR_RNDU);
  mpfr_clear(v);
  return d;
}
}  // namespace

// Where the nearest double m·2^s (|m| < 2^53) is normal and its neighbours finite, q lies between
// it and one neighbour: q − nearest = (n − m·2^s·d)/d, n/d = q, in integers (no gcd) gives its
// sign, hence q rounded down and up (nearest and the neighbour on q's side, both nearest when q
// is that double), and its magnitude rounded up is the bound. Elsewhere (zero, subnormal or
// huge), each rounding by MPFR from the exact difference.
RoundedComponent rounded_component(const Rational& q) {
  const double nearest = to_double_nearest(q);
  const double size = std::fabs(nearest);
  if (!(size >= std::numeric_limits<double>::min() && size < std::numeric_limits<double>::max()))
    return {nearest, rounded(Rational(abs(Rational(rational_from_double(nearest) - q))), MPFR_RNDU),
            rounded(q, MPFR_RNDD), rounded(q, MPFR_RNDU)};
  int e = 0;
  const double m = std::ldexp(std::frexp(nearest, &e), 53);  // an integer: nearest = m·2^(e − 53)
  const mpz_class mz(m);
  mpz_class num = q.get_num(), den = q.get_den();
  if (e >= 53) {
    num -= mpz_class(mz * den) << static_cast<mp_bitcnt_t>(e - 53);
  } else {
    num <<= static_cast<mp_bitcnt_t>(53 - e);
    num -= mz * den;
    den <<= static_cast<mp_bitcnt_t>(53 - e);
  }
  const int side = sgn(num);  // of q − nearest
  if (side == 0) return {nearest, 0, nearest, nearest};
  const double beyond = std::nextafter(nearest, side > 0 ? std::numeric_limits<double>::infinity()
                                                         : -std::numeric_limits<double>::infinity());
  return {nearest, rounded_up(abs(num), den), side > 0 ? nearest : beyond, side > 0 ? beyond : nearest};
}
}  // namespace internal

MapEstimate exact_map_estimate(std::string rule, const Point2& exact) {
  MapEstimate e;
  e.rule = std::move(rule);
  e.method = "exact";
  e.exact = exact;
  e.enclosure.emplace();
  for (int k = 0; k < 2; ++k) {
    const internal::RoundedComponent c = internal::rounded_component(k == 0 ? exact.x : exact.y);
    e.map[k] = c.nearest;
    e.error_bounds[k] = c.error_bound;
    (*e.enclosure)[k] = {c.lo, c.hi};  // the enclosure of an exact value
  }
  e.error_bound = std::max(e.error_bounds[0], e.error_bounds[1]);
  e.correctly_rounded = {true, true};  // nearest rounds the exact value once
  return e;
}

Point2 measured_map(const MapEstimate& e) {
  return e.exact ? *e.exact : Point2{rational_from_double(e.map[0]), rational_from_double(e.map[1])};
}

Point3 measured_map(const MapEstimate3& e) {
  return e.exact ? *e.exact
                 : Point3{rational_from_double(e.map[0]), rational_from_double(e.map[1]), rational_from_double(e.map[2])};
}

MapEstimate3 exact_map_estimate_3(std::string rule, const Point3& exact) {
  MapEstimate3 e;
  e.rule = std::move(rule);
  e.method = "exact";
  e.exact = exact;
  const Rational* c[3] = {&exact.x, &exact.y, &exact.z};
  for (int k = 0; k < 3; ++k) {
    const internal::RoundedComponent r = internal::rounded_component(*c[k]);
    e.map[k] = r.nearest;
    e.enclosure[k] = {r.lo, r.hi};
    e.error_bound = std::max(e.error_bound, r.error_bound);
  }
  return e;
}

}  // namespace gmcc
