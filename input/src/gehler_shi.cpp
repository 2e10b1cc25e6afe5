#include <gmcc/input/gehler_shi.h>
#include <gmcc/input/text_file.h>

#include "csv_fields.h"

#include <cctype>
#include <map>
#include <string_view>

namespace gmcc {
namespace {

// The data files are a few MB; a much larger file is not this data.
constexpr std::size_t max_chart_file_bytes = std::size_t(64) << 20;

// The file's non-blank lines, each with its 1-based number, split at commas.
struct Row {
  std::size_t line;
  std::vector<std::string_view> fields;
};
std::vector<Row> rows_of(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<Row> rows;
  for (std::size_t number = 1; !text.empty(); ++number) {
    const auto end = text.find('\n');
    const std::string_view line = internal::trim(text.substr(0, end));
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    if (line.empty()) continue;
    rows.push_back({number, internal::split_fields(line)});
  }
  return rows;
}

void check_header(const std::vector<Row>& rows, const std::string& file,
                  const std::vector<std::string_view>& header) {
  std::string expected;
  for (std::string_view h : header) expected += (expected.empty() ? "" : ",") + std::string(h);
  if (rows.empty()) throw InputError(file, 0, "empty: expected the header " + expected);
  if (rows.front().fields != header)
    throw InputError(file, rows.front().line, "expected the header " + expected);
}

void check_columns(const Row& row, const std::string& file, std::size_t n) {
  if (row.fields.size() != n)
    throw InputError(file, row.line,
                     "expected " + std::to_string(n) + " comma-separated values, found " +
                         std::to_string(row.fields.size()));
}

std::size_t positive_integer(std::string_view text, const Row& row, const std::string& file,
                             const char* what) {
  std::size_t value = 0;
  if (text.empty() || text.size() > 9)
    throw InputError(file, row.line, std::string(what) + " must be a positive integer");
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c)))
      throw InputError(file, row.line, std::string(what) + " must be a positive integer");
    value = value * 10 + static_cast<std::size_t>(c - '0');
  }
  if (value == 0)
    throw InputError(file, row.line, std::string(what) + " must be a positive integer");
  return value;
}

Rational number(std::string_view text, const Row& row, const std::string& file, const char* what) {
  try {
    return parse_rational(text);
  } catch (const std::invalid_argument& e) {
    throw InputError(file, row.line, std::string(what) + ": " + e.what());
  }
}

bool is_nan(std::string_view s) {
  return s.size() == 3 && std::tolower(static_cast<unsigned char>(s[0])) == 'n' &&
         std::tolower(static_cast<unsigned char>(s[1])) == 'a' &&
         std::tolower(static_cast<unsigned char>(s[2])) == 'n';
}

// The ground-truth file's images, in index order, each with its name's position in by_name.
void read_truths(const std::string& truth_text, const std::string& truth_file, ChartDataset& data,
                 std::map<std::string_view, std::size_t>& by_name) {
  const std::vector<Row> truth_rows = rows_of(truth_text);
  check_header(truth_rows, truth_file,
               {"index", "image", "camera", "shi_real_rgb_r", "shi_real_rgb_g", "shi_real_rgb_b",
                "rec2018_r", "rec2018_g", "rec2018_b"});
  for (std::size_t i = 1; i < truth_rows.size(); ++i) {
    const Row& row = truth_rows[i];
    check_columns(row, truth_file, 9);
    ChartImage image;
    image.index = positive_integer(row.fields[0], row, truth_file, "index");
    if (image.index != data.images.size() + 1)
      throw InputError(truth_file, row.line,
                       "index " + std::to_string(image.index) + " out of order: expected " +
                           std::to_string(data.images.size() + 1));
    image.name = std::string(row.fields[1]);
    if (image.name.empty()) throw InputError(truth_file, row.line, "no image name");
    if (!by_name.emplace(row.fields[1], data.images.size()).second)
      throw InputError(truth_file, row.line, "image " + image.name + " listed twice");
    image.camera = std::string(row.fields[2]);
    if (image.camera != "Canon1D" && image.camera != "Canon5D")
      throw InputError(truth_file, row.line,
                       "camera " + quoted_text(row.fields[2]) + ": expected Canon1D or Canon5D");
    static const char* names[] = {"rec2018_r", "rec2018_g", "rec2018_b"};
    Rational c[3];
    for (int k = 0; k < 3; ++k) {
      if (is_nan(row.fields[6 + k]))
        throw InputError(truth_file, row.line, std::string(names[k]) + " is NaN: no ground truth");
      c[k] = number(row.fields[6 + k], row, truth_file, names[k]);
      if (sgn(c[k]) <= 0)
        throw InputError(truth_file, row.line,
                         std::string(names[k]) + " must be > 0 (a light's response)");
    }
    image.truth = {c[0], c[1], c[2]};
    data.images.push_back(std::move(image));
  }
}

// The patch file's measurements into the images named in by_name (NaN in all three channels:
// missing).
void read_patches(const std::string& patches_text, const std::string& patches_file, const std::string& truth_file,
                  ChartDataset& data, const std::map<std::string_view, std::size_t>& by_name) {
  const std::vector<Row> patch_rows = rows_of(patches_text);
  check_header(patch_rows, patches_file, {"index", "image", "patch", "r", "g", "b"});
  std::vector<std::array<bool, chart_patches>> seen(data.images.size());  // a row, NaN or not
  for (std::size_t i = 1; i < patch_rows.size(); ++i) {
    const Row& row = patch_rows[i];
    check_columns(row, patches_file, 6);
    const std::size_t index = positive_integer(row.fields[0], row, patches_file, "index");
    const auto named = by_name.find(row.fields[1]);
    if (named == by_name.end())
      throw InputError(
          patches_file, row.line,
          "image " + quoted_text(row.fields[1]) + " has no ground truth in " + truth_file);
    ChartImage& image = data.images[named->second];
    if (image.index != index)
      throw InputError(patches_file, row.line,
                       "image " + image.name + " has index " + std::to_string(image.index) +
                           " in " + truth_file + ", not " + std::to_string(index));
    const std::size_t patch = positive_integer(row.fields[2], row, patches_file, "patch");
    if (patch > chart_patches)
      throw InputError(patches_file, row.line,
                       "patch " + std::to_string(patch) + ": a ColorChecker has patches 1 to 24");
    if (seen[named->second][patch - 1])
      throw InputError(
          patches_file, row.line,
          "patch " + std::to_string(patch) + " of image " + image.name + " given twice");
    seen[named->second][patch - 1] = true;
    const int nans = is_nan(row.fields[3]) + is_nan(row.fields[4]) + is_nan(row.fields[5]);
    if (nans == 3) continue;  // no measurement: counted as missing below
    if (nans != 0)
      throw InputError(patches_file, row.line,
                       "NaN in some channels only: a missing patch has NaN in all three");
    static const char* names[] = {"r", "g", "b"};
    Rational c[3];
    for (int k = 0; k < 3; ++k) {
      c[k] = number(row.fields[3 + k], row, patches_file, names[k]);
      if (sgn(c[k]) < 0)
        throw InputError(patches_file, row.line,
                         std::string("channel ") + names[k] +
                             " is negative: a linear sensor response must be >= 0");
    }
    image.patches[patch - 1] = Colour{c[0], c[1], c[2]};
  }
}

}  // namespace

ChartDataset parse_gehler_shi(const std::string& patches_text, const std::string& patches_file,
                              const std::string& truth_text, const std::string& truth_file) {
  ChartDataset data;
  std::map<std::string_view, std::size_t> by_name;  // views into truth_text
  read_truths(truth_text, truth_file, data, by_name);
  if (data.images.empty()) throw InputError(truth_file, 0, "no images");

  read_patches(patches_text, patches_file, truth_file, data, by_name);
  for (const ChartImage& image : data.images)
    for (const std::optional<Colour>& p : image.patches) data.missing_patches += !p;
  return data;
}

ChartDataset read_gehler_shi(const std::string& patches_path, const std::string& truth_path) {
  const TextFileRules patches{max_chart_file_bytes, "chart patch file",
                              "text lines index,image,patch,r,g,b"};
  const TextFileRules truth{max_chart_file_bytes, "ground-truth file",
                            "text lines index,image,camera,...,rec2018_b"};
  const std::string truth_text = read_text_file(truth_path, truth);
  return parse_gehler_shi(read_text_file(patches_path, patches), patches_path, truth_text,
                          truth_path);
}

}  // namespace gmcc
