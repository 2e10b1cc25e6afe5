#include <gmcc/geometry/rational.h>
#include <gmcc/input/image_lights.h>
#include <gmcc/input/text_file.h>

#include <filesystem>
#include <string_view>
#include <vector>

#include "csv_fields.h"

namespace gmcc {

std::map<std::string, Colour> read_image_lights(const std::string& path) {
  const std::string text =
      read_text_file(path, {std::size_t(64) << 20, "truth file", "text lines image,r,g,b"});
  std::map<std::string, Colour> lights;
  std::string_view rest(text);
  if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);  // UTF-8 byte-order mark
  bool header = false;
  for (std::size_t number = 1; !rest.empty(); ++number) {
    const auto end = rest.find('\n');
    const std::string_view line = internal::trim(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> f = internal::split_fields(line);
    if (!header) {
      if (f != std::vector<std::string_view>{"image", "r", "g", "b"})
        throw InputError(path, number, "expected the header image,r,g,b");
      header = true;
      continue;
    }
    if (f.size() != 4)
      throw InputError(path, number,
                       "expected 4 values image,r,g,b, found " + std::to_string(f.size()));
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
    if (!lights.emplace(std::string(f[0]), Colour{c[0], c[1], c[2]}).second)
      throw InputError(path, number, "image " + quoted_text(f[0]) + " listed twice");
  }
  if (lights.empty()) throw InputError(path, 0, "no lights (expected lines image,r,g,b)");
  return lights;
}

const Colour& light_of_image(const std::map<std::string, Colour>& lights,
                             const std::string& image_path, const std::string& lights_path) {
  auto t = lights.find(image_path);
  if (t == lights.end()) t = lights.find(std::filesystem::path(image_path).filename().string());
  if (t == lights.end())
    throw InputError(lights_path, 0,
                     "no light for image " + image_path + " (nor for its file name)");
  return t->second;
}

}  // namespace gmcc
