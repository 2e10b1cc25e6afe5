#include "batch_scene_plain.h"

#include <gmcc/geometry/rational.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>

namespace gmcc::cli {
namespace {

// A cursor over the line; every method returns false (or nothing) on anything not plain.
struct Cursor {
  std::string_view s;
  std::size_t i = 0;

  void space() {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
  }
  bool take(char c) {
    space();
    if (i < s.size() && s[i] == c) return ++i, true;
    return false;
  }
  // A string of printable ASCII without escapes (what nlohmann::json reads as the same bytes).
  std::optional<std::string_view> string() {
    space();
    if (i >= s.size() || s[i] != '"') return std::nullopt;
    const std::size_t start = ++i;
    for (; i < s.size() && s[i] != '"'; ++i)
      if (s[i] < 0x20 || s[i] > 0x7e || s[i] == '\\') return std::nullopt;
    if (i >= s.size()) return std::nullopt;
    return s.substr(start, i++ - start);
  }
  // A non-negative JSON number token, by JSON's grammar: 0 or [1-9][0-9]*, then .[0-9]+, then
  // [eE][+-]?[0-9]+. `integral` when it has neither of the last two.
  std::optional<std::string_view> number(bool& integral) {
    space();
    const std::size_t start = i;
    auto digits = [&] {
      const std::size_t d = i;
      while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
      return i > d;
    };
    if (i < s.size() && s[i] == '0') ++i;
    else if (!digits()) return std::nullopt;
    integral = true;
    if (i < s.size() && s[i] == '.') {
      ++i, integral = false;
      if (!digits()) return std::nullopt;
    }
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
      ++i, integral = false;
      if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
      if (!digits()) return std::nullopt;
    }
    return s.substr(start, i - start);
  }
};

// A channel as parse_batch_scene reads it: a number's own text or a string's, read exactly; a
// negative value or a malformed one is not plain (the full reader names it).
std::optional<Rational> channel(Cursor& c) {
  bool integral = false;
  std::optional<std::string_view> text = c.string();
  if (!text) {
    text = c.number(integral);
    if (!text) return std::nullopt;
    // nlohmann::json reads a number that is not a 64-bit integer as a double, and refuses one
    // beyond the doubles' range ("number overflow"; the full reader then advises strings).
    if ((!integral || text->size() > 18) && !std::isfinite(std::strtod(std::string(*text).c_str(), nullptr)))
      return std::nullopt;
  }
  try {
    Rational x = parse_rational(*text);
    if (sgn(x) < 0) return std::nullopt;
    return x;
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

std::optional<Colour> colour(Cursor& c) {
  if (!c.take('[')) return std::nullopt;
  std::optional<Rational> x[3];
  for (int k = 0; k < 3; ++k)
    if ((k && !c.take(',')) || !(x[k] = channel(c))) return std::nullopt;
  if (!c.take(']')) return std::nullopt;
  return Colour{std::move(*x[0]), std::move(*x[1]), std::move(*x[2])};
}

// The id: an integer below 2^63 (a JSON number nlohmann::json keeps as an integer and writes back
// as the same text) or a plain string.
bool id(Cursor& c, Json& out) {
  if (const auto s = c.string()) {
    out = Json(std::string(*s));
    return true;
  }
  bool integral = false;
  const auto n = c.number(integral);
  if (!n || !integral || n->size() > 18) return false;
  out = Json(std::stoll(std::string(*n)));
  return true;
}

}  // namespace

bool parse_plain_batch_scene(std::string_view text, BatchScene& scene) {
  Cursor c{text};
  BatchScene out;
  out.line = scene.line;
  bool seen_id = false, seen_colours = false, seen_truth = false;
  if (!c.take('{')) return false;
  do {
    const auto key = c.string();
    if (!key || !c.take(':')) return false;
    if (*key == "id" && !seen_id) {
      seen_id = true;
      if (!id(c, out.id)) return false;
    } else if (*key == "colours" && !seen_colours) {
      seen_colours = true;
      if (!c.take('[')) return false;
      do {
        auto x = colour(c);
        if (!x || out.colours.size() >= max_colours) return false;
        out.colours.push_back(std::move(*x));
      } while (c.take(','));
      if (!c.take(']')) return false;
    } else if (*key == "truth" && !seen_truth) {
      seen_truth = true;
      if (!(out.truth = colour(c))) return false;
    } else {
      return false;
    }
  } while (c.take(','));
  if (!c.take('}') || !seen_colours) return false;
  c.space();
  if (c.i != text.size()) return false;
  scene = std::move(out);
  return true;
}

}  // namespace gmcc::cli
