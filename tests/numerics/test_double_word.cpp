// Double-word arithmetic and its enclosures (numerics/double_word.h, dw_enclosure.h, dw_atan.h,
// dw_rounding.h; docs/math.md "The double-word stage"): every operation's enclosure contains the
// exact rational result (GMP), on random and adversarial inputs (cancellation, magnitudes from
// 2^-300 to 2^300, radii); atan's enclosure contains MPFR's atan at 400 bits; the tabulated
// constants are within their charge of MPFR's values; the rounding decision agrees with MPFR's
// round to nearest, ties to even, at and near midpoints; the truncation decision agrees with
// GMP's truncation (mpq_get_d) at and near doubles; an integer's double-word copy encloses it.
#include <gmcc/numerics/dw_atan.h>
#include <gmcc/numerics/dw_integer.h>
#include <gmcc/numerics/dw_rounding.h>

#include <boost/test/unit_test.hpp>

#include <gmpxx.h>
#include <mpfr.h>

#include <cmath>
#include <cstdint>
#include <random>

using namespace gmcc::numerics;

namespace {

mpq_class exact(double x) { return mpq_class(x); }  // GMP converts a double exactly
mpq_class exact(const DoubleWord& x) { return exact(x.hi) + exact(x.lo); }

// Whether q lies in x's enclosure, decided exactly.
bool contains(const DWEnclosure& x, const mpq_class& q) {
  if (!x.finite()) return true;  // an unbounded enclosure claims nothing
  const mpq_class d = q - exact(x.mid);
  return abs(d) <= exact(x.rad);
}

// A random normalised double-word number of magnitude about 2^e, with a random radius.
DWEnclosure random_dw(std::mt19937_64& rng, int e, bool with_radius) {
  std::uniform_real_distribution<double> unit(-1, 1);
  const double hi = std::ldexp(unit(rng), e);
  const double lo = std::ldexp(unit(rng), e - 54);
  DWEnclosure x = DWEnclosure::exact(fast_two_sum(hi, lo));
  if (with_radius) x.rad = std::ldexp(std::fabs(unit(rng)), e - 60 - static_cast<int>(rng() % 40));
  return x;
}

// The exact rational inside x at its lower end, midpoint or upper end (which = 0, 1, 2).
mpq_class point_of(const DWEnclosure& x, int which) {
  return exact(x.mid) + (which - 1) * exact(x.rad);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(double_word)

BOOST_AUTO_TEST_CASE(error_free_transformations_are_exact) {
  std::mt19937_64 rng(2017);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < 20000; ++i) {
    const double a = std::ldexp(unit(rng), static_cast<int>(rng() % 200) - 100);
    const double b = std::ldexp(unit(rng), static_cast<int>(rng() % 200) - 100);
    const DoubleWord s = two_sum(a, b), p = two_prod(a, b);
    BOOST_TEST(exact(s) == exact(a) + exact(b));
    BOOST_TEST(exact(p) == exact(a) * exact(b));
    BOOST_TEST(s.hi == a + b);
  }
}

// The family's ends and sign (enclosure.h) on DWEnclosure: [lower, upper] holds both exact ends
// of [mid − rad, mid + rad], and sign never excludes the sign of a point inside, on enclosures of
// every magnitude, straddling 0 or not, exact, and unbounded.
BOOST_AUTO_TEST_CASE(ends_and_sign_hold_the_exact_enclosure) {
  std::mt19937_64 rng(44);
  int certain = 0;
  for (int i = 0; i < 20000; ++i) {
    DWEnclosure x = random_dw(rng, static_cast<int>(rng() % 1800) - 900, i % 3 != 0);
    if (i % 7 == 0) x.rad = std::fabs(x.mid.hi) * (0.5 + static_cast<double>(rng() % 4) / 4);  // near or across 0
    if (i % 97 == 0) x = DWEnclosure::exact(0.0);
    const UncertainSign s = sign(x);
    if (!x.finite()) {
      BOOST_TEST(!s.is_certain());
      continue;
    }
    for (int which = 0; which < 3; ++which) {
      const mpq_class q = point_of(x, which);
      BOOST_TEST(exact(lower(x)) <= q);
      BOOST_TEST(q <= exact(upper(x)));
      BOOST_TEST((s.lo <= sgn(q) && sgn(q) <= s.hi));
    }
    BOOST_TEST(abs(exact(x.mid)) + exact(x.rad) <= exact(x.abs_upper()));
    certain += s.is_certain();
  }
  BOOST_TEST(certain > 10000);  // the ends are tight enough to decide most signs
  BOOST_TEST(!sign(DWEnclosure::unbounded()).is_certain());
  BOOST_TEST(sign(DWEnclosure::exact(0.0)).is_certain());
  BOOST_TEST(!sign(DWEnclosure{{std::nan(""), 0}, 0}).is_certain());
}

BOOST_AUTO_TEST_CASE(operations_enclose_the_exact_result) {
  std::mt19937_64 rng(3121432);
  for (int i = 0; i < 20000; ++i) {
    const int ex = static_cast<int>(rng() % 600) - 300, ey = ex + static_cast<int>(rng() % 120) - 60;
    const bool radius = i % 2 == 1;
    const DWEnclosure x = random_dw(rng, ex, radius);
    DWEnclosure y = random_dw(rng, ey, radius);
    if (i % 5 == 0) y = DWEnclosure{dw_neg(x.mid), x.rad} + random_dw(rng, ex - 80, false);  // cancellation
    const int wx = static_cast<int>(rng() % 3), wy = static_cast<int>(rng() % 3);
    const mpq_class px = point_of(x, wx), py = point_of(y, wy);
    BOOST_TEST(contains(x + y, px + py));
    BOOST_TEST(contains(x - y, px - py));
    BOOST_TEST(contains(x * y, px * py));
    if (py != 0) BOOST_TEST(contains(x / y, px / py));
    const double b = y.mid.hi;  // with a double
    BOOST_TEST(contains(x + b, px + exact(b)));
    BOOST_TEST(contains(x * b, px * exact(b)));
    const DWEnclosure ax{{std::fabs(x.mid.hi), x.mid.hi < 0 ? -x.mid.lo : x.mid.lo}, x.rad};
    const DWEnclosure r = sqrt(ax);
    if (r.finite()) {
      const mpq_class v = point_of(ax, wx), lo = exact(r.mid) - exact(r.rad), hi = exact(r.mid) + exact(r.rad);
      BOOST_TEST((lo <= 0 || lo * lo <= v));
      BOOST_TEST(hi * hi >= v);
    }
  }
}

BOOST_AUTO_TEST_CASE(enclosures_are_tight) {
  // About 2^-100 relative per operation: a product of two exact inputs stays within 2^-98.
  std::mt19937_64 rng(44);
  for (int i = 0; i < 1000; ++i) {
    const DWEnclosure z = random_dw(rng, 0, false) * random_dw(rng, 3, false);
    BOOST_TEST(z.rad <= std::fabs(z.mid.hi) * 0x1p-98);
  }
}

BOOST_AUTO_TEST_CASE(constants_are_within_their_charge) {
  mpfr_t v, d;
  mpfr_inits2(400, v, d, static_cast<mpfr_ptr>(nullptr));
  auto check = [&](const DoubleWord& c) {  // v holds the true value
    mpfr_sub_d(d, v, c.hi, MPFR_RNDN);
    mpfr_sub_d(d, d, c.lo, MPFR_RNDN);
    mpfr_abs(d, d, MPFR_RNDN);
    BOOST_TEST(mpfr_cmp_d(d, std::fabs(c.hi) * 0x1p-105) <= 0);
  };
  for (int k = 0; k <= 128; ++k) {
    mpfr_set_si(v, k, MPFR_RNDN);
    mpfr_div_si(v, v, 128, MPFR_RNDN);
    mpfr_atan(v, v, MPFR_RNDN);
    check(dw_atan_detail::atan_table[static_cast<std::size_t>(k)]);
  }
  for (int j = 1; j <= 6; ++j) {
    mpfr_set_si(v, 1, MPFR_RNDN);
    mpfr_div_si(v, v, 2 * j + 1, MPFR_RNDN);
    check(dw_atan_detail::odd_reciprocals[static_cast<std::size_t>(j - 1)]);
  }
  mpfr_const_pi(v, MPFR_RNDN);
  mpfr_div_2ui(v, v, 1, MPFR_RNDN);
  check(dw_atan_detail::half_pi);
  mpfr_clears(v, d, static_cast<mpfr_ptr>(nullptr));
}

BOOST_AUTO_TEST_CASE(atan_encloses_mpfr) {
  std::mt19937_64 rng(1964);
  mpfr_t a, m, d;
  mpfr_inits2(400, a, m, d, static_cast<mpfr_ptr>(nullptr));
  for (int i = 0; i < 20000; ++i) {
    // magnitudes 2^-40 … 2^40, table boundaries k/128 ± tiny, 1 and around it
    const int e = static_cast<int>(rng() % 81) - 40;
    DWEnclosure x = random_dw(rng, e, i % 3 == 0);
    if (i % 7 == 0) x = DWEnclosure::exact(fast_two_sum((rng() % 257) / 256.0, std::ldexp(1.0, -60 - static_cast<int>(rng() % 40))));
    const DWEnclosure y = atan(x);
    BOOST_TEST_REQUIRE(y.finite());
    BOOST_TEST(y.rad <= std::fabs(y.mid.hi) * 0x1p-95 + x.rad * 1.0001);
    for (int w = 0; w < 3; ++w) {
      const mpq_class p = point_of(x, w);
      mpfr_set_q(m, p.get_mpq_t(), MPFR_RNDN);  // exact at 400 bits for these inputs
      mpfr_atan(a, m, MPFR_RNDN);
      mpfr_sub_d(d, a, y.mid.hi, MPFR_RNDN);
      mpfr_sub_d(d, d, y.mid.lo, MPFR_RNDN);
      mpfr_abs(d, d, MPFR_RNDN);
      BOOST_TEST(mpfr_cmp_d(d, y.rad * (1 - 0x1p-60)) <= 0);  // MPFR's own error is ~2^-400
    }
  }
  mpfr_clears(a, m, d, static_cast<mpfr_ptr>(nullptr));
}

BOOST_AUTO_TEST_CASE(atan2_encloses_mpfr) {
  std::mt19937_64 rng(1987);
  mpfr_t a, my, mx, d;
  mpfr_inits2(400, a, my, mx, d, static_cast<mpfr_ptr>(nullptr));
  for (int i = 0; i < 20000; ++i) {
    const int e = static_cast<int>(rng() % 61) - 30;
    const DWEnclosure y = random_dw(rng, e, i % 2 == 0), x0 = random_dw(rng, e + static_cast<int>(rng() % 21) - 10, i % 3 == 0);
    const DWEnclosure x{{std::fabs(x0.mid.hi), x0.mid.hi < 0 ? -x0.mid.lo : x0.mid.lo}, x0.rad};
    const DWEnclosure t = atan2(y, x);
    if (!t.finite()) continue;
    for (int w = 0; w < 9; ++w) {  // the corners, edge midpoints and centre of the box
      const mpq_class py = point_of(y, w % 3), px = point_of(x, w / 3);
      mpfr_set_q(my, py.get_mpq_t(), MPFR_RNDN);
      mpfr_set_q(mx, px.get_mpq_t(), MPFR_RNDN);
      mpfr_atan2(a, my, mx, MPFR_RNDN);
      mpfr_sub_d(d, a, t.mid.hi, MPFR_RNDN);
      mpfr_sub_d(d, d, t.mid.lo, MPFR_RNDN);
      mpfr_abs(d, d, MPFR_RNDN);
      BOOST_TEST(mpfr_cmp_d(d, t.rad * (1 - 0x1p-60)) <= 0);
    }
  }
  mpfr_clears(a, my, mx, d, static_cast<mpfr_ptr>(nullptr));
}

BOOST_AUTO_TEST_CASE(rounding_decision_at_and_near_midpoints) {
  std::mt19937_64 rng(754);
  mpfr_t v;
  mpfr_init2(v, 53);
  auto nearest = [&](const mpq_class& q) {
    mpfr_set_q(v, q.get_mpq_t(), MPFR_RNDN);
    return mpfr_get_d(v, MPFR_RNDN);
  };
  std::uniform_real_distribution<double> unit(0.5, 4);
  int decided = 0;
  for (int i = 0; i < 20000; ++i) {
    const double d = (rng() % 2 ? -1 : 1) * std::ldexp(unit(rng), static_cast<int>(rng() % 100) - 50);
    const double up = (std::nextafter(d, INFINITY) - d) / 2, down = (d - std::nextafter(d, -INFINITY)) / 2;
    const double offsets[] = {up, -down, up * (1 - 0x1p-40), -down * (1 - 0x1p-40), up * (1 + 0x1p-40), 0,
                              std::ldexp(up, -20)};
    const double off = offsets[i % 7];
    const double lo = std::ldexp(static_cast<double>(rng() % 3) - 1, -200) * std::fabs(d);  // a little beyond
    DWEnclosure x = DWEnclosure::exact(fast_two_sum(d, off));
    x = x + DWEnclosure::exact(lo);
    x.rad = i % 4 == 0 ? 0 : std::ldexp(std::fabs(d), -120 - static_cast<int>(rng() % 20));
    const std::optional<DWRounding> r = round_to_double(x);
    const mpq_class ends[] = {exact(x.mid) - exact(x.rad), exact(x.mid) + exact(x.rad)};
    const double n0 = nearest(ends[0]), n1 = nearest(ends[1]);
    if (r) {
      ++decided;
      BOOST_TEST(r->value == n0);
      BOOST_TEST(r->value == n1);
      BOOST_TEST(exact(r->lo) <= ends[0]);
      BOOST_TEST(exact(r->hi) >= ends[1]);
      BOOST_TEST(abs(exact(r->value) - ends[0]) <= exact(r->bound));
      BOOST_TEST(abs(exact(r->value) - ends[1]) <= exact(r->bound));
    } else {
      BOOST_TEST((n0 != n1 || x.rad > 0 || lo != 0));  // an exact point off a tie is always decided
    }
  }
  BOOST_TEST(decided > 10000);
  // Exact ties: the even neighbour.
  const double one_up = std::nextafter(1.0, 2.0);
  BOOST_TEST(round_to_double(DWEnclosure::exact(fast_two_sum(1.0, 0x1p-53)))->value == 1.0);
  BOOST_TEST(round_to_double(DWEnclosure::exact(fast_two_sum(one_up, 0x1p-53)))->value == std::nextafter(one_up, 2.0));
  BOOST_TEST(!round_to_double(DWEnclosure{{1.0, 0x1p-53}, 0x1p-110}).has_value());
  BOOST_TEST(!round_to_double(DWEnclosure::unbounded()).has_value());
  mpfr_clear(v);
}

BOOST_AUTO_TEST_CASE(truncation_decision_at_and_near_doubles) {
  // Every decision is mpq_get_d's truncation of both exact ends (the same double), and every
  // enclosure whose ends truncate alike away from 0 is decided: the decision is exact.
  std::mt19937_64 rng(755);
  std::uniform_real_distribution<double> unit(0.5, 4);
  int decided = 0;
  for (int i = 0; i < 20000; ++i) {
    const double d = (rng() % 2 ? -1 : 1) * std::ldexp(unit(rng), static_cast<int>(rng() % 100) - 50);
    const double up = std::nextafter(d, INFINITY) - d, down = d - std::nextafter(d, -INFINITY);
    const double offsets[] = {0, up * 0x1p-30, -down * 0x1p-30, up * (1 - 0x1p-40), -down * (1 - 0x1p-40), up / 2, 0};
    const double off = offsets[i % 7];
    const double tiny = std::ldexp(static_cast<double>(rng() % 3) - 1, -200) * std::fabs(d);  // at, above or below
    DWEnclosure x = DWEnclosure::exact(fast_two_sum(d, off));
    x = x + DWEnclosure::exact(tiny);
    x.rad = i % 4 == 0 ? 0 : std::ldexp(std::fabs(d), -100 - static_cast<int>(rng() % 40));
    const mpq_class ends[] = {exact(x.mid) - exact(x.rad), exact(x.mid) + exact(x.rad)};
    const double t0 = mpq_get_d(ends[0].get_mpq_t()), t1 = mpq_get_d(ends[1].get_mpq_t());
    const std::optional<double> t = truncate_to_double(x);
    BOOST_TEST(t.has_value() == (t0 == t1));
    if (t) {
      ++decided;
      BOOST_TEST(*t == t0);
    }
  }
  BOOST_TEST(decided > 10000);
  BOOST_TEST(*truncate_to_double(DWEnclosure::exact(0.0)) == 0.0);
  BOOST_TEST(!truncate_to_double(DWEnclosure{{0.0, 0.0}, 0x1p-100}).has_value());  // may be either side of 0
  BOOST_TEST(!truncate_to_double(DWEnclosure::unbounded()).has_value());
  BOOST_TEST(*truncate_to_double(DWEnclosure{{1.0, -0x1p-80}, 0}) == std::nextafter(1.0, 0.0));
  BOOST_TEST(*truncate_to_double(DWEnclosure{{-1.0, 0x1p-80}, 0}) == -std::nextafter(1.0, 0.0));
}

BOOST_AUTO_TEST_CASE(integers_are_enclosed) {
  // dw_integer(z, E) contains z·2^-E exactly, its radius within 2^-100 relative, for integers of
  // 1 to 1200 bits (at most 53: exact), of either sign; out of range: nothing.
  gmp_randclass random(gmp_randinit_mt);
  random.seed(756);
  std::mt19937_64 rng(756);
  for (int i = 0; i < 5000; ++i) {
    mpz_class z = random.get_z_bits(1 + rng() % 1200);
    if (rng() % 2) z = -z;
    const long bits = static_cast<long>(mpz_sizeinbase(z.get_mpz_t(), 2));
    const long E = bits + static_cast<long>(rng() % 1200) - 600;
    const std::optional<DWEnclosure> x = dw_integer(z.get_mpz_t(), E);
    if (sgn(z) != 0 && (bits - E > 900 || bits - E < -900)) {
      BOOST_TEST(!x.has_value());
      continue;
    }
    BOOST_TEST_REQUIRE(x.has_value());
    mpq_class v(z);
    if (E >= 0) v /= mpq_class(mpz_class(1) << static_cast<unsigned long>(E));
    else v *= mpq_class(mpz_class(1) << static_cast<unsigned long>(-E));
    BOOST_TEST(contains(*x, v));
    BOOST_TEST(x->rad <= std::fabs(x->mid.hi) * 0x1p-100);
    if (bits <= 53) BOOST_TEST((exact(x->mid) == v));  // a double: exact
  }
}

BOOST_AUTO_TEST_SUITE_END()
