// Fuzz target: a dataset's truth table and folds file (truth_table.h), on arbitrary bytes written
// to a temporary file (the readers take paths, as `gmcc benchmark` gives them).
//
// Every input must either parse or throw gmcc::InputError whose message is one line of bounded
// length naming the file, at a line that exists. What parses: at least one row, each from an
// existing line in increasing order, a non-empty image name listed once, every light channel > 0,
// a black level and saturation within 0..65535, a chart of none or at least 3 points; folds >= 0.

#include "fuzz_support.h"

#include <gmcc/input/truth_table.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>

namespace {

void check_error(const gmcc::InputError& e, const std::string& path, std::size_t lines) {
  const std::string message = e.what();
  FUZZ_CHECK(message.rfind(path, 0) == 0, "message does not start with the file: " + message);
  FUZZ_CHECK(e.line() <= lines, "line " + std::to_string(e.line()) + " beyond the text");
  FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line: " + message);
  FUZZ_CHECK(message.size() <= 400 + path.size(), "a message of " + std::to_string(message.size()) + " bytes");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  char path[] = "/tmp/gmcc_fuzz_truth_XXXXXX";
  const int fd = mkstemp(path);
  FUZZ_CHECK(fd >= 0, "mkstemp");
  FUZZ_CHECK(write(fd, data, size) == static_cast<ssize_t>(size), "write");
  close(fd);
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
  try {
    const std::vector<gmcc::TruthRow> rows = gmcc::read_truth_table(path);
    FUZZ_CHECK(!rows.empty(), "no rows, and no error");
    std::set<std::string> names;
    std::size_t last = 0;
    for (const gmcc::TruthRow& row : rows) {
      FUZZ_CHECK(!row.image.empty() && names.insert(row.image).second, "an empty or repeated image: " + row.image);
      FUZZ_CHECK(row.line > last && row.line <= lines, "line numbers");
      last = row.line;
      FUZZ_CHECK(sgn(row.light.r) > 0 && sgn(row.light.g) > 0 && sgn(row.light.b) > 0, "a light channel <= 0");
      FUZZ_CHECK(!row.black_level || *row.black_level <= 65535, "black level");
      FUZZ_CHECK(!row.saturation || *row.saturation <= 65535, "saturation");
      FUZZ_CHECK(row.chart.empty() || row.chart.size() >= 3, "a chart of fewer than 3 points");
    }
  } catch (const gmcc::InputError& e) {
    check_error(e, path, lines);
  }
  try {
    for (const auto& [image, fold] : gmcc::read_folds_file(path)) FUZZ_CHECK(fold >= 0, "a negative fold: " + image);
  } catch (const gmcc::InputError& e) {
    check_error(e, path, lines);
  }
  std::remove(path);
  return 0;
}
