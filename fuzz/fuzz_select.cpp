// Fuzz target: `gmcc select` end to end, in-process, on arbitrary bytes.
// Input: one byte of options, then the canonical file's text, a `|`, and the image file's text
// (no `|`: the image is the canonical text again). The run must either throw gmcc::InputError
// with a one-line message naming a file or option, or produce the whole output: with --json one
// JSON document whose every approximate number is a number (never null), whose exact maps lie
// in the exact feasible set it reports, and whose enclosures hold their maps.

#include "fuzz_support.h"

#include "select.h"

#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/rational.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace {
using gmcc::Point2;
using gmcc::Rational;
using Json = nlohmann::json;

Rational exact(const Json& j) {
  FUZZ_CHECK(j.is_string(), "an exact number is not a string: " + j.dump());
  Rational r;
  FUZZ_CHECK(r.set_str(j.get<std::string>(), 10) == 0, "not a rational: " + j.dump());
  r.canonicalize();
  FUZZ_CHECK(gmcc::to_string(r) == j.get<std::string>(), "not canonical: " + j.dump());
  return r;
}

Point2 exact_pair(const Json& j) {
  FUZZ_CHECK(j.is_array() && j.size() == 2, "not a pair: " + j.dump());
  return {exact(j[0]), exact(j[1])};
}

void check_number_pair(const Json& j) {
  FUZZ_CHECK(j.is_array() && j.size() == 2 && j[0].is_number() && j[1].is_number(),
             "not a pair of numbers: " + j.dump());
}

// A convex set as the JSON reports it; its own exact vertices, checked against its kind.
gmcc::ConvexSet2 convex_set(const Json& j) {
  static const char* kinds[] = {"polygon", "segment", "point", "empty"};
  gmcc::ConvexSet2 s;
  const std::string kind = j.at("kind").get<std::string>();
  int k = 0;
  while (k < 4 && kind != kinds[k]) ++k;
  FUZZ_CHECK(k < 4, "unknown kind " + kind);
  s.kind = static_cast<gmcc::ConvexKind>(k);
  for (const Json& v : j.at("vertices")) s.vertices.push_back(exact_pair(v));
  const std::size_t n = s.vertices.size();
  FUZZ_CHECK(s.kind == gmcc::ConvexKind::polygon ? n >= 3 : n == static_cast<std::size_t>(3 - k),
             "kind " + kind + " with " + std::to_string(n) + " vertices");
  FUZZ_CHECK(j.at("vertices_approx").size() == n, "vertices_approx count");
  for (const Json& v : j.at("vertices_approx")) check_number_pair(v);
  FUZZ_CHECK(gmcc::canonical_convex_set(s.vertices) == s, "vertices not in canonical form");
  FUZZ_CHECK(exact(j.at("area")) == gmcc::area(s), "area");
  return s;
}

void check_json(const std::string& out) {
  const Json j = Json::parse(out);  // throws (a finding) unless exactly one JSON document
  FUZZ_CHECK(j.is_object(), "not an object");
  const gmcc::ConvexSet2 F = convex_set(j.at("feasible_set"));
  convex_set(j.at("canonical_gamut"));
  const Json& selections = j.at("selections");
  FUZZ_CHECK(selections.size() == (F.kind == gmcc::ConvexKind::empty ? 0u : 3u),
             "selections for kind " + gmcc::to_string(F.kind));
  for (const auto& [rule, s] : selections.items()) {
    if (s.contains("note") && s.at("map").is_null()) {
      // No map: Monte Carlo, quadrature out of range, or the closed form at a forced precision.
      FUZZ_CHECK(rule == "mean_3d" && s.at("error_bounds").is_null() &&
                     (s.at("method") == "monte-carlo" || s.at("method") == "quadrature" ||
                      s.contains("precision_bits")),
                 rule + ": a note without a failed route");
      continue;
    }
    check_number_pair(s.at("map"));
    const double bound = s.at("error_bound").get<double>();
    FUZZ_CHECK(std::isfinite(bound) && bound >= 0, rule + ": error bound " + std::to_string(bound));
    // Per component bounds, their maximum, and the correct-rounding flags (docs/cli.md).
    const Json& bounds = s.at("error_bounds");
    check_number_pair(bounds);
    FUZZ_CHECK(std::max(bounds[0].get<double>(), bounds[1].get<double>()) == bound,
               rule + ": error_bound is not the larger of error_bounds");
    const Json& rounded = s.at("correctly_rounded");
    FUZZ_CHECK(rounded.size() == 2 && rounded[0].is_boolean() && rounded[1].is_boolean(),
               rule + ": correctly_rounded");
    if (s.at("method") == "exact")
      FUZZ_CHECK(rounded[0].get<bool>() && rounded[1].get<bool>(), rule + ": exact map not rounded");
    // A map with a note: the closed form that could not decide the nearest double.
    if (s.contains("note"))
      FUZZ_CHECK(s.at("method") == "analytic" && !(rounded[0].get<bool>() && rounded[1].get<bool>()),
                 rule + ": a note beside a correctly rounded map");
    const double worst = s.at("worst_case_deg").get<double>();
    FUZZ_CHECK(worst >= 0 && worst <= 180, rule + ": worst case " + std::to_string(worst));
    if (s.contains("worst_case_illuminant_deg")) {
      const double w = s.at("worst_case_illuminant_deg").get<double>();
      FUZZ_CHECK(w >= 0 && w <= 180, rule + ": illuminant worst case " + std::to_string(w));
    }
    if (s.contains("map_exact"))
      FUZZ_CHECK(gmcc::contains(F, exact_pair(s.at("map_exact"))), rule + ": map_exact not in F");
    if (s.contains("enclosure")) {
      for (int k = 0; k < 2; ++k) {
        const Json& e = s.at("enclosure")[k];
        check_number_pair(e);
        const double m = s.at("map")[k].get<double>();
        FUZZ_CHECK(e[0].get<double>() <= m && m <= e[1].get<double>(),
                   rule + ": map outside its enclosure");
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t flags = data[0];
  const std::string rest(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::size_t bar = rest.find('|');
  const std::string canonical_text = rest.substr(0, bar);
  const std::string image_text = bar == std::string::npos ? rest : rest.substr(bar + 1);

  // Options from the flag bits; small Monte Carlo and quadrature sizes keep each run short.
  gmcc::cli::SelectOptions o;
  o.json = flags & 1;
  o.mean3d_method = (flags >> 1 & 3) == 2 ? "quadrature" : (flags >> 1 & 3) == 3 ? "monte-carlo" : "analytic";
  o.order = "4";
  o.samples = "3000";
  o.seed = std::to_string(flags);
  switch (flags >> 3 & 3) {
    case 1: o.expand_policy = "centroid-clip", o.expand_factor = "1/10"; break;
    case 2: o.expand_policy = "multiplicative", o.expand_factor = "1/10"; break;
    case 3: o.expand_policy = "multiplicative", o.expand_factor = "1"; break;
    default: break;
  }
  if (flags & 32) o.nonpositive_blue = "reject";
  if (flags & 64) o.canonical_illuminant = "2,1,3/7";
  if (flags & 128) o.precision_bits = "60";

  std::string out;
  try {
    const gmcc::cli::SelectSettings settings = gmcc::cli::select_settings(o);
    const gmcc::ColourTable canonical = gmcc::parse_colour_csv(canonical_text, "canonical.csv");
    const gmcc::ColourTable image = gmcc::parse_colour_csv(image_text, "image.csv");
    out = gmcc::cli::select_output(settings, canonical, image);
  } catch (const gmcc::InputError& e) {
    const std::string message = e.what();
    FUZZ_CHECK(message.rfind("canonical.csv", 0) == 0 || message.rfind("image.csv", 0) == 0 ||
                   message.rfind("--expand", 0) == 0,
               "message names no file: " + message);
    FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line");
    FUZZ_CHECK(message.size() <= 400, "a message of " + std::to_string(message.size()) + " bytes");
    return 0;
  }
  FUZZ_CHECK(!out.empty() && out.back() == '\n', "output not ended by a newline");
  if (o.json)
    check_json(out);
  else
    FUZZ_CHECK(out.find("feasible set: ") != std::string::npos, "summary without the feasible set");
  return 0;
}
