// Fuzz target: `gmcc select` end to end, in-process, on arbitrary bytes.
// Input: two bytes of options, then the canonical file's text, a `|`, the image file's text, and
// optionally a second `|` and a file of plausible lights (--illuminants). No `|`: the image is the
// canonical text again. The run must either throw gmcc::InputError with a one-line message naming
// a file or option, or produce the whole output: with --json one JSON document whose every
// approximate number is a number (never null), whose exact maps lie in the exact feasible set it
// reports, and whose enclosures hold their maps. The 2-D route runs select_output as run_select
// does; --space 3d runs run_select itself (it reads files: the texts are written to a temporary
// folder first) with standard output captured, and its JSON is checked the same way in 3-D.
#include "fuzz_support.h"

#include "select.h"

#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/intersection.h>
#include <gmcc/geometry/rational.h>

#include <nlohmann/json.hpp>

#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

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

// --illuminants and --on-empty (docs/cli.md): the constraint C and the set before it, and what
// the recovery reports, against the feasible set F reported.
void check_constraint_and_recovery(const Json& j, const gmcc::ConvexSet2& F) {
  const bool applied = j.contains("recovery") && j.at("recovery").at("applied").get<bool>();
  if (j.contains("constraint")) {
    const Json& c = j.at("constraint");
    const gmcc::ConvexSet2 C = convex_set(c);
    const gmcc::ConvexSet2 U = convex_set(c.at("unconstrained_feasible_set"));
    FUZZ_CHECK(c.at("illuminants").get<std::size_t>() >= 1, "a constraint of no illuminants");
    // Without recovery F is F ∩ C; a recovered F still keeps to C.
    if (!applied) FUZZ_CHECK(gmcc::intersection(U, C) == F, "F is not (F before the constraint) ∩ C");
    for (const gmcc::Point2& v : F.vertices) FUZZ_CHECK(gmcc::contains(C, v), "a vertex of F outside C");
  }
  if (!j.contains("recovery")) return;
  const Json& r = j.at("recovery");
  const std::string policy = r.at("policy").get<std::string>();
  FUZZ_CHECK(policy == "grow-canonical" || policy == "min-violation", "recovery policy " + policy);
  FUZZ_CHECK(!applied || F.kind != gmcc::ConvexKind::empty, "recovery applied, F still empty");
  if (!applied) return;
  FUZZ_CHECK(r.at("reason").is_string(), "recovery without the reason F was empty");
  convex_set(r.at("canonical_gamut"));
  if (policy == "grow-canonical") {
    const gmcc::Rational factor = exact(r.at("factor"));
    FUZZ_CHECK(r.at("factor_approx").is_number(), "factor_approx not a number");
    if (r.contains("empty_below"))
      FUZZ_CHECK(exact(r.at("empty_below")) < factor, "grow-canonical: empty_below >= factor");
  } else {
    // F was empty, so the least violation is positive (docs/cli.md, --on-empty).
    FUZZ_CHECK(sgn(exact(r.at("violation"))) > 0, "min-violation: violation <= 0 for an empty F");
    FUZZ_CHECK(r.at("violation_approx").is_number(), "violation_approx not a number");
  }
}

void check_json(const std::string& out) {
  const Json j = Json::parse(out);  // throws (a finding) unless exactly one JSON document
  FUZZ_CHECK(j.is_object(), "not an object");
  const gmcc::ConvexSet2 F = convex_set(j.at("feasible_set"));
  convex_set(j.at("canonical_gamut"));
  check_constraint_and_recovery(j, F);
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


// ---- --space 3d ----

gmcc::Point3 exact_triple(const Json& j) {
  FUZZ_CHECK(j.is_array() && j.size() == 3, "not a triple: " + j.dump());
  return {exact(j[0]), exact(j[1]), exact(j[2])};
}

void check_number_triple(const Json& j) {
  FUZZ_CHECK(j.is_array() && j.size() == 3 && j[0].is_number() && j[1].is_number() && j[2].is_number(),
             "not a triple of numbers: " + j.dump());
}

// The 3-D document (cli/select_3d.cpp): F3 in canonical form with its exact volume, and each
// selection's map a finite number triple in its enclosure, its exact map (when rational) in F3
// and rounded to the reported doubles, an irrational map's edge an edge between vertices of F3.
void check_json_3d(const std::string& out) {
  const Json j = Json::parse(out);
  FUZZ_CHECK(j.is_object() && j.at("space") == "3d", "not a 3-D document");
  const Json& f = j.at("feasible_set");
  static const char* kinds[] = {"polytope", "polygon", "segment", "point", "empty"};
  const std::string kind = f.at("kind").get<std::string>();
  int k = 0;
  while (k < 5 && kind != kinds[k]) ++k;
  FUZZ_CHECK(k < 5, "unknown 3-D kind " + kind);
  std::vector<gmcc::Point3> vertices;
  for (const Json& v : f.at("vertices")) vertices.push_back(exact_triple(v));
  FUZZ_CHECK(f.at("vertices_approx").size() == vertices.size(), "vertices_approx count");
  for (const Json& v : f.at("vertices_approx")) check_number_triple(v);
  const auto faces = f.at("faces").get<std::vector<std::vector<std::size_t>>>();
  for (const auto& face : faces)
    for (std::size_t i : face) FUZZ_CHECK(i < vertices.size(), "a face index beyond the vertices");
  gmcc::ConvexSet3 F3{static_cast<gmcc::ConvexKind3>(k), vertices, faces};
  const std::size_t n = vertices.size();
  FUZZ_CHECK(k == 0 ? n >= 4 && faces.size() >= 4 : k == 1 ? n >= 3 && faces.size() == 1 : n == std::size_t(4 - k),
             "kind " + kind + " with " + std::to_string(n) + " vertices, " + std::to_string(faces.size()) + " faces");
  FUZZ_CHECK(gmcc::canonical_convex_set_3(F3.kind, vertices, faces) == F3, "F3 not in canonical form");
  FUZZ_CHECK(exact(f.at("volume")) == gmcc::volume(F3), "volume");
  FUZZ_CHECK(f.at("volume_approx").is_number(), "volume_approx not a number");
  const Json& selections = j.at("selections");
  FUZZ_CHECK(selections.size() == (F3.kind == gmcc::ConvexKind3::empty ? 0u : 2u),
             "3-D selections for kind " + kind);
  for (const auto& [rule, s] : selections.items()) {
    FUZZ_CHECK(rule == "max_volume" || rule == "centroid", "3-D rule " + rule);
    check_number_triple(s.at("map"));
    const double bound = s.at("error_bound").get<double>();
    FUZZ_CHECK(std::isfinite(bound) && bound >= 0, rule + ": error bound " + std::to_string(bound));
    const Json& e = s.at("enclosure");
    FUZZ_CHECK(e.is_array() && e.size() == 3, rule + ": enclosure");
    for (int c = 0; c < 3; ++c) {
      const double m = s.at("map")[c].get<double>();
      FUZZ_CHECK(std::isfinite(m), rule + ": map not finite");
      FUZZ_CHECK(e[c].size() == 2 && e[c][0].get<double>() <= m && m <= e[c][1].get<double>(),
                 rule + ": map outside its enclosure");
    }
    const std::string method = s.at("method").get<std::string>();
    FUZZ_CHECK(method == "exact" || method == "certified", rule + ": method " + method);
    FUZZ_CHECK(s.contains("map_exact") == (method == "exact"), rule + ": map_exact iff exact");
    if (s.contains("map_exact")) {
      const gmcc::Point3 m = exact_triple(s.at("map_exact"));
      FUZZ_CHECK(gmcc::contains(F3, m), rule + ": map_exact not in F3");
      const gmcc::Rational* c[3] = {&m.x, &m.y, &m.z};
      for (int i = 0; i < 3; ++i)
        FUZZ_CHECK(gmcc::to_double_nearest(*c[i]) == s.at("map")[i].get<double>(),
                   rule + ": map is not map_exact rounded to nearest");
      if (rule == "centroid") FUZZ_CHECK(m == gmcc::centroid(F3), "centroid: map_exact is not F3's centroid");
    }
    if (s.contains("exact_form")) {
      const Json& x = s.at("exact_form");
      for (const char* end : {"edge_from", "edge_to"})
        FUZZ_CHECK(std::find(vertices.begin(), vertices.end(), exact_triple(x.at(end))) != vertices.end(),
                   rule + ": " + end + " is not a vertex of F3");
      for (const Json& coefficient : x.at("quadratic")) exact(coefficient);
    }
    if (s.contains("worst_case_deg")) {
      const double w = s.at("worst_case_deg").get<double>();
      FUZZ_CHECK(w >= 0 && w <= 180, rule + ": worst case " + std::to_string(w));
    }
  }
}

// A folder of its own for the 3-D route's files, made once per process and removed at its exit
// (fork mode starts many processes).
const std::string& scratch_dir() {
  static const std::string dir = [] {
    char name[] = "/tmp/gmcc-fuzz-select-XXXXXX";
    FUZZ_CHECK(::mkdtemp(name) != nullptr, "cannot make a temporary folder");
    return std::string(name);
  }();
  static const bool cleanup = std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(scratch_dir(), ignored);
  }) == 0;
  (void)cleanup;
  return dir;
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  FUZZ_CHECK(out.good(), "cannot write " + path);
}

// std::cout into a string for the scope, restored on the way out (exceptions too).
class CaptureCout {
 public:
  CaptureCout() : old_(std::cout.rdbuf(buffer_.rdbuf())) {}
  ~CaptureCout() { std::cout.rdbuf(old_); }
  std::string text() const { return buffer_.str(); }

 private:
  std::ostringstream buffer_;
  std::streambuf* old_;
};

// The select options the two flag bytes choose. Options from the flag bits; small Monte Carlo
// and quadrature sizes keep each run short; the second byte 0 gives the options the first byte
// alone gave before it was added.
gmcc::cli::SelectOptions options_of(std::uint8_t flags, std::uint8_t more) {
  gmcc::cli::SelectOptions o;
  o.json = flags & 1;
  o.mean3d_method = (flags >> 1 & 3) == 2 ? "quadrature" : (flags >> 1 & 3) == 3 ? "monte-carlo" : "analytic";
  static const char* const orders[] = {"4", "1", "2", "16"};
  static const char* const samples[] = {"3000", "1", "10", "100"};
  // Each route's own options only: the others are refused (docs/cli.md, options that cannot apply).
  if (o.mean3d_method == "quadrature") o.order = orders[more >> 5 & 3];
  if (o.mean3d_method == "monte-carlo") o.samples = samples[more >> 5 & 3], o.seed = std::to_string(flags);
  switch (flags >> 3 & 3) {
    case 1: o.expand_policy = "centroid-clip", o.expand_factor = "1/10"; break;
    case 2: o.expand_policy = "multiplicative", o.expand_factor = "1/10"; break;
    case 3: o.expand_policy = "multiplicative", o.expand_factor = "1"; break;
    default: break;
  }
  if (flags & 32) o.nonpositive_blue = "reject";
  if (flags & 64) o.canonical_illuminant = "2,1,3/7";
  // Forced precisions: the lowest accepted, a low one, and one past the automatic first step.
  if (o.mean3d_method == "analytic") {
    if (flags & 128) o.precision_bits = more & 128 ? "53" : "60";
    else if (more & 128) o.precision_bits = "200";
  }
  static const char* const on_empty[] = {"none", "grow-canonical", "min-violation", "none"};
  o.on_empty = on_empty[more & 3];
  if (more & 4) {
    o.space = "3d";
    o.black = more & 8 ? "exclude" : "include";
    // The 2-D-only options must be refused; mostly they are left out so that the 3-D route runs.
    if (!(more & 16)) {
      o.expand_policy = "none", o.expand_factor = "0", o.on_empty = "none";
      o.mean3d_method = "analytic", o.order = "12", o.samples = "1000000", o.seed = "1";
      o.precision_bits = "0", o.canonical_illuminant = "1,1,1", o.nonpositive_blue = "drop";
    }
  }
  return o;
}

// An input error's message: names a file or an option first, one line, bounded in length.
void check_message(const std::string& message, bool space_3d) {
  const std::string dir = space_3d ? scratch_dir() + "/" : "";
  bool named = false;
  for (const std::string& name : {dir + "canonical.csv", dir + "image.csv", dir + "illuminants.csv",
                                  std::string("--expand"), std::string("--on-empty"),
                                  std::string("--illuminants"), std::string("--mean3d"),
                                  std::string("--precision"), std::string("--order"),
                                  std::string("--samples"), std::string("--seed"),
                                  std::string("--canonical-illuminant"),
                                  std::string("--nonpositive-blue")})
    named = named || message.rfind(name, 0) == 0;
  FUZZ_CHECK(named, "message names no file: " + message);
  FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line");
  FUZZ_CHECK(message.size() <= 400 + dir.size(), "a message of " + std::to_string(message.size()) + " bytes");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::uint8_t flags = data[0], more = data[1];
  const std::string rest(reinterpret_cast<const char*>(data) + 2, size - 2);
  const std::size_t bar = rest.find('|');
  const std::size_t bar2 = bar == std::string::npos ? bar : rest.find('|', bar + 1);
  const std::string canonical_text = rest.substr(0, bar);
  const std::string image_text = bar == std::string::npos ? rest : rest.substr(bar + 1, bar2 - bar - 1);
  const bool has_illuminants = bar2 != std::string::npos;
  const std::string illuminants_text = has_illuminants ? rest.substr(bar2 + 1) : std::string();

  gmcc::cli::SelectOptions o = options_of(flags, more);
  const bool space_3d = more & 4;

  std::string out;
  try {
    if (space_3d) {
      const std::string& dir = scratch_dir();
      o.canonical_path = dir + "/canonical.csv";
      o.image_path = dir + "/image.csv";
      write_file(o.canonical_path, canonical_text);
      write_file(o.image_path, image_text);
      if (has_illuminants && (more & 16)) {
        o.illuminants_path = dir + "/illuminants.csv";
        write_file(o.illuminants_path, illuminants_text);
      }
      CaptureCout capture;
      FUZZ_CHECK(gmcc::cli::run_select(o) == 0, "run_select returned non-zero without an error");
      out = capture.text();
    } else {
      o.image_path = "image.csv";  // the files are parsed below, in memory
      const gmcc::cli::SelectSettings settings = gmcc::cli::select_settings(o);
      const gmcc::ColourTable canonical = gmcc::parse_colour_csv(canonical_text, "canonical.csv");
      const gmcc::ColourTable image = gmcc::parse_colour_csv(image_text, "image.csv");
      std::optional<gmcc::ColourTable> illuminants;
      if (has_illuminants) illuminants = gmcc::parse_colour_csv(illuminants_text, "illuminants.csv");
      out = gmcc::cli::select_output(settings, canonical, image, illuminants ? &*illuminants : nullptr);
    }
  } catch (const gmcc::InputError& e) {
    check_message(e.what(), space_3d);
    return 0;
  }
  FUZZ_CHECK(!out.empty() && out.back() == '\n', "output not ended by a newline");
  if (space_3d) {
    if (o.json) check_json_3d(out);
    else FUZZ_CHECK(out.rfind("3-D feasible set", 0) == 0, "3-D summary without the feasible set");
  } else if (o.json) {
    check_json(out);
  } else {
    FUZZ_CHECK(out.find("feasible set: ") != std::string::npos, "summary without the feasible set");
  }
  return 0;
}
