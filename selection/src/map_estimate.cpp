#include <gmcc/selection/map_estimate.h>

#include <mpfr.h>

#include <algorithm>

namespace gmcc {
namespace {
// A double >= |x| (x exact): the rounding error of a rational map, as a bound.
double upper_double(const Rational& x) {
  mpfr_t v;
  mpfr_init2(v, 53);
  mpfr_set_q(v, Rational(abs(x)).get_mpq_t(), MPFR_RNDU);
  const double d = mpfr_get_d(v, MPFR_RNDU);
  mpfr_clear(v);
  return d;
}
}  // namespace

MapEstimate exact_map_estimate(std::string rule, const Point2& exact) {
  MapEstimate e;
  e.rule = std::move(rule);
  e.method = "exact";
  e.exact = exact;
  e.map = to_double_nearest(exact);
  e.error_bounds = {upper_double(rational_from_double(e.map[0]) - exact.x),
                    upper_double(rational_from_double(e.map[1]) - exact.y)};
  e.error_bound = std::max(e.error_bounds[0], e.error_bounds[1]);
  e.correctly_rounded = {true, true};  // to_double_nearest rounds the exact value once
  // The enclosure of an exact value is [value rounded down, value rounded up].
  e.enclosure.emplace();
  for (int k = 0; k < 2; ++k) {
    mpfr_t v;
    mpfr_init2(v, 53);
    const Rational& q = k == 0 ? exact.x : exact.y;
    mpfr_set_q(v, q.get_mpq_t(), MPFR_RNDD);
    (*e.enclosure)[k][0] = mpfr_get_d(v, MPFR_RNDD);
    mpfr_set_q(v, q.get_mpq_t(), MPFR_RNDU);
    (*e.enclosure)[k][1] = mpfr_get_d(v, MPFR_RNDU);
    mpfr_clear(v);
  }
  return e;
}

}  // namespace gmcc
