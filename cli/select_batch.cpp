#include "select_batch.h"

#include "batch_scene_plain.h"
#include "in_order_pool.h"

#include "json_output.h"
#include "select_record_json.h"
#include "write_stdout.h"

#include <gmcc/input/text_file.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <thread>

namespace gmcc::cli {
namespace {

// A SAX handler that builds the JSON value of a line with every non-integer number kept as its
// text (a string), so that decimals are read exactly by parse_rational, as colour files are.
class ExactSax {
 public:
  using number_integer_t = Json::number_integer_t;
  using number_unsigned_t = Json::number_unsigned_t;
  using number_float_t = Json::number_float_t;
  using string_t = Json::string_t;
  using binary_t = Json::binary_t;

  bool null() { return add(Json()); }
  bool boolean(bool b) { return add(Json(b)); }
  bool number_integer(number_integer_t v) { return add(Json(v)); }
  bool number_unsigned(number_unsigned_t v) { return add(Json(v)); }
  bool number_float(number_float_t, const string_t& text) { return add(Json(text)); }
  bool string(string_t& s) { return add(Json(s)); }
  bool binary(binary_t&) { return false; }
  bool start_object(std::size_t) { return open(Json::object()); }
  bool key(string_t& k) {
    if (stack_.back()->contains(k)) {
      error_ = "the member " + quoted_text(k) + " appears twice";
      return false;
    }
    key_ = k;
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    std::string what = e.what();
    const auto bracket = what.find("] ");
    if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) what.erase(0, bracket + 2);
    // The parser's message quotes the input it read: keep it short and printable.
    std::string printable;
    for (const char ch : what.substr(0, 200)) {
      const auto b = static_cast<unsigned char>(ch);
      if (b >= 0x20 && b < 0x7f) {
        printable += ch;
      } else {
        char hex[8];
        std::snprintf(hex, sizeof hex, "\\x%02X", b);
        printable += hex;
      }
    }
    if (what.size() > 200) printable += "...";
    error_ = "not a JSON object (" + printable + ")";
    if (what.find("number overflow") != std::string::npos)
      error_ += "; write numbers beyond the range of doubles as strings, \"1e400\"";
    (void)position;
    return false;
  }

  Json root;
  std::string error_;

 private:
  bool add(Json v) {
    if (stack_.empty()) {
      root = std::move(v);
      return true;
    }
    Json& top = *stack_.back();
    if (top.is_array()) top.push_back(std::move(v));
    else top[key_] = std::move(v);
    return true;
  }
  bool open(Json v) {
    if (stack_.size() >= 8) {
      error_ = "nested more than 8 levels deep";
      return false;
    }
    Json* slot;
    if (stack_.empty()) {
      root = std::move(v);
      slot = &root;
    } else if (stack_.back()->is_array()) {
      stack_.back()->push_back(std::move(v));
      slot = &stack_.back()->back();
    } else {
      slot = &((*stack_.back())[key_] = std::move(v));
    }
    stack_.push_back(slot);
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }
  std::vector<Json*> stack_;
  std::string key_;
};

// A channel: an integer, or the text of a decimal or p/q (a JSON number's own text, or a string).
Rational channel(const Json& v, const std::string& where) {
  std::string text;
  if (v.is_number_integer()) text = v.dump();
  else if (v.is_string()) text = v.get<std::string>();
  else throw std::invalid_argument(where + ": expected a number, found " + std::string(v.type_name()));
  Rational x;
  try {
    x = parse_rational(text);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(where + ": " + e.what());
  }
  if (sgn(x) < 0)
    throw std::invalid_argument(where + " is negative (" + text.substr(0, 40) +
                                "): a linear sensor response must be >= 0");
  return x;
}

Colour colour(const Json& v, const std::string& where) {
  if (!v.is_array() || v.size() != 3)
    throw std::invalid_argument(where + ": expected [r, g, b], three numbers");
  return {channel(v[0], where + "[0]"), channel(v[1], where + "[1]"), channel(v[2], where + "[2]")};
}

std::string scene_error(const SceneInputError& e, const std::string& file, std::size_t line,
                        const std::string& canonical_file) {
  std::string problem = e.what();
  if (e.problem == SceneProblem::nonpositive_blue)
    problem += "; use --nonpositive-blue drop to skip such colours";
  if (e.input == SceneInput::image && e.problem == SceneProblem::too_large && !e.index)
    problem = "against the canonical gamut of " + canonical_file + ", " + problem;
  std::string where;
  if (e.input == SceneInput::truth) where = "truth: ";
  else if (e.index) where = "colours[" + std::to_string(*e.index) + "]: ";
  return InputError(file, line, where + problem).what();
}

}  // namespace

void parse_batch_scene(const std::string& text, const std::string& file, BatchScene& scene) {
  ExactSax sax;
  if (!Json::sax_parse(text, &sax, nlohmann::detail::input_format_t::json, true))
    throw InputError(file, scene.line, sax.error_.empty() ? "not a JSON object" : sax.error_);
  const Json& j = sax.root;
  if (!j.is_object())
    throw InputError(file, scene.line, "expected a JSON object {\"colours\": [[r,g,b], ...]}");
  if (j.contains("id")) scene.id = j["id"];
  try {
    for (const auto& [k, v] : j.items())
      if (k != "id" && k != "colours" && k != "truth")
        throw std::invalid_argument("unknown member " + quoted_text(k) +
                                    " (a scene has id, colours and truth)");
    if (!j.contains("colours"))
      throw std::invalid_argument("no \"colours\" member (a list of [r, g, b])");
    const Json& c = j["colours"];
    if (!c.is_array() || c.empty())
      throw std::invalid_argument("\"colours\" must be a non-empty list of [r, g, b]");
    if (c.size() > max_colours)
      throw std::invalid_argument("more than " + std::to_string(max_colours) +
                                  " colours, the limit for one image");
    scene.colours.reserve(c.size());
    for (std::size_t i = 0; i < c.size(); ++i)
      scene.colours.push_back(colour(c[i], "colours[" + std::to_string(i) + "]"));
    if (j.contains("truth")) scene.truth = colour(j["truth"], "truth");
  } catch (const std::invalid_argument& e) {
    throw InputError(file, scene.line, e.what());
  }
}

namespace {

// One scene's record as a line of text, whether it is an error record, and whether the scene
// gave a truth (for the warning, written in order by the caller).
struct BatchRecord {
  std::string text;
  bool failed = false, truth = false;
};

BatchRecord batch_record(const PreparedCanonical& prepared, bool record_form, std::size_t number,
                         std::string_view text, const std::string& file, const std::string& canonical_file) {
  BatchRecord out;
  BatchScene scene;
  scene.line = number;
  Json record;
  record["line"] = number;
  try {
    if (!parse_plain_batch_scene(text, scene)) parse_batch_scene(std::string(text), file, scene);
    if (!scene.id.is_null()) record["id"] = scene.id;
    out.truth = scene.truth.has_value();
    if (record_form) {
      out.text = record_text(number, scene.id, select_scene_record(prepared, scene.colours, scene.truth, prepared.options));
      return out;
    }
    Json members = scene_json(prepared, select_scene(prepared, scene.colours, scene.truth), false);
    for (auto& [k, v] : members.items()) record[k] = std::move(v);
  } catch (const InputError& e) {
    if (!scene.id.is_null()) record["id"] = scene.id;
    record["error"] = e.what();
    out.failed = true;
  } catch (const SceneInputError& e) {
    record["error"] = scene_error(e, file, number, canonical_file);
    out.failed = true;
  }
  // Invalid UTF-8 can only come from the input quoted in a message: replaced, not fatal.
  out.text = record.dump(-1, ' ', false, Json::error_handler_t::replace) + '\n';
  return out;
}

}  // namespace

namespace {

// The non-blank lines of a scene file with their 1-based numbers; the scene limit is checked
// before any work. \throws InputError beyond max_batch_scenes or with no scene.
std::vector<std::pair<std::size_t, std::string_view>> scene_lines(std::string_view text, const std::string& file) {
  std::vector<std::pair<std::size_t, std::string_view>> lines;
  for (std::size_t number = 1; !text.empty(); ++number) {
    const auto end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    if (lines.size() == max_batch_scenes)
      throw InputError(file, number,
                       "more than " + std::to_string(max_batch_scenes) + " scenes, the limit for one file: split the file");
    lines.emplace_back(number, line);
  }
  if (lines.empty()) throw InputError(file, 0, "no scenes (expected JSON Lines, one scene a line)");
  return lines;
}

}  // namespace

int run_select_batch(const SelectOptions& o, const SelectSettings& settings) {
  const ColourTable canonical = read_colour_csv(o.canonical_path);
  std::optional<ColourTable> illuminants;
  if (!o.illuminants_path.empty()) illuminants = read_colour_csv(o.illuminants_path);
  SelectSceneOptions options = settings.scene;
  if (illuminants) options.illuminants = illuminants->colours;
  std::optional<PreparedCanonical> prepared;
  try {
    prepared.emplace(prepare_canonical(canonical.colours, options));
  } catch (const SceneInputError& e) {
    throw select_input_error(e, canonical, nullptr, illuminants ? &*illuminants : nullptr);
  }
  const std::string& file = o.images_path;
  const std::string text =
      read_text_file(file, {max_scene_file_bytes, "scene file", "JSON Lines, one scene a line"});

  // The scenes' lines, then their records made by the worker threads and written in input
  // order as they come (a scene's record can take megabytes against a large canonical gamut: only
  // a few are held at once).
  const std::vector<std::pair<std::size_t, std::string_view>> lines = scene_lines(text, file);
  write_stdout(json_lines_preamble());
  const unsigned threads = settings.threads ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
  std::size_t failed = 0;
  bool warned = settings.canonical_illuminant_given;
  in_order<BatchRecord>(
      lines.size(), threads,
      [&](std::size_t k) {
        return batch_record(*prepared, settings.record, lines[k].first, lines[k].second, file, canonical.file);
      },
      [&](BatchRecord r) {
        if (r.truth && !warned) {
          warn_default_canonical_illuminant("--images (a scene's \"truth\")");
          warned = true;
        }
        failed += r.failed;
        write_stdout(r.text);
      });
  const std::size_t scenes = lines.size();
  if (failed) {
    std::cerr << "gmcc: error: " << file << ": " << failed << " of " << scenes
              << " scenes could not be selected; their records carry \"error\" with the line\n";
    return 2;
  }
  return 0;
}

}  // namespace gmcc::cli
