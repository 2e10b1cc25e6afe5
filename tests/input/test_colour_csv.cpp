#include <gmcc/input/colour_csv.h>

#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
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

BOOST_AUTO_TEST_CASE(unreadable_files_are_reported) {
  // As root, mode 000 does not stop reads: nothing to test there.
  if (::geteuid() == 0) return;
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("gmcc-unreadable-" + std::to_string(::getpid()));
  std::ofstream(path) << "1,1,1\n";
  std::filesystem::permissions(path, std::filesystem::perms::none);
  std::string message;
  try {
    read_colour_csv(path.string());
  } catch (const InputError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  BOOST_TEST(message == path.string() + ": cannot open: Permission denied");
}

BOOST_AUTO_TEST_CASE(lines_are_limited_in_length) {
  static_assert(max_colour_line_bytes == 65536);
  // At the limit (spaces around numbers are allowed): read; one byte more: refused, by line.
  const std::string at_limit = std::string(max_colour_line_bytes - 5, ' ') + "1,2,3";
  BOOST_TEST(parse_colour_csv("1,1,1\n" + at_limit + "\n", "c.csv").colours.size() == 2u);
  BOOST_TEST(error_of("1,1,1\n" + at_limit + " \n").find("c.csv:2: line of 65537 bytes") == 0u);
  // A megabyte of digits with no line end: a one-line message, not the digits.
  const std::string message = error_of(std::string(1 << 20, '7'));
  BOOST_TEST(message.find("c.csv:1: line of 1048576 bytes, longer than the 65536-byte limit") == 0u);
  BOOST_TEST(message.size() < 200u);
  // A comment is not a colour: one far past the limit (a provenance line listing 10,000 inputs
  // with their checksums) is skipped, and the file reads back.
  const std::string provenance = "# inputs:" + std::string(800000, 'x') + "\n";
  BOOST_TEST(parse_colour_csv(provenance + "r,g,b\n1,2,3\n", "c.csv").colours.size() == 1u);
  // Long numbers within a line are refused by parse_rational, and quoted briefly.
  const std::string long_number = error_of("1,2," + std::string(500, '3') + "\n");
  BOOST_TEST(long_number.find("c.csv:1: channel b: '3333") == 0u);
  BOOST_TEST(long_number.find("has 500 digits: at most 100") != std::string::npos);
  BOOST_TEST(long_number.size() < 200u);
  const std::string negative = error_of("1,-" + std::string(90, '4') + ",3\n");
  BOOST_TEST(negative.find("c.csv:1: channel g is negative (-444") == 0u);
  BOOST_TEST(negative.size() < 200u);
}

// Files that are not regular files are read as streams, the limits applied while reading
// (docs/cli.md, "Files, special paths, signals and time limits").
BOOST_AUTO_TEST_CASE(special_files_are_read_as_streams) {
  const auto error_reading = [](const std::string& path) -> std::string {
    try {
      read_colour_csv(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  // Size 0 by a seek: once read as empty ("no colours"); the NUL check now runs on block one.
  BOOST_TEST(error_reading("/dev/zero") == "/dev/zero:1: binary data (a NUL byte): expected text lines r,g,b");
  BOOST_TEST(error_reading("/dev/null") == "/dev/null: no colours (expected lines r,g,b)");
  // Size 0 by stat, but text: read, and its first line is not a colour.
  BOOST_TEST(error_reading("/proc/version").find("/proc/version:1: expected 3") == 0u);
  // A pipe, as process substitution passes it (/dev/fd/N).
  int ends[2];
  BOOST_REQUIRE(::pipe(ends) == 0);
  const std::string text = "1,2,3\n4,5,6\n";
  BOOST_REQUIRE(::write(ends[1], text.data(), text.size()) == static_cast<ssize_t>(text.size()));
  ::close(ends[1]);
  const ColourTable t = read_colour_csv("/dev/fd/" + std::to_string(ends[0]));
  ::close(ends[0]);
  BOOST_TEST(t.colours.size() == 2u);
  // A NUL after line breaks: its line is named.
  BOOST_REQUIRE(::pipe(ends) == 0);
  BOOST_REQUIRE(::write(ends[1], "1,1,1\n2,2,2\n\0", 13) == 13);
  ::close(ends[1]);
  BOOST_TEST(error_reading("/dev/fd/" + std::to_string(ends[0])).find(":3: binary data (a NUL byte)") !=
             std::string::npos);
  ::close(ends[0]);
}

BOOST_AUTO_TEST_CASE(colours_are_limited_in_number) {
  static_assert(max_colours == 1000000);
  std::string text;
  text.reserve(6 * (max_colours + 1));
  for (std::size_t i = 0; i < max_colours; ++i) text += "0,0,1\n";
  BOOST_TEST(parse_colour_csv(text, "c.csv").colours.size() == max_colours);
  text += "# the next colour is one too many\n0,0,1\n";
  BOOST_TEST(error_of(text).find("c.csv:1000002: more than 1000000 colours") == 0u);
}

BOOST_AUTO_TEST_SUITE_END()

// The header says what the colours are: `r,g,b` pixel colours, `r/b,g/b,1` chromaticity lifts
// (gmcc canonical's 2-D gamut), which the 3-D route refuses.
BOOST_AUTO_TEST_CASE(the_header_marks_chromaticity_lifts) {
  const ColourTable plain = parse_colour_csv("# c\nr,g,b\n1,2,3\n", "c.csv");
  BOOST_TEST(!plain.chromaticity_lifts);
  BOOST_TEST(plain.header_line == 2u);
  const ColourTable lifts = parse_colour_csv("R/B, G/B, 1\n1/2,3,1\n", "c.csv");
  BOOST_TEST(lifts.chromaticity_lifts);
  BOOST_TEST(lifts.header_line == 1u);
  BOOST_TEST(parse_colour_csv("1,2,3\n", "c.csv").header_line == 0u);
  // Only as the first content line: later, it is a malformed colour.
  BOOST_TEST(error_of("1,2,3\nr/b,g/b,1\n").find("c.csv:2:") == 0u);
}
