// Fuzz target: gmcc::parse_colour_csv on arbitrary bytes.
// Every input must either parse or throw gmcc::InputError whose message is one line of bounded
// length naming the file (and a line that exists). What parses must be colours with channels
// >= 0, at most max_colours of them, from increasing lines that exist; written back as exact
// `r,g,b` lines it must parse to the same colours.

#include "fuzz_support.h"

#include <gmcc/input/colour_csv.h>

#include <algorithm>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t lines = std::count(text.begin(), text.end(), '\n') + 1;
  gmcc::ColourTable table;
  try {
    table = gmcc::parse_colour_csv(text, "fuzz.csv");
  } catch (const gmcc::InputError& e) {
    const std::string message = e.what();
    FUZZ_CHECK(message.rfind("fuzz.csv", 0) == 0, "message does not start with the file: " + message);
    FUZZ_CHECK(e.source() == "fuzz.csv", "InputError::source()");
    FUZZ_CHECK(e.line() <= lines, "line " + std::to_string(e.line()) + " beyond the text");
    FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line");
    FUZZ_CHECK(message.size() <= 400, "a message of " + std::to_string(message.size()) + " bytes");
    return 0;
  }
  FUZZ_CHECK(!table.colours.empty(), "no colours, and no error");
  FUZZ_CHECK(table.colours.size() <= gmcc::max_colours, "more than max_colours");
  FUZZ_CHECK(table.lines.size() == table.colours.size(), "one line number per colour");
  for (std::size_t i = 0; i < table.lines.size(); ++i) {
    FUZZ_CHECK(table.lines[i] >= 1 && table.lines[i] <= lines, "line number beyond the text");
    FUZZ_CHECK(i == 0 || table.lines[i] > table.lines[i - 1], "line numbers not increasing");
  }
  std::string written;
  bool writable = true;  // to_string of a number with a large exponent exceeds max_number_digits
  for (const gmcc::Colour& c : table.colours) {
    for (const gmcc::Rational* x : {&c.r, &c.g, &c.b}) {
      FUZZ_CHECK(sgn(*x) >= 0, "a negative channel was accepted");
      const std::string s = gmcc::to_string(*x);
      writable = writable && std::count_if(s.begin(), s.end(), [](char ch) {
                               return ch >= '0' && ch <= '9';
                             }) <= static_cast<long>(gmcc::max_number_digits);
      written += s + (x == &c.b ? "\n" : ",");
    }
  }
  if (writable) {
    const gmcc::ColourTable again = gmcc::parse_colour_csv(written, "again.csv");
    FUZZ_CHECK(again.colours == table.colours, "written back, the colours read differently");
  }
  return 0;
}
