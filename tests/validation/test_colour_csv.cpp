#include <gmcc/validation/colour_csv.h>

#include <boost/test/unit_test.hpp>

#include <string>

using namespace gmcc;

namespace {
// The message of the InputError that parsing `text` throws, or "" if it does not throw.
std::string error_of(const std::string& text) {
  try {
    parse_colour_csv(text, "c.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

BOOST_AUTO_TEST_SUITE(colour_csv)

BOOST_AUTO_TEST_CASE(odd_but_valid_input_is_accepted) {
  const std::string text =
      "\xEF\xBB\xBFr, g ,b\r\n# a comment\r\n\r\n 0.1 ,\t2/3, 1e-2 \r\n  # indented comment\n"
      "3,2,1";
  const ColourTable t = parse_colour_csv(text, "c.csv");
  BOOST_REQUIRE(t.colours.size() == 2u);
  BOOST_TEST((t.colours[0] == Colour{Rational(1, 10), Rational(2, 3), Rational(1, 100)}));
  BOOST_TEST((t.colours[1] == Colour{3, 2, 1}));
  BOOST_TEST(t.lines[0] == 4u);
  BOOST_TEST(t.lines[1] == 6u);
}

BOOST_AUTO_TEST_CASE(bad_input_names_file_line_and_problem) {
  BOOST_TEST(error_of("1,2,3\n1,2\n").find("c.csv:2: expected 3") == 0u);
  BOOST_TEST(error_of("1,2,3,4\n").find("c.csv:1: expected 3") == 0u);
  BOOST_TEST(error_of("# x\n1,-2,3\n").find("c.csv:2: channel g is negative") == 0u);
  BOOST_TEST(error_of("1,nan,3\n").find("c.csv:1: channel g: NaN") == 0u);
  BOOST_TEST(error_of("1,2,inf\n").find("c.csv:1: channel b: infinity") == 0u);
  BOOST_TEST(error_of("1,2,1/0\n").find("divides by zero") != std::string::npos);
  BOOST_TEST(error_of("1,2,abc\n").find("c.csv:1: channel b: 'abc' is not a number") == 0u);
  BOOST_TEST(error_of("1,,3\n").find("c.csv:1: channel g") == 0u);
  BOOST_TEST(error_of(std::string("1,2,3\n1,2\0,3\n", 13)).find("c.csv:2: binary") == 0u);
  BOOST_TEST(error_of("").find("c.csv: no colours") == 0u);
  BOOST_TEST(error_of("r,g,b\n# only a header\n").find("c.csv: no colours") == 0u);
  BOOST_TEST(error_of("r,g,b\nr,g,b\n").find("c.csv:2:") == 0u);  // a header only once
}

BOOST_AUTO_TEST_CASE(missing_files_are_reported) {
  BOOST_CHECK_THROW(read_colour_csv("/nonexistent/c.csv"), InputError);
  BOOST_CHECK_THROW(read_colour_csv("/"), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
