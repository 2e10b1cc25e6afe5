#include <gmcc/geometry/rational.h>

#include <boost/test/unit_test.hpp>

#include <limits>
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

BOOST_AUTO_TEST_SUITE_END()
