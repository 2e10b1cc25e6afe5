#include <gmcc/input/colour_csv.h>
#include <gmcc/input/text_file.h>

#include "csv_fields.h"


namespace gmcc {
namespace {

// The header line's meaning: 0 none, 1 `r,g,b` (pixel colours), 2 `r/b,g/b,1` (chromaticity
// lifts).
int header_kind(std::string_view line) {
  std::string compact;
  for (char c : line)
    if (c != ' ' && c != '\t') compact += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return compact == "r,g,b" ? 1 : compact == "r/b,g/b,1" ? 2 : 0;
}

std::string location(const std::string& file, std::size_t line) {
  return line ? file + ":" + std::to_string(line) : file;
}

}  // namespace

InputError::InputError(std::string source, std::size_t line, const std::string& problem)
    : std::runtime_error(location(source, line) + ": " + problem), source_(std::move(source)),
      line_(line) {}

ColourTable parse_colour_csv(const std::string& text, const std::string& file) {
  ColourTable table;
  table.file = file;
  std::string_view rest(text);
  if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);  // UTF-8 byte-order mark
  bool first_content = true;
  for (std::size_t number = 1; !rest.empty() || number == 1; ++number) {
    const auto end = rest.find('\n');
    const std::string_view raw = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (raw.find('\0') != std::string_view::npos)
      throw InputError(file, number, "binary data (a NUL byte): expected text lines r,g,b");
    const std::string_view line = internal::trim(raw);
    // A comment may be long (provenance listing many inputs); the file's size bounds it.
    if (line.empty() || line.front() == '#') {
      if (rest.empty()) break;
      continue;
    }
    if (raw.size() > max_colour_line_bytes)
      throw InputError(file, number,
                       "line of " + std::to_string(raw.size()) + " bytes, longer than the " +
                           std::to_string(max_colour_line_bytes) +
                           "-byte limit: expected text lines r,g,b");
    if (first_content && header_kind(line)) {
      table.chromaticity_lifts = header_kind(line) == 2;
      table.header_line = number;
      first_content = false;
      continue;
    }
    first_content = false;
    const std::vector<std::string_view> fields = internal::split_fields(line);
    if (fields.size() != 3)
      throw InputError(file, number,
                       "expected 3 comma-separated values r,g,b, found " +
                           std::to_string(fields.size()));
    Rational channel[3];
    static const char* names[] = {"r", "g", "b"};
    for (int k = 0; k < 3; ++k) {
      try {
        channel[k] = parse_rational(fields[k]);
      } catch (const std::invalid_argument& e) {
        throw InputError(file, number, std::string("channel ") + names[k] + ": " + e.what());
      }
      if (sgn(channel[k]) < 0)
        throw InputError(file, number,
                         std::string("channel ") + names[k] + " is negative (" +
                             std::string(fields[k].substr(0, 40)) +
                             (fields[k].size() > 40 ? "..." : "") +
                             "): a linear sensor response must be >= 0");
    }
    if (table.colours.size() == max_colours)
      throw InputError(file, number,
                       "more than " + std::to_string(max_colours) +
                           " colours, the limit for one file (memory and time grow with them)");
    table.colours.push_back({channel[0], channel[1], channel[2]});
    table.lines.push_back(number);
    if (rest.empty()) break;
  }
  if (table.colours.empty())
    throw InputError(file, 0, "no colours (expected lines r,g,b)");
  return table;
}

void require_pixel_colours(const ColourTable& table, const std::string& use) {
  if (table.chromaticity_lifts)
    throw InputError(table.file, table.header_line,
                     "the header r/b,g/b,1 marks chromaticity lifts (a 2-D perspective gamut, as "
                     "gmcc canonical writes by default), not pixel colours: " + use +
                         " needs colours r,g,b (learn a 3-D gamut with gmcc canonical --space 3d)");
}

ColourTable read_colour_csv(const std::string& path) {
  return parse_colour_csv(
      read_text_file(path, {max_colour_file_bytes, "colour file", "text lines r,g,b"}), path);
}

}  // namespace gmcc
