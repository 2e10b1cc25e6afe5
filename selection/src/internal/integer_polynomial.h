#pragma once
// Exact polynomials over ℤ in one variable t, and their real roots in (0, 1] by Sturm sequences:
// the algebra of the illuminant worst case's edge quartics (docs/math.md §3, "Worst case
// (illuminant space)"). Internal to gmcc::selection; tests/selection/test_integer_polynomial.cpp.
//
// Integer coefficients throughout: over ℚ every operation reduces a fraction by a gcd, and
// Euclid's remainders grow numerators and denominators at every step; on feasible sets with long
// exact vertices (inputs of 50 digits and more) that cost seconds to minutes per edge. The degrees
// met here are at most 5, so plain loops suffice (no fast multiplication).

#include <gmcc/geometry/rational.h>

#include <vector>

namespace gmcc::internal {

/// Coefficients, constant term first, no trailing zeros: the zero polynomial is empty.
using IntegerPolynomial = std::vector<mpz_class>;

/// Drops trailing zero coefficients (the canonical form above).
void trim(IntegerPolynomial& p);
/// a + b.
IntegerPolynomial add(IntegerPolynomial a, const IntegerPolynomial& b);
/// a − b.
IntegerPolynomial sub(IntegerPolynomial a, const IntegerPolynomial& b);
/// k·a.
IntegerPolynomial scaled(IntegerPolynomial a, const mpz_class& k);
/// a·b, schoolbook: O(deg a · deg b).
IntegerPolynomial mul(const IntegerPolynomial& a, const IntegerPolynomial& b);
/// p′.
IntegerPolynomial derivative(const IntegerPolynomial& p);
/// p divided by its content, the gcd of its coefficients (> 0): the same signs everywhere.
IntegerPolynomial primitive(IntegerPolynomial p);
/// k·a mod b for some integer k > 0 (b ≠ 0): pseudo-division, each step scaling a by |lc(b)| so
/// that no division is needed; k > 0 keeps a Sturm sequence's signs.
IntegerPolynomial pseudo_remainder(IntegerPolynomial a, const IntegerPolynomial& b);
/// A gcd of a and b, up to a non-zero constant factor: the primitive remainder sequence.
IntegerPolynomial polynomial_gcd(IntegerPolynomial a, IntegerPolynomial b);
/// a / b, when b divides a in ℤ[t] (a and b primitive: by Gauss's lemma the quotient then has
/// integer coefficients, so every step divides exactly).
IntegerPolynomial exact_quotient(IntegerPolynomial a, const IntegerPolynomial& b);
/// The square-free part p / gcd(p, p′), primitive: the distinct roots of p ≠ 0, each simple.
IntegerPolynomial square_free_part(const IntegerPolynomial& p);

/// The sign (−1, 0, 1) of p at t, from the homogeneous form Σ c_i a^i b^(d−i) with t = a/b,
/// b > 0: integer arithmetic only, no rational normalisation.
int sign_at(const IntegerPolynomial& p, const Rational& t);

/// True when p ≠ 0 certainly has no root in the open interval (0, 1): the coefficients of
/// (1 + u)^d · p(1/(1 + u)), d = deg p, have no sign variation. t = 1/(1 + u) maps u ∈ (0, ∞)
/// onto t ∈ (0, 1), and by Descartes' rule of signs a polynomial has at most as many positive
/// roots (with multiplicity) as sign variations in its coefficients (Basu, Pollack & Roy,
/// "Algorithms in Real Algebraic Geometry", Thm 2.33). False says nothing. A Taylor shift: O(d²)
/// additions, against the Sturm sequence's multiplications of ever longer numbers.
bool no_root_in_open_unit_interval(const IntegerPolynomial& p);

/// The Sturm sequence of a square-free s of degree ≥ 1: s, s′, then the negated remainders, each
/// made primitive (positive scalings keep a Sturm sequence's signs), up to the last non-zero one.
std::vector<IntegerPolynomial> sturm_sequence(const IntegerPolynomial& s);

/// Sign variations of a Sturm sequence at t, zeros skipped. By Sturm's theorem the number of
/// distinct roots of s in (lo, hi] is V(lo) − V(hi), also when lo or hi is a root (Basu, Pollack
/// & Roy, Thm 2.50 and its proof).
int sign_variations(const std::vector<IntegerPolynomial>& chain, const Rational& t);

/// A half-open interval (lo, hi] holding exactly one root of a polynomial; `exact` when hi is
/// known to be the root itself (a bisection point, or the interval's end, hit it).
struct RootInterval {
  Rational lo, hi;
  bool exact = false;
};

/// The distinct real roots of p ≠ 0 in (0, 1], isolated: disjoint intervals (lo, hi] of width
/// ≤ `width`, or whose hi is the root. Sturm's theorem on the square-free part splits (0, 1] by
/// exact bisection until each piece holds one root, then bisection on the sign of the square-free
/// part refines it (docs/math.md §3). Depth-first, the upper half of a split first.
std::vector<RootInterval> isolate_roots_in_unit_interval(const IntegerPolynomial& p, const Rational& width);

/// The distinct real roots of p ≠ 0 in (0, 1], each as an exact rational: the root itself when a
/// bisection point hits it, otherwise the right end of an interval (lo, hi] of width ≤ 2^-100
/// holding exactly one root (isolate_roots_in_unit_interval's hi, in its order).
std::vector<Rational> roots_in_unit_interval(const IntegerPolynomial& p);

}  // namespace gmcc::internal
