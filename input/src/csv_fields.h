#pragma once
// The comma-separated fields of one line of a text data file, each with the blanks around it
// removed: the one splitter of the colour, chart and light-table readers. Internal to
// gmcc::input.

#include <string_view>
#include <vector>

namespace gmcc::internal {

/// `s` without leading and trailing spaces, tabs, carriage returns, vertical tabs and form feeds.
inline std::string_view trim(std::string_view s) {
  const char* blanks = " \t\r\v\f";
  const auto first = s.find_first_not_of(blanks);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(blanks) - first + 1);
}

/// The fields of `line` between commas, each trimmed (one field when there is no comma).
inline std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

}  // namespace gmcc::internal
