#include <gmcc/geometry/rational.h>
#include <gmcc/input/text_file.h>
#include <gmcc/input/truth_table.h>

#include <filesystem>
#include <set>
#include <string_view>

#include "csv_fields.h"

namespace gmcc {
namespace {

// The data lines of a text file: (line number, trimmed line), blank and # lines skipped, a UTF-8
// byte-order mark dropped.
std::vector<std::pair<std::size_t, std::string_view>> data_lines(const std::string& text) {
  std::string_view rest(text);
  if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);
  std::vector<std::pair<std::size_t, std::string_view>> out;
  for (std::size_t number = 1; !rest.empty(); ++number) {
    const auto end = rest.find('\n');
    const std::string_view line = internal::trim(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (!line.empty() && line.front() != '#') out.push_back({number, line});
  }
  return out;
}

std::uint32_t level(std::string_view text, const std::string& path, std::size_t line, const char* what) {
  Rational q;
  try {
    q = parse_rational(text);
  } catch (const std::invalid_argument& e) {
    throw InputError(path, line, std::string(what) + ": " + e.what());
  }
  if (q.get_den() != 1 || sgn(q) < 0 || q > 65535)
    throw InputError(path, line, std::string(what) + ": expected an integer from 0 to 65535");
  return static_cast<std::uint32_t>(q.get_num().get_ui());
}

}  // namespace

std::vector<TruthRow> read_truth_table(const std::string& path) {
  const std::string text =
      read_text_file(path, {std::size_t(256) << 20, "truth table", "text lines image,r,g,b"});
  const auto lines = data_lines(text);
  if (lines.empty()) throw InputError(path, 0, "no images (expected a header image,r,g,b and one line per image)");
  const std::vector<std::string_view> header = internal::split_fields(lines[0].second);
  if (header.size() < 4 || header[0] != "image" || header[1] != "r" || header[2] != "g" || header[3] != "b")
    throw InputError(path, lines[0].first, "expected the header image,r,g,b[,black_level][,saturation][,mask][,chart]");
  std::set<std::string_view> seen;
  for (std::size_t k = 4; k < header.size(); ++k) {
    const std::string_view h = header[k];
    if (h != "black_level" && h != "saturation" && h != "mask" && h != "chart")
      throw InputError(path, lines[0].first, "unknown column " + quoted_text(h) +
                                                 " (optional columns: black_level, saturation, mask, chart)");
    if (!seen.insert(h).second) throw InputError(path, lines[0].first, "column " + quoted_text(h) + " twice");
  }
  std::vector<TruthRow> rows;
  std::set<std::string> names;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const auto& [number, line] = lines[l];
    const std::vector<std::string_view> f = internal::split_fields(line);
    if (f.size() != header.size())
      throw InputError(path, number, "expected " + std::to_string(header.size()) + " values, found " +
                                         std::to_string(f.size()));
    TruthRow row;
    row.line = number;
    row.image = std::string(f[0]);
    if (row.image.empty()) throw InputError(path, number, "no image name");
    Rational c[3];
    static const char* names3[] = {"r", "g", "b"};
    for (int k = 0; k < 3; ++k) {
      try {
        c[k] = parse_rational(f[1 + k]);
      } catch (const std::invalid_argument& e) {
        throw InputError(path, number, std::string(names3[k]) + ": " + e.what());
      }
      if (sgn(c[k]) <= 0) throw InputError(path, number, std::string(names3[k]) + " must be > 0 (a light's response)");
    }
    row.light = {c[0], c[1], c[2]};
    for (std::size_t k = 4; k < header.size(); ++k) {
      if (f[k].empty()) continue;
      if (header[k] == "black_level") row.black_level = level(f[k], path, number, "black_level");
      if (header[k] == "saturation") row.saturation = level(f[k], path, number, "saturation");
      if (header[k] == "mask") row.mask = std::string(f[k]);
      if (header[k] == "chart") {
        std::vector<Rational> v;
        std::string_view s = f[k];
        while (!s.empty()) {
          const auto sp = s.find(' ');
          const std::string_view token = s.substr(0, sp);
          s = sp == std::string_view::npos ? std::string_view() : internal::trim(s.substr(sp + 1));
          if (token.empty()) continue;
          try {
            v.push_back(parse_rational(token));
          } catch (const std::invalid_argument& e) {
            throw InputError(path, number, std::string("chart: ") + e.what());
          }
        }
        if (v.size() % 2 || v.size() < 6)
          throw InputError(path, number, "chart: expected \"x1 y1 x2 y2 x3 y3 ...\", 3 or more points");
        for (std::size_t i = 0; i < v.size(); i += 2) row.chart.push_back({v[i], v[i + 1]});
      }
    }
    if (!names.insert(row.image).second) throw InputError(path, number, "image " + quoted_text(row.image) + " listed twice");
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(path, 0, "no images after the header");
  return rows;
}

std::map<std::string, TruthRow> truth_rows_by_image(std::vector<TruthRow> rows) {
  std::map<std::string, TruthRow> out;
  for (TruthRow& r : rows) {
    std::string name = r.image;
    out.emplace(std::move(name), std::move(r));
  }
  return out;
}

const TruthRow& truth_of_image(const std::map<std::string, TruthRow>& rows, const std::string& image_path,
                               const std::string& truths_path) {
  auto t = rows.find(image_path);
  if (t == rows.end()) t = rows.find(std::filesystem::path(image_path).filename().string());
  if (t == rows.end()) throw InputError(truths_path, 0, "no light for image " + image_path + " (nor for its file name)");
  return t->second;
}

void require_paths_under_folder(const std::vector<TruthRow>& rows, const std::string& table_path) {
  for (const TruthRow& r : rows)
    for (const std::string* p : {&r.image, &r.mask}) {
      if (p->empty()) continue;
      const std::filesystem::path path(*p);
      bool up = false;
      for (const std::filesystem::path& part : path) up = up || part == "..";
      if (path.has_root_path() || up)
        throw InputError(table_path, r.line,
                         std::string(p == &r.image ? "image " : "mask ") + quoted_text(*p) +
                             (up ? " leaves" : " is outside") + " the --images folder (a path relative to it, without .., is expected)");
    }
}

std::map<std::string, int> read_folds_file(const std::string& path) {
  const std::string text = read_text_file(path, {std::size_t(64) << 20, "folds file", "text lines image,fold"});
  const auto lines = data_lines(text);
  if (lines.empty() || internal::split_fields(lines[0].second) != std::vector<std::string_view>{"image", "fold"})
    throw InputError(path, lines.empty() ? 0 : lines[0].first, "expected the header image,fold");
  std::map<std::string, int> folds;
  for (std::size_t l = 1; l < lines.size(); ++l) {
    const auto& [number, line] = lines[l];
    const std::vector<std::string_view> f = internal::split_fields(line);
    if (f.size() != 2) throw InputError(path, number, "expected 2 values image,fold, found " + std::to_string(f.size()));
    Rational q;
    try {
      q = parse_rational(f[1]);
    } catch (const std::invalid_argument& e) {
      throw InputError(path, number, std::string("fold: ") + e.what());
    }
    if (q.get_den() != 1 || sgn(q) < 0 || q > 1000000)
      throw InputError(path, number, "fold: expected an integer from 0 to 1000000");
    if (!folds.emplace(std::string(f[0]), static_cast<int>(q.get_num().get_si())).second)
      throw InputError(path, number, "image " + quoted_text(f[0]) + " listed twice");
  }
  if (folds.empty()) throw InputError(path, 0, "no folds after the header");
  return folds;
}

}  // namespace gmcc
