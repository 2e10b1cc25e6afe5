#include "truth_file.h"

#include <gmcc/geometry/rational.h>
#include <gmcc/validation/input_error.h>
#include <gmcc/validation/text_file.h>

#include <filesystem>
#include <string_view>
#include <vector>

namespace gmcc::cli {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::map<std::string, Colour> read_truths(const std::string& path) {
  const std::string text =
      read_text_file(path, {std::size_t(64) << 20, "truth file", "text lines image,r,g,b"});
  std::map<std::string, Colour> truths;
  std::string_view rest(text);
  bool header = false;
  for (std::size_t number = 1; !rest.empty(); ++number) {
    const auto end = rest.find('\n');
    const std::string_view line = trim(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (line.empty() || line.front() == '#') continue;
    std::vector<std::string_view> f;
    for (std::size_t start = 0;;) {
      const auto comma = line.find(',', start);
      f.push_back(trim(line.substr(start, comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    if (!header) {
      if (f != std::vector<std::string_view>{"image", "r", "g", "b"})
        throw InputError(path, number, "expected the header image,r,g,b");
      header = true;
      continue;
    }
    if (f.size() != 4)
      throw InputError(path, number, "expected 4 values image,r,g,b, found " + std::to_string(f.size()));
    Rational c[3];
    static const char* names[] = {"r", "g", "b"};
    for (int k = 0; k < 3; ++k) {
      try {
        c[k] = parse_rational(f[1 + k]);
      } catch (const std::invalid_argument& e) {
        throw InputError(path, number, std::string(names[k]) + ": " + e.what());
      }
      if (sgn(c[k]) <= 0)
        throw InputError(path, number, std::string(names[k]) + " must be > 0 (a light's response)");
    }
    if (!truths.emplace(std::string(f[0]), Colour{c[0], c[1], c[2]}).second)
      throw InputError(path, number, "image " + quoted_text(f[0]) + " listed twice");
  }
  if (truths.empty()) throw InputError(path, 0, "no lights (expected lines image,r,g,b)");
  return truths;
}

const Colour& light_of_image(const std::map<std::string, Colour>& truths,
                             const std::string& image_path, const std::string& truths_path) {
  auto t = truths.find(image_path);
  if (t == truths.end()) t = truths.find(std::filesystem::path(image_path).filename().string());
  if (t == truths.end())
    throw InputError(truths_path, 0, "no light for image " + image_path + " (nor for its file name)");
  return t->second;
}

}  // namespace gmcc::cli
