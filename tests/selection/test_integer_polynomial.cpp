// The ℤ[t] toolkit and its Sturm root isolation (selection/src/internal/integer_polynomial.h),
// checked on polynomials built from known rational roots: the roots are the independent answer.
#include "../test_support.h"

#include "internal/integer_polynomial.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <set>
#include <vector>

using namespace gmcc;
using namespace gmcc::internal;
using gmcc::test::Rng;
using gmcc::test::random_rational;

namespace {

// p(t) in ℚ by Horner: an evaluation that shares nothing with sign_at's homogeneous form.
Rational value_at(const IntegerPolynomial& p, const Rational& t) {
  Rational v = 0;
  for (std::size_t i = p.size(); i-- > 0;) v = v * t + Rational(p[i]);
  return v;
}

// b·t − a for the root a/b (b > 0).
IntegerPolynomial linear(const Rational& r) { return {mpz_class(-r.get_num()), r.get_den()}; }

// A product of linear factors with the given roots (repeats make multiple roots), times k ≠ 0
// and, when `complex_pair`, t² + 1 (two roots that are not real).
IntegerPolynomial with_roots(const std::vector<Rational>& roots, long k, bool complex_pair) {
  IntegerPolynomial p{mpz_class(k)};
  for (const Rational& r : roots) p = mul(p, linear(r));
  if (complex_pair) p = mul(p, {1, 0, 1});
  return p;
}

// Random roots in [-1/2, 3/2] on a grid (so repeats occur, and 0 and 1 are drawn), with random
// multiplicities; about n of them before repeats.
std::vector<Rational> random_roots(Rng& rng, int n) {
  std::vector<Rational> roots;
  std::uniform_int_distribution<int> mult(1, 3), pick(0, 4);
  for (int i = 0; i < n; ++i) {
    const Rational r = pick(rng) == 0 ? Rational(pick(rng) % 2) : random_rational(rng, -6, 18, 12);
    for (int m = mult(rng); m > 0; --m) roots.push_back(r);
  }
  return roots;
}

std::set<Rational> distinct_in(const std::vector<Rational>& roots, const Rational& lo, const Rational& hi) {
  std::set<Rational> out;
  for (const Rational& r : roots)
    if (r > lo && r <= hi) out.insert(r);
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(integer_polynomial)

BOOST_AUTO_TEST_CASE(arithmetic_agrees_with_evaluation_in_q) {
  Rng rng(29);
  std::uniform_int_distribution<long> coef(-50, 50);
  for (int trial = 0; trial < 200; ++trial) {
    IntegerPolynomial a(1 + trial % 5), b(1 + trial % 3);
    for (mpz_class& c : a) c = coef(rng);
    for (mpz_class& c : b) c = coef(rng);
    trim(a), trim(b);
    const Rational t = random_rational(rng, -30, 30, 7), k = 3;
    BOOST_TEST(value_at(add(a, b), t) == value_at(a, t) + value_at(b, t));
    BOOST_TEST(value_at(sub(a, b), t) == value_at(a, t) - value_at(b, t));
    BOOST_TEST(value_at(mul(a, b), t) == value_at(a, t) * value_at(b, t));
    BOOST_TEST(value_at(scaled(a, 3), t) == k * value_at(a, t));
    BOOST_TEST(sign_at(a, t) == sgn(value_at(a, t)));
    BOOST_TEST((sub(a, a).empty() && scaled(a, 0).empty()));  // the zero polynomial is empty
    // (a·b)' = a'b + ab', from the coefficients' rule alone.
    BOOST_TEST((derivative(mul(a, b)) == add(mul(derivative(a), b), mul(a, derivative(b)))));
  }
}

BOOST_AUTO_TEST_CASE(division_gcd_and_square_free_part) {
  Rng rng(7);
  for (int trial = 0; trial < 150; ++trial) {
    const std::vector<Rational> ra = random_roots(rng, 1 + trial % 3), rb = random_roots(rng, 1 + trial % 2);
    const IntegerPolynomial a = primitive(with_roots(ra, 1, trial % 2 == 0));
    const IntegerPolynomial b = primitive(with_roots(rb, 1, false));
    BOOST_TEST((exact_quotient(mul(a, b), b) == a));
    // k·(a·b + r) mod b = k·r for deg r < deg b: the remainder is a positive multiple of r's.
    IntegerPolynomial r{mpz_class(trial % 5 + 1)};
    const IntegerPolynomial rem = pseudo_remainder(add(mul(a, b), r), b);
    BOOST_TEST((rem.size() == 1 && sgn(rem[0]) > 0 && mpz_divisible_p(rem[0].get_mpz_t(), r[0].get_mpz_t())));
    // gcd(a, b) vanishes exactly at the common roots (up to a constant factor).
    const IntegerPolynomial g = polynomial_gcd(a, b);
    for (const Rational& x : ra) BOOST_TEST((sign_at(g, x) == 0) == (std::count(rb.begin(), rb.end(), x) > 0));
    // The square-free part has each distinct root once: degree = distinct real roots (+ 2 for t² + 1).
    const IntegerPolynomial s = square_free_part(a);
    const std::set<Rational> distinct(ra.begin(), ra.end());
    BOOST_TEST(s.size() - 1 == distinct.size() + (trial % 2 == 0 ? 2 : 0));
    for (const Rational& x : distinct) BOOST_TEST(sign_at(s, x) == 0);
  }
}

BOOST_AUTO_TEST_CASE(sturm_counts_distinct_roots) {
  Rng rng(11);
  for (int trial = 0; trial < 150; ++trial) {
    const std::vector<Rational> roots = random_roots(rng, 1 + trial % 4);
    const IntegerPolynomial p = with_roots(roots, trial % 3 == 0 ? -5 : 2, trial % 2 == 1);
    const std::vector<IntegerPolynomial> chain = sturm_sequence(square_free_part(p));
    auto count = [&](const Rational& lo, const Rational& hi) {
      return sign_variations(chain, lo) - sign_variations(chain, hi);
    };
    // The whole line (every root lies in [-1/2, 3/2]), random windows, and windows whose ends are
    // roots: (lo, hi] counts hi and not lo.
    BOOST_TEST(count(-1000, 1000) == static_cast<int>(distinct_in(roots, -1000, 1000).size()));
    for (int w = 0; w < 5; ++w) {
      Rational lo = random_rational(rng, -8, 20, 12), hi = random_rational(rng, -8, 20, 12);
      if (lo > hi) std::swap(lo, hi);
      BOOST_TEST(count(lo, hi) == static_cast<int>(distinct_in(roots, lo, hi).size()));
    }
    const Rational& r = roots.front();
    BOOST_TEST(count(r, r + 1) == static_cast<int>(distinct_in(roots, r, r + 1).size()));
    BOOST_TEST(count(r - 1, r) == static_cast<int>(distinct_in(roots, r - 1, r).size()));
  }
}

BOOST_AUTO_TEST_CASE(isolating_intervals_hold_one_root_each) {
  Rng rng(13);
  for (int trial = 0; trial < 150; ++trial) {
    const std::vector<Rational> roots = random_roots(rng, 1 + trial % 5);
    const IntegerPolynomial p = with_roots(roots, -3, trial % 2 == 0);
    const Rational width = Rational(1) >> (trial % 3 == 0 ? 100 : 10);
    const std::vector<RootInterval> iv = isolate_roots_in_unit_interval(p, width);
    const std::set<Rational> wanted = distinct_in(roots, 0, 1);
    BOOST_TEST(iv.size() == wanted.size());
    std::set<Rational> found;
    for (const RootInterval& x : iv) {
      BOOST_TEST((x.lo < x.hi && x.lo >= 0 && x.hi <= 1));
      const std::set<Rational> inside = distinct_in(roots, x.lo, x.hi);
      BOOST_TEST(inside.size() == 1u);
      if (inside.size() == 1) found.insert(*inside.begin());
      BOOST_TEST((x.hi - x.lo <= width || x.exact));
      if (x.exact) BOOST_TEST(sign_at(p, x.hi) == 0);
    }
    BOOST_TEST((found == wanted));  // every root in (0, 1] once
    std::vector<RootInterval> sorted = iv;
    std::sort(sorted.begin(), sorted.end(), [](const RootInterval& a, const RootInterval& b) { return a.lo < b.lo; });
    for (std::size_t k = 1; k < sorted.size(); ++k) BOOST_TEST(sorted[k - 1].hi <= sorted[k].lo);  // disjoint
    const std::vector<Rational> ends = roots_in_unit_interval(p);
    BOOST_TEST(ends.size() == wanted.size());
  }
  BOOST_TEST(isolate_roots_in_unit_interval({5}, Rational(1, 8)).empty());  // a constant: none
}

BOOST_AUTO_TEST_CASE(descartes_test_is_exact_on_real_rooted_polynomials) {
  // With every root real, (1 + u)^d·p(1/(1 + u)) has every root at u ≤ 0, so its coefficients
  // have no sign variation exactly when no root lies in (0, 1); with one inside there is one.
  Rng rng(17);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<Rational> roots = random_roots(rng, 1 + trial % 4);
    const IntegerPolynomial p = with_roots(roots, trial % 2 ? 1 : -4, false);
    const bool none_inside = std::none_of(roots.begin(), roots.end(), [](const Rational& r) { return r > 0 && r < 1; });
    BOOST_TEST(no_root_in_open_unit_interval(p) == none_inside);
    // t² + 1 has no real root but makes the test inconclusive at worst: never a wrong "none".
    if (!none_inside) BOOST_TEST(!no_root_in_open_unit_interval(with_roots(roots, 1, true)));
  }
}

BOOST_AUTO_TEST_SUITE_END()
