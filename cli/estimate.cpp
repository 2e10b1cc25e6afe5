#include "estimate.h"

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/selection/prepare_canonical.h>
#include <gmcc/selection/select_scene.h>
#include <gmcc/input/colour_csv.h>
#include <gmcc/input/image_file.h>
#include <gmcc/photo/corrected_image.h>
#include <gmcc/photo/estimate_3d.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "json_output.h"
#include "option_choices.h"
#include "output_files.h"
#include "provenance.h"
#include "raw_report.h"
#include "select.h"
#include "write_stdout.h"

namespace gmcc::cli {
namespace {

struct Settings {
  SelectSceneOptions scene;  // its illuminants: --illuminants, for either route
  PixelSettings pixels;
  std::optional<Colour> truth;                 // --truth: the one image's light
  std::map<std::string, TruthRow> truths;      // --truths: each image's light and own pixel rules
};

Settings settings_of(const EstimateOptions& o) {
  Settings s;
  s.pixels = pixel_settings(o.pixels);
  s.scene.canonical_illuminant = light_option("--canonical-illuminant", o.canonical_illuminant);
  if (!o.truth.empty()) {
    if (o.images.size() != 1)
      throw InputError("--truth", 0, "applies to one image; this run has " +
                                         std::to_string(o.images.size()));
    s.truth = light_option("--truth", o.truth);
  }
  if (!o.truths_path.empty()) {
    if (!o.truth.empty())
      throw InputError("--truths", 0, "give --truth (one image) or --truths (a file), not both");
    s.truths = truth_rows_by_image(read_truth_table(o.truths_path));
  }
  s.scene.expansion = expansion_option(o.expand_factor, o.expand_policy);
  s.scene.on_empty = recovery_policy_from_string(o.on_empty);
  s.scene.illuminant_worst_case = o.illuminant_worst_case != "off";
  if (!o.illuminants_path.empty()) s.scene.illuminants = plausible_lights(o.illuminants_path);
  return s;
}

std::string fixed(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

// An image read and made colours by the run's pixel rules and its own (its truth-table row): the
// image, the rules that held for it, a raw file's reading (its pattern empty for any other
// image) and the colours.
struct ReadImage {
  RgbImage image;
  PixelRules rules;
  RawImage raw;
  ImageColours colours;
};
ReadImage read_image_for(const std::string& path, const Settings& s, const EstimateOptions& o) {
  const TruthRow* row = s.truths.empty() ? nullptr : &truth_of_image(s.truths, path, o.truths_path);
  ReadImage r;
  r.colours = image_colours_of(path, s.pixels, &r.image, &r.rules, row, o.truths_path, &r.raw);
  return r;
}

// The run's output on stdout: the JSON document (its images last) or the summary.
int report(bool json, Json& document, Json images, const std::ostringstream& text) {
  if (json) {
    document["images"] = std::move(images);
    finish_document(document);
    write_stdout(document.dump(2) + "\n");
  } else {
    write_stdout(text.str());
  }
  return 0;
}

// --corrected DIR: the folder made and its outputs staged (written as they are made, put in place
// together at the end), after checking that no two images would write the same names: two
// inputs with one stem (a/x.png and b/x.png, or x.png and x.tif) are refused before any work.
std::unique_ptr<StagedFiles> corrected_output(const EstimateOptions& o) {
  if (o.corrected_dir.empty()) return nullptr;
  std::map<std::string, std::string> stems;
  for (const std::string& path : o.images) {
    const std::string stem = std::filesystem::path(path).stem().string();
    const auto [it, fresh] = stems.emplace(stem, path);
    if (!fresh)
      throw InputError("--corrected", 0, "images " + it->second + " and " + path + " have the same stem \"" + stem +
                                             "\": their corrected images would have the same names");
  }
  ensure_directory(o.corrected_dir);
  return std::make_unique<StagedFiles>(o.corrected_dir);
}

// The scene of one image's colours, with its true light if one is given; bad input as an
// InputError naming the image or the canonical file.
SceneResult select_image(const PreparedCanonical& prepared, const ColourTable& canonical, const Settings& s,
                         const std::string& truths_path, const std::string& path, const ImageColours& colours) {
  try {
    const std::optional<Colour> truth =
        s.truths.empty() ? s.truth : std::optional<Colour>(truth_of_image(s.truths, path, truths_path).light);
    return select_scene(prepared, colours.colours, truth);
  } catch (const SceneInputError& e) {
    if (e.input == SceneInput::image)
      throw InputError(path, 0, std::string(e.what()) +
                                    (e.problem == SceneProblem::no_usable_colour
                                         ? " (every kept pixel has b = 0 after the black level)"
                                         : ""));
    throw select_input_error(e, canonical, nullptr, nullptr);
  }
}

// An image's JSON record: the file, its size and depth, and what became of its pixels.
Json image_record(const std::string& path, const RgbImage& image, const ImageColours& colours) {
  Json record;
  record["file"] = path;
  record["width"] = image.width;
  record["height"] = image.height;
  record["bits"] = image.bits;
  record["pixels"] = {{"total", colours.counts.pixels},     {"masked", colours.counts.masked},
                      {"saturated", colours.counts.saturated}, {"dark", colours.counts.dark},
                      {"bright", colours.counts.bright},       {"kept", colours.counts.kept},
                      {"colours", colours.counts.colours},
                      {"hull_vertices", colours.counts.hull_vertices},
                      {"no_chromaticity", colours.counts.no_chromaticity}};
  return record;
}

// The summary's first line on an image: its size and what became of its pixels.
void describe_pixels(std::ostream& text, const std::string& path, const RgbImage& image,
                     const ImageColours& colours, const PixelRules& rules) {
  text << path << ": " << image.width << "x" << image.height << " (" << image.bits
       << "-bit), " << colours.counts.masked << " pixels masked, " << colours.counts.saturated
       << " saturated, ";
  if (colours.counts.dark || rules.dark_below || rules.dark_below_fraction)
    text << colours.counts.dark << " dark, ";
  if (colours.counts.bright || rules.bright_above_fraction) text << colours.counts.bright << " bright, ";
  text << colours.counts.kept << " kept, " << colours.counts.colours << " distinct colours";
  if (colours.set == ColourSet::hull && rules.bin == 1)
    text << ", " << colours.counts.hull_vertices << " on the chromaticity hull";
  if (colours.set == ColourSet::hull_3d) text << ", " << colours.counts.hull_vertices << " on the 3-D hull";
}

// The summary's lines on an image's pixels and its feasible set.
void describe_image(std::ostream& text, const std::string& path, const RgbImage& image, const ImageColours& colours,
                    const PixelRules& rules, const SceneResult& result, const RawImage& raw) {
  describe_pixels(text, path, image, colours, rules);
  text << "\n";
  if (!raw.pattern.empty()) text << raw_text(raw);
  text << "  feasible set: " << to_string(result.feasible.kind) << ", "
       << result.feasible.vertices.size() << " vertices\n";
}

}  // namespace

CLI::App* add_estimate_command(CLI::App& app, EstimateOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "estimate",
      "Estimate the light of linear camera images (8/16-bit PNG or TIFF, or camera raw files through "
      "LibRaw: DNG, CR2, NEF, ..., each Bayer quad one pixel) by gamut mapping: "
      "pixels to colours by explicit pre-processing (docs/conventions.md §8), then the feasible "
      "set and the three selection rules against one canonical gamut.");
  cmd->add_option("--canonical", o.canonical_path, "canonical colours, one r,g,b per line")
      ->required();
  add_images_argument(*cmd, o.images);
  add_pixel_options(*cmd, o.pixels);
  add_truths_option(*cmd, o.truths_path, ", for each rule's errors");
  cmd->add_option("--truth", o.truth,
                  "r,g,b of the true light (one image): each rule's errors against it")
      ->type_name("R,G,B");
  cmd->add_option("--canonical-illuminant", o.canonical_illuminant,
                  "r,g,b of the canonical light c: the estimate of map m is c ⊘ (m, 1)")
      ->capture_default_str();
  cmd->add_option("--expand", o.expand_factor, "expand the canonical gamut by this factor")
      ->capture_default_str();
  cmd->add_option("--expand-policy", o.expand_policy, "none | centroid-clip | multiplicative")
      ->check(CLI::IsMember(expansion_policy_names()))
      ->capture_default_str();
  cmd->add_option("--on-empty", o.on_empty, "none | grow-canonical | min-violation")
      ->check(CLI::IsMember(recovery_policy_names()))
      ->capture_default_str();
  cmd->add_option("--illuminants", o.illuminants_path,
                  "plausible lights, one r,g,b per line: only maps of plausible lights are kept (2d: "
                  "Finlayson's illumination constraint on perspective maps; 3d: the cone of their maps, "
                  "Barnard's ECRULE)");
  cmd->add_option("--illuminant-worst-case", o.illuminant_worst_case,
                  "on | off: each rule's illuminant-space worst case")
      ->check(CLI::IsMember(switch_choices))
      ->capture_default_str();
  cmd->add_flag("--json", o.json, "print one JSON document instead of a summary");
  cmd->add_option("--corrected", o.corrected_dir,
                  "write DIR/<image>_<rule>.png, the image white-balanced by each rule's map "
                  "(16-bit)");
  cmd->add_option("--space", o.space,
                  "2d: the perspective route (chromaticities, max-area, 2-D mean, 3-D mean); "
                  "3d: Forsyth's CRULE on the pixel colours against a 3-D canonical gamut "
                  "(gmcc canonical --space 3d), with max-volume, centroid and max-trace")
      ->check(CLI::IsMember(space_choices))
      ->capture_default_str();
  cmd->add_option("--rules", o.rules_3d,
                  "3d: the rules to apply, of max-volume, centroid, max-trace (default all)")
      ->delimiter(',')
      ->check(CLI::IsMember(rule_3_labels()));
  cmd->add_option("--black", o.black, "3d: include or exclude black (0,0,0) in the canonical gamut")
      ->check(CLI::IsMember(canonical_black_names()))
      ->capture_default_str();
  cmd->add_option("--centroid", o.centroid,
                  "3d: the centroid certified (a double with a rigorous bound) or exact (in Q)")
      ->check(CLI::IsMember(crule_3d_route_names()))
      ->capture_default_str();
  return cmd;
}

namespace {

// --space 3d's settings: the 2-D route's options refused, the colour set hull-3d unless given
// (hull refused: it passes chromaticity lifts).
Settings settings_3d(const EstimateOptions& o) {
  const CLI::App* cmd = o.pixels.command;
  for (const char* name : {"--expand", "--expand-policy", "--on-empty", "--illuminant-worst-case"}) {
    if (cmd && cmd->count(name))
      throw InputError(name, 0, "applies to the 2-D perspective route, not --space 3d");
    drop_recorded_option(name);  // the provenance lists what is in effect
  }
  PixelOptions pixel_options = o.pixels;
  if (cmd && cmd->count("--colour-set")) {
    if (o.pixels.colour_set == "hull")
      throw InputError("--colour-set", 0,
                       "hull passes chromaticity lifts, not pixel colours; --space 3d takes "
                       "hull-3d (the default) or distinct");
  } else {
    pixel_options.colour_set = "hull-3d";
    record_option_in_effect("--colour-set", "hull-3d");
  }
  EstimateOptions plain = o;
  plain.pixels = pixel_options;
  return settings_of(plain);
}

// The 3-D estimate's options: the canonical light, the centroid's route and the rules asked for.
Estimate3Options estimate3_options(const EstimateOptions& o, const Settings& s) {
  Estimate3Options options;
  options.canonical_light = s.scene.canonical_illuminant;
  options.route = crule_3d_route_from_string(o.centroid);
  options.exact_feasible_set = false;  // only its kind and vertex count are printed
  if (s.scene.illuminants) options.illuminants = *s.scene.illuminants;
  if (!o.rules_3d.empty()) {
    options.rules.clear();
    for (const std::string& r : o.rules_3d) options.rules.push_back(rule_3_from_string(r));
  }
  return options;
}

// One 3-D rule's answer: its line of the summary on `text`, and its JSON. Errors against a
// truth in their own spaces: the recovery error (light against light) and the map-space error,
// the space of the worst case, which bounds it whenever the truth is in F3.
Json rule_3d_output(std::ostream& text, Rule3 rule, const ImageSelection3& sel) {
  const MapEstimate3& m = sel.selection.estimate;
  Json j = {{"map", m.map}, {"method", m.method}, {"error_bound", m.error_bound}};
  if (sel.selection.worst_case_deg) j["worst_case_deg"] = *sel.selection.worst_case_deg;
  text << "  " << to_string(rule);
  if (sel.light) {
    const std::array<double, 3>& e = *sel.light;
    j["light"] = e;
    text << "  light (" << fixed(e[0], 6) << ", " << fixed(e[1], 6) << ", " << fixed(e[2], 6) << ")";
    if (sel.recovery_error_deg) {
      j["recovery_error_deg"] = *sel.recovery_error_deg;
      text << "  recovery error " << fixed(*sel.recovery_error_deg, 3) << " deg";
    }
  } else {
    text << "  no light (a map component is 0: likely dark pixels with a zero channel, which the default "
            "pixel rules keep; drop them with --dark 1 or --pixel-rule gijsenij)";
  }
  if (sel.map_error_deg) {
    j["map_error_deg"] = *sel.map_error_deg;
    text << "  map error " << fixed(*sel.map_error_deg, 3) << " deg";
  }
  if (sel.selection.worst_case_deg) text << "  worst case (map) " << fixed(*sel.selection.worst_case_deg, 3) << " deg";
  text << "\n";
  return j;
}

// With plausible lights and no rule's light: whether F3 itself holds a positive map (then the
// constraint removed every one: "F3 holds maps, none of a plausible light"), in the text and JSON.
void constraint_outcome(std::ostream& text, Json& record, const CanonicalConstraints3& prepared,
                        const ImageColours& colours, const Estimate3Options& options, const ImageEstimate3& r) {
  if (options.illuminants.empty()) return;
  bool any = false;
  for (Rule3 rule : options.rules) any = any || (r[rule] && r[rule]->light);
  Json c = {{"lights", options.illuminants.size()}, {"plausible_map", any}};
  if (!any) {
    Estimate3Options plain = options;
    plain.illuminants.clear();
    plain.truth.reset();
    plain.rules = {Rule3::max_trace};
    const ImageEstimate3 unconstrained = estimate_3d(prepared, colours, plain);
    const std::optional<ImageSelection3>& m = unconstrained[Rule3::max_trace];
    const bool f3_positive = m && m->light;
    c["unconstrained_positive_map"] = f3_positive;
    text << (f3_positive ? "  no light: F3 holds maps, none of a plausible light (F3 ∩ the cone of the "
                           "--illuminants lights' maps has no map with every component > 0)\n"
                         : "  no light: F3 itself holds no map with every component > 0\n");
  }
  record["constraint"] = std::move(c);
}

// `gmcc estimate --space 3d`: CRULE on each image's pixel colours against the prepared 3-D
// canonical gamut (gmcc/photo/estimate_3d.h).
int run_estimate_3d(const EstimateOptions& o) {
  Settings s = settings_3d(o);
  const Estimate3Options options = estimate3_options(o, s);
  const ColourTable canonical = read_colour_csv(o.canonical_path);
  require_pixel_colours(canonical, "--space 3d");
  const CanonicalBlack black = canonical_black_from_string(o.black);
  const CanonicalConstraints3 prepared(canonical.colours, black);
  const std::unique_ptr<StagedFiles> outputs = corrected_output(o);

  Json images = Json::array();
  std::ostringstream text;
  for (const std::string& path : o.images) {
    const auto [image, rules, raw, colours] = read_image_for(path, s, o);
    const std::optional<Colour> truth =
        s.truths.empty() ? s.truth : std::optional<Colour>(truth_of_image(s.truths, path, o.truths_path).light);
    ImageEstimate3 r;
    try {
      Estimate3Options with_truth = options;
      with_truth.truth = truth;
      r = estimate_3d(prepared, colours, with_truth);
    } catch (const UnboundedFeasibleSet& e) {
      throw InputError(path, 0, e.what());
    }
    Json record = image_record(path, image, colours);
    record["space"] = "3d";
    record["feasible_set"] = {{"kind", to_string(r.lazy_feasible.kind())}, {"vertices", r.lazy_feasible.size()}};
    Json estimates = Json::object();
    describe_pixels(text, path, image, colours, rules);
    text << "\n";
    if (!raw.pattern.empty()) {
      record["raw"] = raw_json(raw);
      text << raw_text(raw);
    }
    text << "  feasible set (3-D): " << to_string(r.lazy_feasible.kind()) << ", " << r.lazy_feasible.size()
         << " vertices\n";
    if (truth) {
      // Decided exactly on F3's rows (feasible_ray_3d.h): some positive multiple of c ⊘ e in F3.
      record["truth"] = {{"light", {to_string(truth->r), to_string(truth->g), to_string(truth->b)}},
                         {"in_feasible_set", *r.truth_in_feasible}};
      text << "  true light (" << fmt(to_double_nearest(truth->r)) << ", " << fmt(to_double_nearest(truth->g)) << ", "
           << fmt(to_double_nearest(truth->b)) << "): its map " << (*r.truth_in_feasible ? "inside" : "outside")
           << " the feasible set (up to intensity)\n";
    }
    for (Rule3 rule : options.rules) {
      const std::optional<ImageSelection3>& sel = r[rule];
      if (!sel) continue;
      estimates[to_string(rule)] = rule_3d_output(text, rule, *sel);
      if (outputs && sel->light) {
        const std::string stem = std::filesystem::path(path).stem().string();
        outputs->add(stem + "_" + to_string(rule) + ".png",
                     encode_png16(corrected_image(image, rules.black_level, rules.saturation.value_or(65536),
                                                  sel->selection.estimate.map)));
      }
    }
    if (r.lazy_feasible.kind() == ConvexKind3::empty)
      text << "  no estimate: no diagonal map takes every kept colour into the canonical gamut\n";
    constraint_outcome(text, record, prepared, colours, options, r);
    record["estimates"] = std::move(estimates);
    images.push_back(std::move(record));
  }
  if (outputs) outputs->commit();
  Json document;
  if (o.json) {
    document["space"] = "3d";
    document["canonical_gamut"] = {{"colours", canonical.colours.size()},
                                   {"black", o.black},
                                   {"half_spaces", prepared.half_spaces()}};
  }
  return report(o.json, document, std::move(images), text);
}

}  // namespace

int run_estimate(const EstimateOptions& o) {
  if (o.space == "3d") return run_estimate_3d(o);
  const CLI::App* cmd = o.pixels.command;
  for (const char* name : {"--rules", "--black", "--centroid"}) {
    if (cmd && cmd->count(name)) throw InputError(name, 0, "applies to --space 3d");
    drop_recorded_option(name);  // the provenance lists what is in effect
  }
  const Settings s = settings_of(o);
  const ColourTable canonical = read_colour_csv(o.canonical_path);
  const PreparedCanonical prepared = [&] {
    try {
      return prepare_canonical(canonical.colours, s.scene);
    } catch (const SceneInputError& e) {
      throw select_input_error(e, canonical, nullptr, nullptr);
    }
  }();
  // Files are put in place only once every image is done: nothing half-written on an error.
  const std::unique_ptr<StagedFiles> outputs = corrected_output(o);

  Json document;
  Json images = Json::array();
  std::ostringstream text;
  for (const std::string& path : o.images) {
    const auto [image, rules, raw, colours] = read_image_for(path, s, o);
    const SceneResult result = select_image(prepared, canonical, s, o.truths_path, path, colours);
    Json record = image_record(path, image, colours);
    Json estimates = Json::object();
    if (!raw.pattern.empty()) record["raw"] = raw_json(raw);
    describe_image(text, path, image, colours, rules, result, raw);
    for (Rule k : all_rules) {
      const std::optional<Selection>& sel = result.selections[k];
      if (!sel || !sel->estimate.valid) continue;
      const std::string key = to_string(k);
      const std::optional<std::array<double, 3>> light = light_of_perspective_map(sel->estimate.map, prepared.options.canonical_illuminant);
      if (!light) continue;  // a map component <= 0: no light
      const std::array<double, 3>& e = *light;
      estimates[key] = {{"map", sel->estimate.map}, {"light", e}};
      text << "  " << key << "  light (" << fixed(e[0], 6) << ", " << fixed(e[1], 6) << ", "
           << fixed(e[2], 6) << ")";
      if (result.truth) {
        const std::optional<RuleErrors>& t = result.truth->errors[k];
        if (t && t->positive_map) text << "  recovery error " << fixed(t->illuminant_error_deg, 3) << " deg";
      }
      text << "\n";
      if (outputs) {
        const std::string stem = std::filesystem::path(path).stem().string();
        outputs->add(stem + "_" + key + ".png",
                     encode_png16(corrected_image(image, rules.black_level, rules.saturation.value_or(65536),
                                                  {sel->estimate.map[0], sel->estimate.map[1], 1.0})));
      }
    }
    if (result.feasible.kind == ConvexKind::empty) text << "  no estimate: " << result.empty_reason << "\n";
    record["estimates"] = std::move(estimates);
    Json scene = scene_json(prepared, result, false);
    for (auto& [key, value] : scene.items()) record[key] = std::move(value);
    images.push_back(std::move(record));
  }
  if (outputs) outputs->commit();
  if (o.json)
    document["canonical_gamut"] = {{"colours", prepared.colours},
                                   {"vertices", prepared.gamut.vertices.size()}};
  return report(o.json, document, std::move(images), text);
}

}  // namespace gmcc::cli
