// The one place where text and doubles become exact rationals (docs/conventions.md §1).
#include <gmcc/geometry/point.h>
#include <gmcc/geometry/rational.h>

#include <mpfr.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace gmcc {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

[[noreturn]] void malformed(std::string_view text, const char* why) {
  throw std::invalid_argument(quoted_text(text) + " is not a number: " + why +
                              " (expected a decimal such as 0.25 or 2.5e-3, or a fraction p/q)");
}

// [+-]digits
mpz_class parse_integer(std::string_view text, std::string_view whole, bool allow_sign) {
  std::size_t i = 0;
  bool negative = false;
  if (allow_sign && i < text.size() && (text[i] == '+' || text[i] == '-')) {
    negative = text[i] == '-';
    ++i;
  }
  if (i == text.size()) malformed(whole, "missing digits");
  for (std::size_t j = i; j < text.size(); ++j)
    if (!is_digit(text[j])) malformed(whole, "unexpected character");
  mpz_class z(std::string(text.substr(i)), 10);
  return negative ? mpz_class(-z) : z;
}

}  // namespace

std::string quoted_text(std::string_view text) {
  constexpr std::size_t shown = 40;
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < shown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char hex[] = "0123456789ABCDEF";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  out += "'";
  if (text.size() > shown) out += " (" + std::to_string(text.size()) + " characters)";
  return out;
}

namespace {

// Refuse, before any parsing, a field of more digits (before any exponent) than a number may
// have (in O(length)), and NaN and the infinities by name.
void check_digits_and_specials(std::string_view text) {
  std::size_t digit_count = 0;
  for (char c : text) {
    if (c == 'e' || c == 'E') break;
    digit_count += is_digit(c);
  }
  if (digit_count > max_number_digits)
    throw std::invalid_argument(quoted_text(text) + " has " + std::to_string(digit_count) +
                                " digits: at most " + std::to_string(max_number_digits) +
                                " are accepted in one number");
  const std::string low = lower(text);
  const std::string_view unsigned_low =
      (low[0] == '+' || low[0] == '-') ? std::string_view(low).substr(1) : std::string_view(low);
  if (unsigned_low == "nan")
    throw std::invalid_argument("NaN is not allowed: a colour channel must be a finite number");
  if (unsigned_low == "inf" || unsigned_low == "infinity")
    throw std::invalid_argument("infinity is not allowed: a colour channel must be finite");
}

// sign · digits · 10^power, exactly and reduced (digits: the mantissa's decimal digits).
Rational decimal_value(const std::string& digits, long power, bool negative) {
  // Short decimals (the spectral tables' every number) in machine integers: m/10^k is reduced by
  // removing the factors 2 and 5 it shares with 10^k, the only ones it can share.
  static_assert(sizeof(unsigned long) >= 8, "mpq_set_ui takes the 18-digit mantissa as unsigned long");
  if (digits.size() <= 18 && power <= 0 && power >= -18) {
    std::uint64_t m = 0, d = 1;
    for (char c : digits) m = m * 10 + static_cast<std::uint64_t>(c - '0');
    for (long k = 0; k < -power; ++k) d *= 10;
    if (m == 0) d = 1;
    while (d % 2 == 0 && m % 2 == 0) m /= 2, d /= 2;
    while (d % 5 == 0 && m % 5 == 0) m /= 5, d /= 5;
    Rational r;
    mpq_set_ui(r.get_mpq_t(), static_cast<unsigned long>(m), static_cast<unsigned long>(d));
    if (negative) mpq_neg(r.get_mpq_t(), r.get_mpq_t());
    return r;
  }
  mpz_class mantissa(digits, 10);
  if (negative) mantissa = -mantissa;
  mpz_class scale;
  mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(power < 0 ? -power : power));
  Rational r = power >= 0 ? Rational(mantissa * scale) : Rational(mantissa, scale);
  r.canonicalize();
  return r;
}

}  // namespace

Rational parse_rational(std::string_view text) {
  if (text.empty()) malformed(text, "empty field");
  check_digits_and_specials(text);

  if (const auto slash = text.find('/'); slash != std::string_view::npos) {
    const mpz_class p = parse_integer(text.substr(0, slash), text, true);
    const mpz_class q = parse_integer(text.substr(slash + 1), text, false);
    if (q == 0) throw std::invalid_argument(quoted_text(text) + " divides by zero");
    Rational r(p, q);
    r.canonicalize();
    return r;
  }

  // Decimal: sign, integer digits, optional fraction, optional exponent.
  std::size_t i = 0;
  bool negative = false;
  if (text[i] == '+' || text[i] == '-') {
    negative = text[i] == '-';
    ++i;
  }
  std::string digits;  // all mantissa digits, decimal point removed
  long fraction_digits = 0;
  bool seen_digit = false;
  while (i < text.size() && is_digit(text[i])) digits += text[i++], seen_digit = true;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && is_digit(text[i])) digits += text[i++], ++fraction_digits,
                                                  seen_digit = true;
  }
  if (!seen_digit) malformed(text, "missing digits");
  long exponent = 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) exp_negative = text[i++] == '-';
    if (i == text.size() || !is_digit(text[i])) malformed(text, "missing exponent digits");
    while (i < text.size() && is_digit(text[i])) {
      exponent = exponent * 10 + (text[i++] - '0');
      if (exponent > max_decimal_exponent)
        throw std::invalid_argument(quoted_text(text) + ": exponent beyond ±" +
                                    std::to_string(max_decimal_exponent) + " is not supported");
    }
    if (exp_negative) exponent = -exponent;
  }
  if (i != text.size()) malformed(text, "unexpected character");
  // |power| <= max_decimal_exponent + max_number_digits: both were checked above.
  const long power = exponent - fraction_digits;

  return decimal_value(digits, power, negative);
}

Rational rational_from_double(double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("a non-finite double has no exact value");
  Rational r;
  mpq_set_d(r.get_mpq_t(), value);  // exact: a double is a dyadic rational
  return r;
}

std::string to_string(const Rational& value) { return value.get_str(10); }

namespace {
// q rounded to nearest in the floating type F, subnormals included. MPFR's documented emulation
// of a binary format: its exponent range set to F's, then mpfr_subnormalize. Rounding to F's
// precision and then to the subnormal grid would round twice: a value just below a subnormal
// midpoint becomes the midpoint, then goes to even (caught by the strtod check of
// fuzz/fuzz_parse_rational).
template <class F>
F nearest(const Rational& q, F (*get)(mpfr_srcptr, mpfr_rnd_t)) {
  using limits = std::numeric_limits<F>;
  const mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
  // MPFR writes x = m·2^e with 1/2 <= |m| < 1; the smallest subnormal is 2^(min_exponent − digits).
  mpfr_set_emin(limits::min_exponent - limits::digits + 1);
  mpfr_set_emax(limits::max_exponent);
  mpfr_t x;
  mpfr_init2(x, limits::digits);
  const int inexact = mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
  mpfr_subnormalize(x, inexact, MPFR_RNDN);
  const F value = get(x, MPFR_RNDN);  // exact: x is representable in F
  mpfr_clear(x);
  mpfr_set_emin(emin);
  mpfr_set_emax(emax);
  return value;
}
}  // namespace

double to_double_nearest(const Rational& value) { return nearest<double>(value, mpfr_get_d); }

long double to_long_double_nearest(const Rational& value) {
  return nearest<long double>(value, mpfr_get_ld);
}

std::array<double, 2> to_double_nearest(const Point2& p) {
  return {to_double_nearest(p.x), to_double_nearest(p.y)};
}

}  // namespace gmcc
