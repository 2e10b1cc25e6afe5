#pragma once
/// \file rational.h
/// The one boundary where text or floating-point data becomes exact (docs/conventions.md §1).

#include <gmpxx.h>

#include <string>
#include <string_view>

namespace gmcc {

/// An exact rational number (GMP), always kept in canonical (reduced) form.
using Rational = mpq_class;

/// Largest decimal exponent accepted by parse_rational (|e| in `1.5e-3`). Every double's exponent
/// (to 308, subnormals to -324) fits with room. An exponent writes a long number in a few
/// characters (4e3619 is an integer of 3620 digits), and exact arithmetic grows with the length:
/// a triangle with vertices near 4e361 and 4e3619 took 6 s (the fuzz target for `gmcc select`
/// found such inputs), at exponents up to 400 it takes 0.03 s.
inline constexpr long max_decimal_exponent = 400;

/// Most digits accepted in one number: those of the mantissa (integer and fraction digits,
/// leading zeros included), or of p and q together; exponent digits are bounded by
/// max_decimal_exponent instead. Exact arithmetic grows with the numbers' lengths (a feasible set
/// from 100-digit inputs has vertices of thousands of digits, and the illuminant worst case
/// works on polynomials in them), so a limit keeps every run short. 100 digits write every
/// double from 1e-13 to 1e16 exactly in decimal, and every double from 1e-65 to 1e80 exactly
/// as p/q.
inline constexpr std::size_t max_number_digits = 100;

/// Parse decimal or fraction text *exactly*: `0.1` is 1/10, `-2.5e-3` is -1/400, `3/7` is 3/7.
/// Grammar: [+-]digits[.digits][(e|E)[+-]digits] or [+-]digits/digits (a leading `.5` and a
/// trailing `5.` are accepted). No surrounding white space, no hexadecimal.
/// \throws std::invalid_argument with a message a person can act on (NaN, infinity, `p/0`,
///         malformed text, more than max_number_digits digits, exponent beyond
///         max_decimal_exponent). Messages quote at most the first 40 characters of the text,
///         with bytes outside printable ASCII written as \\xNN.
Rational parse_rational(std::string_view text);

/// `text` as messages quote it: in single quotes, at most its first 40 characters, bytes outside
/// printable ASCII as \\xNN, and the full length when cut, so that binary garbage or a
/// megabyte-long field gives a one-line message.
std::string quoted_text(std::string_view text);

/// The exact value of a finite double (every double is a dyadic rational).
/// \throws std::invalid_argument for NaN or infinity.
Rational rational_from_double(double value);

/// Canonical text of a rational: `p/q` in lowest terms with q > 0, or `p` when q = 1.
std::string to_string(const Rational& value);

/// The double nearest to an exact rational (round to nearest, ties to even; via MPFR), with one
/// rounding also where the result is subnormal. Unlike mpq_get_d, which truncates, this is
/// correctly rounded; beyond the largest double it is ±infinity.
double to_double_nearest(const Rational& value);

/// The long double nearest to an exact rational (round to nearest, ties to even, subnormals
/// included; via MPFR at the long double's precision, 64 bits on x86_64).
long double to_long_double_nearest(const Rational& value);

}  // namespace gmcc
