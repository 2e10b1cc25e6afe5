// Fuzz target: gmcc::parse_rational, the one boundary where text becomes exact.
// Every input must either parse or throw std::invalid_argument with a one-line message of
// bounded length. What parses must be canonical, survive the round trip through to_string, obey
// the sign rules, and, for decimals, round to the same double as glibc's strtod (both correctly
// rounded, so they must agree bit for bit).

#include "fuzz_support.h"

#include <gmcc/geometry/rational.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

using gmcc::Rational;

namespace {

std::size_t digits_of(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c >= '0' && c <= '9';
  return n;
}

// Parse, or the message of the std::invalid_argument thrown (anything else escapes: a finding).
bool parses(std::string_view text, Rational& out, std::string& message) {
  try {
    out = gmcc::parse_rational(text);
    return true;
  } catch (const std::invalid_argument& e) {
    message = e.what();
    return false;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Rational r;
  std::string message;
  if (!parses(text, r, message)) {
    FUZZ_CHECK(!message.empty(), "an empty message");
    FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line");
    FUZZ_CHECK(message.size() <= 300, "a message of " + std::to_string(message.size()) + " bytes");
    return 0;
  }
  FUZZ_CHECK(text.size() >= 1, "empty text parsed");

  // Canonical: q > 0 and gcd(p, q) = 1.
  FUZZ_CHECK(sgn(r.get_den()) > 0, "denominator <= 0");
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), r.get_num_mpz_t(), r.get_den_mpz_t());
  FUZZ_CHECK(g == 1, "not in lowest terms");

  // Round trip: the canonical text holds the same value (read by GMP; and by parse_rational
  // itself when it is within max_number_digits).
  const std::string canonical = gmcc::to_string(r);
  Rational back;
  FUZZ_CHECK(back.set_str(canonical, 10) == 0, "to_string gave text GMP cannot read: " + canonical);
  back.canonicalize();
  FUZZ_CHECK(back == r, "to_string does not round-trip");
  if (digits_of(canonical) <= gmcc::max_number_digits) {
    Rational again;
    FUZZ_CHECK(parses(canonical, again, message), "canonical text rejected: " + message);
    FUZZ_CHECK(again == r, "parse_rational(to_string(x)) != x for " + canonical);
    FUZZ_CHECK(gmcc::to_string(again) == canonical, "canonical text is not a fixed point");
  }

  // Signs: an explicit sign on unsigned text.
  if (text[0] != '+' && text[0] != '-') {
    Rational plus, minus;
    FUZZ_CHECK(parses("+" + text, plus, message) && plus == r, "'+x' != x");
    FUZZ_CHECK(parses("-" + text, minus, message) && minus == -r, "'-x' != -x");
  }

  // Decimals: the nearest double agrees with strtod (glibc rounds correctly, subnormals too).
  // Compared as numbers: strtod keeps the sign of "-0", a rational has none.
  if (text.find('/') == std::string::npos) {
    const double expected = std::strtod(text.c_str(), nullptr);
    const double got = gmcc::to_double_nearest(r);
    FUZZ_CHECK(expected == got, "to_double_nearest(" + text + ") differs from strtod");
  }
  return 0;
}
