#include <gmcc/selection/map_estimate.h>
#include <gmcc/selection/map_estimate_3.h>

#include "internal/rounded_component.h"

#include <mpfr.h>

#include <algorithm>

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
}  // namespace

RoundedComponent rounded_component(const Rational& q) {
  const double nearest = to_double_nearest(q);
  return {nearest, rounded(Rational(abs(Rational(rational_from_double(nearest) - q))), MPFR_RNDU),
          rounded(q, MPFR_RNDD), rounded(q, MPFR_RNDU)};
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
