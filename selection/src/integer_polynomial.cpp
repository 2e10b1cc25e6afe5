#include "internal/integer_polynomial.h"

#include <gmcc/geometry/integers_over_lcm.h>

#include <utility>

namespace gmcc::internal {

void trim(IntegerPolynomial& p) {
  while (!p.empty() && sgn(p.back()) == 0) p.pop_back();
}

IntegerPolynomial add(IntegerPolynomial a, const IntegerPolynomial& b) {
  if (a.size() < b.size()) a.resize(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
  trim(a);
  return a;
}

IntegerPolynomial sub(IntegerPolynomial a, const IntegerPolynomial& b) {
  if (a.size() < b.size()) a.resize(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) a[i] -= b[i];
  trim(a);
  return a;
}

IntegerPolynomial scaled(IntegerPolynomial a, const mpz_class& k) {
  for (mpz_class& x : a) x *= k;
  trim(a);
  return a;
}

IntegerPolynomial mul(const IntegerPolynomial& a, const IntegerPolynomial& b) {
  if (a.empty() || b.empty()) return {};
  IntegerPolynomial r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}

IntegerPolynomial derivative(const IntegerPolynomial& p) {
  IntegerPolynomial d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<unsigned long>(i));
  trim(d);
  return d;
}

bool no_root_in_open_unit_interval(const IntegerPolynomial& p) {
  IntegerPolynomial r(p.rbegin(), p.rend());  // t^d · p(1/t)
  const std::size_t d = r.size() - 1;
  for (std::size_t i = 0; i < d; ++i)  // r(x) → r(x + 1)
    for (std::size_t j = d; j-- > i;) r[j] += r[j + 1];
  int last = 0;
  for (const mpz_class& c : r) {
    const int sc = sgn(c);
    if (sc == 0) continue;
    if (last != 0 && sc != last) return false;
    last = sc;
  }
  return true;
}

IntegerPolynomial primitive(IntegerPolynomial p) {
  divide_by_content(p);
  return p;
}

IntegerPolynomial pseudo_remainder(IntegerPolynomial a, const IntegerPolynomial& b) {
  const mpz_class lb = abs(b.back());
  const int sign_lb = sgn(b.back());
  while (!a.empty() && a.size() >= b.size()) {
    const std::size_t shift = a.size() - b.size();
    const mpz_class la = sign_lb > 0 ? a.back() : mpz_class(-a.back());
    for (mpz_class& c : a) c *= lb;
    for (std::size_t i = 0; i < b.size(); ++i) a[i + shift] -= la * b[i];
    a.pop_back();  // its coefficient is now exactly 0
    trim(a);
  }
  return a;
}

IntegerPolynomial polynomial_gcd(IntegerPolynomial a, IntegerPolynomial b) {
  while (!b.empty()) {
    IntegerPolynomial r = primitive(pseudo_remainder(a, b));
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}

IntegerPolynomial exact_quotient(IntegerPolynomial a, const IntegerPolynomial& b) {
  IntegerPolynomial q(a.size() - b.size() + 1);
  for (std::size_t shift = q.size(); shift-- > 0;) {
    mpz_class k;
    mpz_divexact(k.get_mpz_t(), a[shift + b.size() - 1].get_mpz_t(), b.back().get_mpz_t());
    for (std::size_t i = 0; i < b.size(); ++i) a[i + shift] -= k * b[i];
    q[shift] = std::move(k);
  }
  return q;
}

IntegerPolynomial square_free_part(const IntegerPolynomial& p) {
  const IntegerPolynomial pz = primitive(p);
  return primitive(exact_quotient(pz, primitive(polynomial_gcd(pz, derivative(pz)))));
}

int sign_at(const IntegerPolynomial& p, const Rational& t) {
  if (p.empty()) return 0;
  const mpz_class& a = t.get_num();
  const mpz_class& b = t.get_den();
  // Horner on the homogeneous form: r ← r·a + c_i·b^(d−i), from i = d − 1 down to 0.
  mpz_class r = p.back(), b_power = 1;
  for (std::size_t i = p.size() - 1; i-- > 0;) {
    b_power *= b;
    r = r * a + p[i] * b_power;
  }
  return sgn(r);
}

std::vector<IntegerPolynomial> sturm_sequence(const IntegerPolynomial& s) {
  std::vector<IntegerPolynomial> chain{s, primitive(derivative(s))};
  for (;;) {  // positive scalings keep a Sturm sequence's signs
    IntegerPolynomial r = primitive(pseudo_remainder(chain[chain.size() - 2], chain.back()));
    if (r.empty()) break;
    for (mpz_class& c : r) c = -c;
    chain.push_back(std::move(r));
  }
  return chain;
}

int sign_variations(const std::vector<IntegerPolynomial>& chain, const Rational& t) {
  int count = 0, last = 0;
  for (const IntegerPolynomial& p : chain) {
    const int s = sign_at(p, t);
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

namespace {

// One simple root of s in (lo, hi], refined by bisection on the sign of s alone to width ≤
// `width`, or hit exactly. Just right of lo, s has the sign of s(lo), or of s′(lo) where lo is
// itself a (simple) root of s.
RootInterval refine(const IntegerPolynomial& s, const IntegerPolynomial& ds, Rational lo, Rational hi,
                    const Rational& width) {
  int sign_lo = sign_at(s, lo);
  if (sign_lo == 0) sign_lo = sign_at(ds, lo);
  bool exact = false;
  while (hi - lo > width) {
    if (sign_at(s, hi) == 0) {
      exact = true;
      break;
    }
    Rational mid = (lo + hi) / 2;
    const int sign_mid = sign_at(s, mid);
    if (sign_mid == 0) {
      hi = std::move(mid);
      exact = true;
      break;
    }
    (sign_mid == sign_lo ? lo : hi) = std::move(mid);
  }
  return {std::move(lo), std::move(hi), exact};
}

}  // namespace

std::vector<RootInterval> isolate_roots_in_unit_interval(const IntegerPolynomial& p, const Rational& width) {
  const IntegerPolynomial s = square_free_part(p);
  if (s.size() < 2) return {};
  const std::vector<IntegerPolynomial> chain = sturm_sequence(s);
  struct Piece {
    Rational lo, hi;
    int v_lo, v_hi;
  };
  std::vector<Piece> todo{{Rational(0), Rational(1), sign_variations(chain, Rational(0)),
                           sign_variations(chain, Rational(1))}};
  std::vector<RootInterval> roots;
  while (!todo.empty()) {
    Piece piece = std::move(todo.back());
    todo.pop_back();
    const int count = piece.v_lo - piece.v_hi;
    if (count == 0) continue;
    if (count == 1) {
      roots.push_back(refine(s, chain[1], std::move(piece.lo), std::move(piece.hi), width));
      continue;
    }
    Rational mid = (piece.lo + piece.hi) / 2;
    const int v_mid = sign_variations(chain, mid);
    todo.push_back({piece.lo, mid, piece.v_lo, v_mid});
    todo.push_back({std::move(mid), piece.hi, v_mid, piece.v_hi});
  }
  return roots;
}

std::vector<Rational> roots_in_unit_interval(const IntegerPolynomial& p) {
  std::vector<Rational> out;
  for (RootInterval& r : isolate_roots_in_unit_interval(p, Rational(1) >> 100)) out.push_back(std::move(r.hi));
  return out;
}

}  // namespace gmcc::internal
