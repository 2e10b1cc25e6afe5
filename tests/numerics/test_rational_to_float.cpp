// numerics/rational_to_float.h: certified conversions of exact rationals under one range policy,
// checked exactly in ℚ (the converted value read back as the rational it is).
#include "../test_support.h"

#include <gmcc/numerics/platform.h>
#include <gmcc/numerics/rational_to_float.h>
#include <gmcc/numerics/truncated_quotient.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <optional>

using namespace gmcc;
using namespace gmcc::numerics;
using gmcc::test::Rng;

namespace {

// A long double as the exact rational it is: its 64-bit significand times a power of two.
Rational exact_value(long double x) {
  int e;
  const long double m = std::frexp(std::fabs(x), &e);  // |x| = m·2^e, 0.5 <= m < 1
  const auto top = static_cast<std::uint64_t>(std::ldexp(m, 64));  // exact: m has at most 64 bits
  mpz_class t;
  mpz_import(t.get_mpz_t(), 1, 1, sizeof top, 0, 0, &top);
  Rational r(x < 0 ? mpz_class(-t) : t);
  return e - 64 >= 0 ? Rational(r * (mpz_class(1) << (e - 64))) : Rational(r / (mpz_class(1) << (64 - e)));
}

// |x − q| <= rel·|q|, exactly.
bool within(long double x, const Rational& q, const Rational& rel) { return abs(exact_value(x) - q) <= rel * abs(q); }

// A random rational of about 2^e (num and den of many limbs, so their top bits truncate).
Rational around_power(Rng& rng, long e) {
  gmp_randclass random(gmp_randinit_mt);
  random.seed(static_cast<unsigned long>(rng()));
  const mpz_class den = random.get_z_bits(200) + 1;
  mpz_class num = random.get_z_bits(200) + 1;
  num = e >= 0 ? mpz_class(num << static_cast<unsigned long>(e)) : num;
  Rational q(num, e >= 0 ? den : mpz_class(den << static_cast<unsigned long>(-e)));
  q.canonicalize();
  return rng() % 2 ? q : Rational(-q);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(rational_to_float)

BOOST_AUTO_TEST_CASE(doubles_are_certified_within_the_policy) {
  Rng rng(47);
  const Rational two_u = Rational(1) >> 52;
  for (int trial = 0; trial < 400; ++trial) {
    const Rational q = around_power(rng, static_cast<long>(rng() % 320) - 160);
    const long e = binary_magnitude(q.get_num_mpz_t(), q.get_den_mpz_t());
    const std::optional<double> d = certified_double(q.get_mpq_t());
    BOOST_TEST(d.has_value() == (std::labs(e) <= double_magnitude_limit));
    if (d) {
      BOOST_TEST(within(*d, q, two_u));
      BOOST_TEST(in_double_range(*d));
    }
    // The magnitude is within one of log2|q|: 2^(e−1) < |q| < 2^(e+1).
    const Rational a = abs(q);
    BOOST_TEST((e >= 1 ? a > (Rational(1) << (e - 1)) : a > (Rational(1) >> (1 - e))));
    BOOST_TEST((e + 1 >= 0 ? a < (Rational(1) << (e + 1)) : a < (Rational(1) >> (-e - 1))));
  }
  BOOST_TEST(*certified_double(Rational(0).get_mpq_t()) == 0.0);
  BOOST_TEST(certified_double(Rational(mpz_class(1) << 138).get_mpq_t()).has_value());   // magnitude 138
  BOOST_TEST(!certified_double(Rational(mpz_class(1) << 139).get_mpq_t()).has_value());  // 139
  BOOST_TEST((in_double_range(0.0) && in_double_range(0x1.fp138) && !in_double_range(0x1p139)));
  BOOST_TEST((in_double_range(0x1p-139) && !in_double_range(0x1.fp-140) && !in_double_range(NAN)));
}

BOOST_AUTO_TEST_CASE(extended_values_are_certified_within_the_policy) {
  if (!extended_precision_compiled) return;  // no 64-bit significand: nothing to check
  Rng rng(53);
  const Rational rel = Rational(1) >> 61, rel_int = Rational(1) >> 63;
  for (int trial = 0; trial < 400; ++trial) {
    const Rational q = around_power(rng, static_cast<long>(rng() % 4000) - 2000);
    const std::optional<long double> x = certified_extended(q.get_num_mpz_t(), q.get_den_mpz_t());
    BOOST_TEST_REQUIRE(x.has_value());
    BOOST_TEST(within(*x, q, rel));
    const mpz_class z = q.get_num();
    BOOST_TEST(within(*certified_extended(z.get_mpz_t()), Rational(z), rel_int));
  }
  const mpz_class big = mpz_class(1) << 16000, one = 1;
  BOOST_TEST(certified_extended(mpz_class(big - 1).get_mpz_t()).has_value());  // 16000 bits
  BOOST_TEST(!certified_extended(big.get_mpz_t()).has_value());                  // 16001 bits
  BOOST_TEST(!certified_extended(one.get_mpz_t(), mpz_class(big << 1).get_mpz_t()).has_value());
  BOOST_TEST(*certified_extended(mpz_class(0).get_mpz_t(), one.get_mpz_t()) == 0.0L);
  BOOST_TEST(times_power_of_two(3.0L, -2000) * exact_power_of_two(900) * exact_power_of_two(900) *
                 exact_power_of_two(200) == 3.0L);  // exact scaling both ways
}

// truncated_quotient against mpq_get_d (an independent route: GMP's exact long division, then
// truncation) on unreduced quotients x/w of every shape the lazy 3-D set meets: random numbers of
// 1 to 1100 bits, exact quotients (x = q·w for a double q, so the value is a truncation
// boundary), their neighbours x ± 1, powers of two and small integers; each sign.
BOOST_AUTO_TEST_CASE(truncated_quotients_are_mpq_get_d) {
  Rng rng(61);
  gmp_randclass random(gmp_randinit_mt);
  random.seed(61);
  long decided = 0, trials = 0;
  auto check = [&](const mpz_class& x, const mpz_class& w) {
    if (sgn(x) == 0 || std::labs(binary_magnitude(x.get_mpz_t(), w.get_mpz_t())) > double_magnitude_limit - 1) return;
    mpq_t q;  // a read-only view, unreduced, as the library's caller uses it
    *mpq_numref(q) = *x.get_mpz_t();
    *mpq_denref(q) = *w.get_mpz_t();
    const std::optional<double> t = truncated_quotient(x.get_mpz_t(), w.get_mpz_t());
    ++trials;
    if (!t) return;
    ++decided;
    BOOST_TEST(*t == mpq_get_d(q), "x = " << x.get_str(16) << ", w = " << w.get_str(16));
  };
  for (int trial = 0; trial < 3000; ++trial) {
    const unsigned long wb = 1 + rng() % 600, xb = 1 + rng() % (wb + 400);
    const mpz_class w = random.get_z_bits(wb) + 1;
    mpz_class x = random.get_z_bits(xb) + 1;
    if (rng() % 2) x = -x;
    check(x, w);
    // An exact quotient: x = m·2^k·w for a 53-bit m (a truncation boundary), then x ± 1.
    const mpz_class m = random.get_z_bits(1 + rng() % 53) + 1;
    const long k = static_cast<long>(rng() % 200) - 100;
    mpz_class e = m * w;
    mpz_class ww = w;
    if (k >= 0) e <<= static_cast<unsigned long>(k);
    else ww <<= static_cast<unsigned long>(-k);
    check(e, ww), check(mpz_class(e + 1), ww), check(mpz_class(e - 1), ww), check(mpz_class(-e), ww);
    // Powers of two and small numbers.
    check(mpz_class(1) << static_cast<unsigned long>(rng() % 130), mpz_class(1) << static_cast<unsigned long>(rng() % 130));
    check(mpz_class(static_cast<long>(rng() % 1000) - 500), mpz_class(1 + rng() % 1000));
  }
  BOOST_TEST(trials > 12000);
  BOOST_TEST(decided * 100 >= trials * 99);  // the leading bits decide all but the edge cases
}

BOOST_AUTO_TEST_SUITE_END()
