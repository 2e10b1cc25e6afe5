#pragma once
/// \file integers_over_lcm.h
/// Rationals as integers over one common denominator, and integers divided by their content: the
/// step every exact predicate and constraint takes before its integer arithmetic (integer lines
/// and planes, homogeneous points, the exact LP's rows, the illuminant worst case's quartics;
/// docs/conventions.md §1, docs/math.md §1a′ and §3). Scaling by a positive integer changes no
/// sign, no half-space and no root, and integers need no gcd per operation after it.

#include <gmcc/geometry/rational.h>

#include <array>
#include <functional>
#include <vector>

namespace gmcc {

/// l ← lcm(l, den(x)): one more denominator into a running least common multiple (start at 1).
/// O(M(n) log n) in the numbers' length n (GMP's mpz_lcm).
inline void include_denominator(mpz_class& l, const Rational& x) {
  mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
}

/// The least common multiple L ≥ 1 of the denominators of the rationals in xs (1 when empty).
template <class Range>
mpz_class lcm_of_denominators(const Range& xs) {
  mpz_class l = 1;
  for (const Rational& x : xs) include_denominator(l, x);
  return l;
}

/// The least common multiple L ≥ 1 of the denominators of x, y, … (lcm_of_denominators on them).
template <class... R>
mpz_class lcm_of_denominators_of(const R&... xs) {
  return lcm_of_denominators(std::array<std::reference_wrapper<const Rational>, sizeof...(R)>{xs...});
}

/// x·L as an integer, for L a multiple of x's denominator (num(x)·(L / den(x)), exactly).
inline mpz_class times_lcm(const Rational& x, const mpz_class& l) {
  mpz_class k;
  mpz_divexact(k.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  return x.get_num() * k;
}

/// The rationals in xs times the lcm L of their denominators, in order: integers in the same
/// proportions (a positive common factor). L itself when `lcm` is given.
template <class Range>
std::vector<mpz_class> integers_over_lcm(const Range& xs, mpz_class* lcm = nullptr) {
  const mpz_class l = lcm_of_denominators(xs);
  std::vector<mpz_class> out;
  for (const Rational& x : xs) out.push_back(times_lcm(x, l));
  if (lcm) *lcm = l;
  return out;
}

/// The integers in zs (a range of mpz_class lvalues) divided by their content, the gcd of them all,
/// when it exceeds 1: the same signs and proportions, shorter numbers. All zeros stay zeros.
template <class Range>
void divide_by_content(Range&& zs) {
  mpz_class g = 0;
  for (mpz_class& z : zs) mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), z.get_mpz_t());
  if (g > 1)
    for (mpz_class& z : zs) mpz_divexact(z.get_mpz_t(), z.get_mpz_t(), g.get_mpz_t());
}

/// divide_by_content on the integers a, b, … together (say a plane's coefficients and offset).
template <class... Z>
void divide_by_content_of(Z&... zs) {
  divide_by_content(std::array<std::reference_wrapper<mpz_class>, sizeof...(Z)>{zs...});
}

}  // namespace gmcc
