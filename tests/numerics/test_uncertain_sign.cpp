// The enclosure family's one decision type (numerics/uncertain_sign.h) and its free functions,
// one generic body over every kind: doubles and x87 midpoint–radius, x87 intervals, MPFI. The
// exact sign, computed in ℚ, is the independent answer: a kind may leave a sign undecided but
// never decide it wrongly.
#include "../test_support.h"

#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/numerics/platform.h>
#include <gmcc/numerics/uncertain_sign.h>

#include "internal/interval.h"
#include "internal/ld_interval.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

using namespace gmcc;
using gmcc::numerics::UncertainSign;

namespace {
using gmcc::test::random_rational;
using gmcc::test::Rng;

// The kinds, each with of(q): q enclosed.
struct DoubleKind {
  static Enclosure of(const Rational& q) { return enclose_rational(q); }
};
struct LongKind {
  static LongEnclosure of(const Rational& q) {
    return LongEnclosure::relative(static_cast<long double>(mpq_get_d(q.get_mpq_t())), 0x1p-50L);
  }
};
struct LDKind {
  static numerics::LDInterval of(const Rational& q) { return internal::enclose_ld(q); }
};
struct MpfiKind {
  static internal::Interval of(const Rational& q) { return internal::Interval(q, 96); }
};

bool allows(UncertainSign s, int exact) { return s.lo <= exact && exact <= s.hi; }

// a·b − c·d in the kind K, against its exact sign; near-cancelling cases included.
template <class K>
void check_kind(bool bounds_hold) {
  Rng rng(41);
  int decided = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Rational a = random_rational(rng, -99, 99, 97), b = random_rational(rng, -99, 99, 89);
    const Rational c = trial % 3 == 0 ? a : random_rational(rng, -99, 99, 83);
    const Rational d = trial % 3 == 0 ? Rational(b + Rational(trial % 7 - 3, 1 << 20)) : random_rational(rng, -99, 99, 79);
    const auto x = K::of(a) * K::of(b) - K::of(c) * K::of(d);
    const int exact = sgn(Rational(a * b - c * d));
    const UncertainSign s = sign(x);
    BOOST_TEST(s.lo <= s.hi);
    if (bounds_hold) BOOST_TEST(allows(s, exact));
    BOOST_TEST(certainly_positive(x) == certainly_positive(s));
    BOOST_TEST(certainly_negative(x) == certainly_negative(s));
    BOOST_TEST(certainly_nonzero(x) == (certainly_positive(x) || certainly_negative(x)));
    BOOST_TEST(allows(-s, -exact) == allows(s, exact));
    decided += s.is_certain();
  }
  BOOST_TEST(decided > 1500);  // most products are far from cancelling: the kinds decide them
}

}  // namespace

BOOST_AUTO_TEST_SUITE(uncertain_sign)

BOOST_AUTO_TEST_CASE(every_kind_decides_only_true_signs) {
  check_kind<DoubleKind>(true);
  check_kind<LongKind>(numerics::extended_precision_active());
  check_kind<LDKind>(numerics::extended_precision_active());
  check_kind<MpfiKind>(true);
}

BOOST_AUTO_TEST_CASE(nan_and_zero) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Enclosure e_nan{nan, 0}, e_inf = Enclosure{0, Enclosure::unbounded};
  for (const Enclosure& e : {e_nan, e_inf}) {
    BOOST_TEST(!sign(e).is_certain());
    BOOST_TEST((!certainly_positive(e) && !certainly_negative(e) && !certainly_nonzero(e)));
  }
  internal::Interval i_nan(64);
  mpfi_set_d(i_nan.get(), nan);
  BOOST_TEST(!sign(i_nan).is_certain());  // mpfr_sgn(NaN) is 0: it must not pass for a zero
  BOOST_TEST(!internal::certainly_nonzero(i_nan));
  const internal::Interval zero(Rational(0), 64);
  BOOST_TEST(numerics::certainly_zero(sign(zero)));
  BOOST_TEST(!internal::certainly_nonzero(zero));
  const internal::Interval x(Rational(1, 3), 64), y(Rational(1, 2), 64);
  BOOST_TEST(numerics::certainly_negative(compare(x, y)));
  BOOST_TEST(numerics::certainly_positive(compare(y, Rational(1, 3))));
  BOOST_TEST(!compare(x, Rational(1, 3)).is_certain());  // 1/3 is not a binary number: x holds it
  BOOST_TEST((UncertainSign::certain(-1).is_certain() && !UncertainSign::indeterminate().is_certain()));
}

BOOST_AUTO_TEST_SUITE_END()
