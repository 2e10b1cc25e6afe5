#pragma once
// A small RAII wrapper over MPFI intervals: certified enclosures for the irrational rules.
// Internal to gmcc::selection.

#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/uncertain_sign.h>

#include <mpfi.h>

#include <optional>
#include <utility>

namespace gmcc::internal {

class Interval {
 public:
  explicit Interval(mpfr_prec_t bits) { mpfi_init2(v_, bits); }
  Interval(const Rational& q, mpfr_prec_t bits) : Interval(bits) { mpfi_set_q(v_, q.get_mpq_t()); }
  /// [lo, hi] for long doubles lo <= hi, exact when bits >= the long double's significand.
  Interval(long double lo, long double hi, mpfr_prec_t bits);
  Interval(const Interval& o) : Interval(mpfi_get_prec(o.v_)) { mpfi_set(v_, o.v_); }
  Interval& operator=(const Interval& o) {
    if (this != &o) mpfi_set(v_, o.v_);
    return *this;
  }
  ~Interval() { mpfi_clear(v_); }

  mpfi_ptr get() { return v_; }
  mpfi_srcptr get() const { return v_; }
  mpfr_prec_t precision() const { return mpfi_get_prec(v_); }

  friend Interval operator+(const Interval& a, const Interval& b) {
    Interval r(a.precision());
    mpfi_add(r.v_, a.v_, b.v_);
    return r;
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    Interval r(a.precision());
    mpfi_sub(r.v_, a.v_, b.v_);
    return r;
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    Interval r(a.precision());
    mpfi_mul(r.v_, a.v_, b.v_);
    return r;
  }
  friend Interval operator*(const Interval& a, const Rational& q) {
    Interval r(a.precision());
    mpfi_mul_q(r.v_, a.v_, q.get_mpq_t());
    return r;
  }
  friend Interval operator/(const Interval& a, const Interval& b) {
    Interval r(a.precision());
    mpfi_div(r.v_, a.v_, b.v_);
    return r;
  }
  /// a², never negative (unlike a·a when a holds 0).
  friend Interval sqr(const Interval& a) {
    Interval r(a.precision());
    mpfi_sqr(r.v_, a.v_);
    return r;
  }
  friend Interval sqrt(const Interval& a) {
    Interval r(a.precision());
    mpfi_sqrt(r.v_, a.v_);
    return r;
  }
  /// atan2(y, x) over intervals (y > 0 here, so no branch cut is crossed). Where x > 0 and
  /// y >= 0 it is atan(y/x), enclosed from one correctly rounded atan at the quotient's
  /// midpoint: |atan'| <= 1, so the quotient's radius plus one ulp covers the interval (half
  /// the cost of mpfi_atan2, which evaluates both ends).
  friend Interval atan2(const Interval& y, const Interval& x);

 private:
  mpfi_t v_;
};

/// The double nearest the interval's midpoint, and a rigorous bound on its distance to every
/// point of the interval (rounded up). The pair is (value, bound).
std::pair<double, double> nearest_with_bound(const Interval& x);

/// (value, a rigorous bound on value's distance to every point of x, rounded up).
std::pair<double, double> bound_from(const Interval& x, double value);

/// A bounded enclosure reported as one double: the double every point of it rounds to when
/// there is one (single_rounding, `correctly_rounded`), else the double nearest its midpoint;
/// `bound` covers the distance to every point of it, rounded up.
struct RoundedEnclosure {
  double value = 0, bound = 0;
  bool correctly_rounded = false;
};
RoundedEnclosure round_to_double(const Interval& x);

/// The interval's ends rounded outward to doubles.
std::pair<double, double> outward_doubles(const Interval& x);

/// The double nearest every point of the interval, if there is one: both ends round (to
/// nearest, ties to even) to the same double, so — rounding being monotone — does every value
/// between them, the true one included. Empty when a rounding boundary lies inside.
std::optional<double> single_rounding(const Interval& x);

/// True when the interval is bounded and lies wholly beyond the largest finite double (either
/// sign): no precision can give a double inside it.
bool beyond_doubles(const Interval& x);

/// True when neither end is infinite or NaN.
bool bounded(const Interval& x);

/// \name The enclosure family's questions (numerics/enclosure.h), for MPFI
///@{
/// The signs x allows: certain when both ends are on one side of zero (or both zero);
/// indeterminate when x holds zero and more, or is NaN.
numerics::UncertainSign sign(const Interval& x);
/// The sign of x − q, x's precision: certain when every point of x is above q, below q, or q.
numerics::UncertainSign compare(const Interval& x, const Rational& q);
/// The sign of x − y: certain when every point of x is above (or below) every point of y.
numerics::UncertainSign compare(const Interval& x, const Interval& y);
/// Every point of x is > 0.
inline bool certainly_positive(const Interval& x) { return numerics::certainly_positive(sign(x)); }
/// Every point of x is < 0.
inline bool certainly_negative(const Interval& x) { return numerics::certainly_negative(sign(x)); }
/// Every point of x is ≠ 0.
inline bool certainly_nonzero(const Interval& x) { return numerics::certainly_nonzero(sign(x)); }
///@}

/// True when the interval is bounded and its width is at most 2^-bits times its magnitude (or
/// it is a point). An unbounded interval is never tight: its width and magnitude are both
/// infinite, and inf <= inf·2^-bits would call it tight.
bool tight(const Interval& x, int bits);

}  // namespace gmcc::internal
