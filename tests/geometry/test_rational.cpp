#include <gmcc/geometry/rational.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <stdexcept>

using gmcc::parse_rational;
using gmcc::Rational;

BOOST_AUTO_TEST_SUITE(rational)

BOOST_AUTO_TEST_CASE(decimal_text_is_read_exactly) {
  BOOST_TEST(parse_rational("0.1") == Rational(1, 10));
  BOOST_TEST(parse_rational("0.1") != gmcc::rational_from_double(0.1));
  BOOST_TEST(parse_rational("-2.5e-3") == Rational(-1, 400));
  BOOST_TEST(parse_rational("1E2") == Rational(100));
  BOOST_TEST(parse_rational(".5") == Rational(1, 2));
  BOOST_TEST(parse_rational("5.") == Rational(5));
  BOOST_TEST(parse_rational("+007.250") == Rational(29, 4));
  BOOST_TEST(parse_rational("123456789012345678901234567890") ==
             Rational(mpz_class("123456789012345678901234567890")));
}

BOOST_AUTO_TEST_CASE(fractions_are_reduced) {
  const Rational r = parse_rational("6/4");
  BOOST_TEST(r == Rational(3, 2));
  BOOST_TEST(gmcc::to_string(r) == "3/2");
  BOOST_TEST(gmcc::to_string(parse_rational("8/4")) == "2");
  BOOST_TEST(parse_rational("-3/9") == Rational(-1, 3));
}

BOOST_AUTO_TEST_CASE(bad_text_is_rejected_with_a_reason) {
  for (const char* bad : {"", "abc", "1.2.3", "1/0", "nan", "NaN", "-inf", "Infinity", "1e",
                          "1e+", "--1", "1/-2", "1/2/3", "0x10", " 1", "1 ", "1e99999", "."})
    BOOST_CHECK_THROW(parse_rational(bad), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(doubles_convert_exactly_and_round_correctly) {
  BOOST_TEST(gmcc::rational_from_double(0.1) ==
             Rational(mpz_class("3602879701896397"), mpz_class("36028797018963968")));
  BOOST_CHECK_THROW(gmcc::rational_from_double(std::numeric_limits<double>::quiet_NaN()),
                    std::invalid_argument);
  // mpq_get_d truncates; to_double_nearest rounds: 1/3 rounds up in its last bit.
  BOOST_TEST(gmcc::to_double_nearest(Rational(1, 3)) == 1.0 / 3.0);
  BOOST_TEST(gmcc::to_double_nearest(Rational(2, 3)) == 2.0 / 3.0);
  const double x = 0.7;
  BOOST_TEST(gmcc::to_double_nearest(gmcc::rational_from_double(x)) == x);
}

BOOST_AUTO_TEST_CASE(numbers_are_limited_to_max_number_digits) {
  static_assert(gmcc::max_number_digits == 100);
  const std::string nines(100, '9');
  BOOST_TEST(parse_rational(nines) == Rational(mpz_class(nines)));
  BOOST_CHECK_THROW(parse_rational(nines + "9"), std::invalid_argument);
  // Fraction and leading zeros count; exponent digits do not (max_decimal_exponent bounds them).
  const Rational ten_to_99(mpz_class("1" + std::string(99, '0')));
  BOOST_TEST(parse_rational("0." + std::string(98, '0') + "1") == Rational(1 / ten_to_99));
  BOOST_CHECK_THROW(parse_rational("0." + std::string(99, '0') + "1"), std::invalid_argument);
  BOOST_TEST(parse_rational(std::string(50, '1') + "/" + std::string(50, '3')) == Rational(1, 3));
  BOOST_CHECK_THROW(parse_rational(std::string(50, '1') + "/" + std::string(51, '3')),
                    std::invalid_argument);
  BOOST_TEST(parse_rational("1e" + std::string(200, '0') + "400") ==
             Rational(mpz_class("1" + std::string(400, '0'))));
  BOOST_TEST(parse_rational("1e-400") == Rational(1 / Rational(mpz_class("1" + std::string(400, '0')))));
  BOOST_CHECK_THROW(parse_rational("1e401"), std::invalid_argument);
  BOOST_CHECK_THROW(parse_rational("4e3619"), std::invalid_argument);
  try {
    parse_rational(std::string(5000, '7'));
    BOOST_FAIL("5000 digits accepted");
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    BOOST_TEST(message.find("has 5000 digits: at most 100") != std::string::npos);
    BOOST_TEST(message.size() < 200u);  // the number is not echoed whole
  }
}

BOOST_AUTO_TEST_CASE(messages_quote_text_briefly_and_printably) {
  try {
    parse_rational(std::string("\x01\xff\n") + std::string(1000, 'x'));
    BOOST_FAIL("garbage accepted");
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    BOOST_TEST(message.rfind("'\\x01\\xFF\\x0A", 0) == 0u);
    BOOST_TEST(message.find("(1003 characters)") != std::string::npos);
    BOOST_TEST(message.size() < 200u);
    for (char c : message) BOOST_TEST((c >= 0x20 && c < 0x7f));
  }
}

// Regression (fuzz/corpus/parse_rational/subnormal_below_midpoint): rounding first to 53 bits and
// then to the subnormal grid rounded twice. The 100-digit decimal just below 1.5·2^-1074 became
// 1.5·2^-1074 exactly, then went to even (2^-1073); the nearest double is 2^-1074, as strtod says.
BOOST_AUTO_TEST_CASE(subnormal_results_are_rounded_once) {
  const std::string below_midpoint =
      "7.410984687618698162648531893023320585475897039214871466383785237510132609053131277979497545"
      "424539885e-324";
  const double smallest = std::numeric_limits<double>::denorm_min();
  BOOST_TEST(std::strtod(below_midpoint.c_str(), nullptr) == smallest);
  BOOST_TEST(gmcc::to_double_nearest(parse_rational(below_midpoint)) == smallest);
  // The midpoint itself goes to even; just above it, up.
  const Rational midpoint = Rational(3) / Rational(mpz_class(1) << 1075);
  BOOST_TEST(gmcc::to_double_nearest(midpoint) == 2 * smallest);
  BOOST_TEST(gmcc::to_double_nearest(Rational(midpoint + Rational(1) / Rational(mpz_class(1) << 1200))) ==
             2 * smallest);
  BOOST_TEST(gmcc::to_double_nearest(Rational(midpoint - Rational(1) / Rational(mpz_class(1) << 1200))) ==
             smallest);
  // Half the smallest subnormal goes to 0 (even), anything above it to the smallest.
  const Rational half = Rational(1) / Rational(mpz_class(1) << 1075);
  BOOST_TEST(gmcc::to_double_nearest(half) == 0.0);
  BOOST_TEST(gmcc::to_double_nearest(Rational(half + Rational(1) / Rational(mpz_class(1) << 1200))) ==
             smallest);
  // The same for long double (x87: 64-bit significand, smallest subnormal 2^-16445).
  const long double smallest_ld = std::numeric_limits<long double>::denorm_min();
  const Rational midpoint_ld = Rational(3) / Rational(mpz_class(1) << 16446);
  BOOST_TEST(gmcc::to_long_double_nearest(Rational(midpoint_ld - Rational(1) / Rational(mpz_class(1) << 16600))) ==
             smallest_ld);
  BOOST_TEST(gmcc::to_long_double_nearest(midpoint_ld) == 2 * smallest_ld);
  // And the exponent range is restored: normal values far outside the double range still work.
  BOOST_TEST(gmcc::to_double_nearest(Rational(mpz_class(1) << 2000)) ==
             std::numeric_limits<double>::infinity());
  BOOST_TEST(gmcc::to_long_double_nearest(Rational(mpz_class(1) << 2000)) == std::ldexp(1.0L, 2000));
}

BOOST_AUTO_TEST_SUITE_END()
