// gmcc::numerics against GMP and MPFR (independent arbitrary-precision routes), and the platform
// fence: a thread whose x87 is set to 53 bits must not take the extended-precision fast paths.
#include <gmcc/numerics/constants.h>
#include <gmcc/numerics/platform.h>
#include <gmcc/numerics/top_bits.h>
#include <gmcc/numerics/wide_multiply.h>
#include <gmcc/selection/select_maps.h>

#include <boost/test/unit_test.hpp>

#include <gmpxx.h>
#include <mpfr.h>

#include <cstdint>
#include <random>
#include <vector>

#if defined(__x86_64__) && defined(__GLIBC__)
#include <fpu_control.h>
#define GMCC_TEST_X87_CONTROL 1
#endif

namespace {

mpz_class big(std::uint64_t x) {
  mpz_class z;
  mpz_import(z.get_mpz_t(), 1, 1, sizeof x, 0, 0, &x);
  return z;
}

// Integers of every size from 0 to 300 bits, with the awkward ones around limb boundaries.
std::vector<mpz_class> sample_integers() {
  std::vector<mpz_class> out;
  gmp_randclass random(gmp_randinit_mt);
  random.seed(20261125);
  for (unsigned bits : {1u, 2u, 31u, 32u, 33u, 63u, 64u, 65u, 127u, 128u, 129u, 191u, 192u, 300u}) {
    const mpz_class p = mpz_class(1) << bits;
    for (const mpz_class& z : {mpz_class(p - 1), p, mpz_class(p + 1)}) out.push_back(z), out.push_back(-z);
  }
  for (int i = 0; i < 2000; ++i) out.push_back(random.get_z_bits(1 + i % 300));
  out.push_back(0);
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(numerics)

BOOST_AUTO_TEST_CASE(top_bits_are_the_leading_64_bits) {
  for (const mpz_class& z : sample_integers()) {
    const gmcc::numerics::TopBits t = gmcc::numerics::top_bits(z.get_mpz_t());
    const mpz_class a = abs(z), m = big(t.mantissa);
    BOOST_TEST_REQUIRE(t.shift >= 0);
    // m·2^s <= |z| < (m + 1)·2^s: m is |z| truncated to its leading bits.
    BOOST_TEST((m << t.shift) <= a);
    BOOST_TEST(a < (mpz_class(m + 1) << t.shift));
    if (a < (mpz_class(1) << 64)) {
      BOOST_TEST(t.shift == 0);  // exact
    } else {
      BOOST_TEST(t.mantissa >> 63 == 1u);  // all 64 bits used: relative error below 2^-63
    }
  }
}

BOOST_AUTO_TEST_CASE(wide_products_and_quotients_agree_with_gmp) {
  std::mt19937_64 random(7);
  std::vector<std::uint64_t> values{0, 1, 2, 0xffffffffu, 0x100000000u, 0x100000001u, ~std::uint64_t{0},
                                    ~std::uint64_t{0} - 1, std::uint64_t{1} << 63};
  for (int i = 0; i < 200; ++i) values.push_back(random() >> (i % 64));
  for (std::uint64_t a : values)
    for (std::uint64_t b : values) {
      const mpz_class product = big(a) * big(b);
      for (const auto p : {gmcc::numerics::multiply_wide(a, b), gmcc::numerics::multiply_wide_halves(a, b)}) {
        BOOST_TEST_REQUIRE(big(p.high) == mpz_class(product >> 64));
        BOOST_TEST_REQUIRE(big(p.low) == mpz_class(product - (mpz_class(product >> 64) << 64)));
      }
      // ⌊a·b/n⌋ for every n with a quotient below 2^64 (high < n).
      const gmcc::numerics::WideProduct p = gmcc::numerics::multiply_wide(a, b);
      for (std::uint64_t n : values) {
        if (n == 0 || p.high >= n) continue;
        const mpz_class q = product / big(n);
        BOOST_TEST_REQUIRE(big(gmcc::numerics::divide_wide(p, n)) == q);
        BOOST_TEST_REQUIRE(big(gmcc::numerics::divide_wide_halves(p, n)) == q);
      }
    }
}

BOOST_AUTO_TEST_CASE(pi_is_the_nearest_long_double) {
  // Against MPFR's π at 256 bits: within half an ulp (2^-63 at π) of it, and as a double the
  // nearest double to π.
  mpfr_t pi, d;
  mpfr_inits2(256, pi, d, static_cast<mpfr_ptr>(nullptr));
  mpfr_const_pi(pi, MPFR_RNDN);
  mpfr_set_ld(d, gmcc::numerics::pi, MPFR_RNDN);
  mpfr_sub(d, d, pi, MPFR_RNDN);
  mpfr_abs(d, d, MPFR_RNDN);
  BOOST_TEST(mpfr_cmp_d(d, 0x1p-63) <= 0);
  BOOST_TEST(static_cast<double>(gmcc::numerics::pi) == mpfr_get_d(pi, MPFR_RNDN));
  mpfr_clears(pi, d, static_cast<mpfr_ptr>(nullptr));
}

BOOST_AUTO_TEST_CASE(the_fast_paths_follow_the_build) {
  // At the default precision control, active exactly when compiled in.
  BOOST_TEST(gmcc::numerics::extended_precision_active() == gmcc::numerics::extended_precision_compiled);
#ifdef GMCC_PORTABLE_NUMERICS
  BOOST_TEST(!gmcc::numerics::extended_precision_compiled);
#endif
}

#ifdef GMCC_TEST_X87_CONTROL
// With the x87 precision control at 53 bits, the fast paths' bounds would not hold: every rule
// must then take its portable route (the 3-D mean at more than 64 bits) and give the same maps.
BOOST_AUTO_TEST_CASE(a_53_bit_x87_thread_takes_the_portable_routes) {
  using gmcc::Point2;
  using gmcc::Rational;
  gmcc::ConvexSet2 F;
  F.kind = gmcc::ConvexKind::polygon;
  F.vertices = {{Rational(11, 10), Rational(13, 10)}, {Rational(19, 10), Rational(6, 5)},
                {Rational(21, 10), Rational(9, 5)}, {Rational(7, 5), Rational(11, 5)}};
  const gmcc::Selections full = gmcc::select_maps(F);
  fpu_control_t saved;
  _FPU_GETCW(saved);
  const fpu_control_t reduced = static_cast<fpu_control_t>((saved & ~_FPU_EXTENDED) | _FPU_DOUBLE);
  _FPU_SETCW(reduced);
  const bool active = gmcc::numerics::extended_precision_active();
  const gmcc::Selections low = gmcc::select_maps(F);
  _FPU_SETCW(saved);
  BOOST_TEST(!active);
  BOOST_TEST_REQUIRE(full[gmcc::Rule::mean_3d].has_value());
  BOOST_TEST_REQUIRE(low[gmcc::Rule::mean_3d].has_value());
  // The closed form's first stage is double-word arithmetic in SSE2 doubles (106 bits), which
  // the x87 control word does not touch; without it, the x87 stages work at 64 or 80 bits and the
  // portable MPFI route starts at 53 + 40 bits (mean_3d_analytic.cpp, automatic_precision).
  BOOST_TEST(full[gmcc::Rule::mean_3d]->estimate.precision_bits == 106u);
  BOOST_TEST(low[gmcc::Rule::mean_3d]->estimate.precision_bits >= 93u);
  for (const auto& [a, b] : {std::pair{full[gmcc::Rule::max_area], low[gmcc::Rule::max_area]}, std::pair{full[gmcc::Rule::mean_2d], low[gmcc::Rule::mean_2d]},
                             std::pair{full[gmcc::Rule::mean_3d], low[gmcc::Rule::mean_3d]}}) {
    BOOST_TEST(a->estimate.map[0] == b->estimate.map[0]);  // correctly rounded on both routes
    BOOST_TEST(a->estimate.map[1] == b->estimate.map[1]);
    BOOST_TEST(b->estimate.correctly_rounded[0]);
    BOOST_TEST(b->estimate.correctly_rounded[1]);
    BOOST_TEST_REQUIRE(a->worst_case_deg.has_value());
    BOOST_TEST_REQUIRE(b->worst_case_deg.has_value());
    // Both within a relative 2^-50 of the true angle (worst_case.h).
    BOOST_TEST(std::abs(*a->worst_case_deg - *b->worst_case_deg) <= 0x1p-49 * *a->worst_case_deg);
  }
}
#endif

BOOST_AUTO_TEST_SUITE_END()
