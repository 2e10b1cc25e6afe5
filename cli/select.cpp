#include "select.h"

#include "integer_option.h"
#include "json_output.h"
#include "option_choices.h"
#include "select_3d.h"
#include "select_batch.h"
#include "write_stdout.h"

#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/input/colour_csv.h>

#include <iostream>

namespace gmcc::cli {
namespace {

// The options' defaults, to tell an option given from its default.
const SelectOptions kDefault{};

// Was the option given on the command line? Without the parsed command (an in-process caller),
// an option counts as given when it differs from its default.
bool given(const SelectOptions& o, const std::string& name, const std::string& value,
           const std::string& default_value) {
  return o.command ? o.command->count(name) > 0 : value != default_value;
}

// Options that cannot apply in this run are refused, each with the reason (docs/cli.md).
void reject_inapplicable(const SelectOptions& o) {
  auto is_given = [&o](const std::string& name, const std::string& value, const std::string& d) {
    return given(o, name, value, d);
  };
  const bool has_image = !o.image_path.empty(), has_images = !o.images_path.empty();
  if (has_image == has_images)
    throw InputError(has_image ? "--images" : "--image", 0,
                     has_image ? "give --image (one image) or --images (a batch), not both"
                               : "one of --image (one image) or --images (a batch) is required");
  if (!has_images && is_given("--threads", o.threads, "0"))
    throw InputError("--threads", 0, "worker threads apply to --images (a batch) only");
  if (o.space == "3d") {
    if (is_given("--expand", o.expand_factor, "0") || is_given("--expand-policy", o.expand_policy, "none"))
      throw InputError("--expand", 0, "expansion applies to the 2-D gamut only, not to --space 3d");
    if (is_given("--on-empty", o.on_empty, "none"))
      throw InputError("--on-empty", 0,
                       "recovery policies are 2-D only, not --space 3d; with --black include the "
                       "3-D feasible set is never empty");
    for (const auto& [name, value, d] :
         {std::tuple<std::string, std::string, std::string>{"--mean3d", o.mean3d_method, kDefault.mean3d_method},
          {"--precision", o.precision_bits, kDefault.precision_bits}, {"--order", o.order, kDefault.order},
          {"--samples", o.samples, kDefault.samples}, {"--seed", o.seed, kDefault.seed}})
      if (is_given(name, value, d))
        throw InputError(name, 0,
                         "the 3-D mean and its routes are 2-D rules; --space 3d selects max-volume "
                         "and the centroid exactly, with no route to choose");
    if (is_given("--canonical-illuminant", o.canonical_illuminant, "1,1,1"))
      throw InputError("--canonical-illuminant", 0,
                       "--space 3d reports no illuminant-space error, so the canonical light is "
                       "not used");
    if (is_given("--nonpositive-blue", o.nonpositive_blue, "drop"))
      throw InputError("--nonpositive-blue", 0,
                       "--space 3d maps colours, not chromaticities: a colour with b = 0 is used "
                       "as it is");
    if (!o.truth.empty())
      throw InputError("--truth", 0, "scoring against truth is 2-D only, not --space 3d");
    if (is_given("--illuminant-worst-case", o.illuminant_worst_case, "on"))
      throw InputError("--illuminant-worst-case", 0,
                       "--space 3d reports no illuminant-space worst case");
    if (has_images)
      throw InputError("--images", 0, "batch selection is 2-D only, not --space 3d");
    return;
  }
  if (is_given("--black", o.black, "include"))
    throw InputError("--black", 0, "black in the canonical gamut applies to --space 3d only");
  const std::string route = o.mean3d_method;
  if (route != "monte-carlo")
    for (const auto& [name, value, d] : {std::tuple<std::string, std::string, std::string>{
                                             "--samples", o.samples, kDefault.samples},
                                         {"--seed", o.seed, kDefault.seed}})
      if (is_given(name, value, d))
        throw InputError(name, 0, "applies to --mean3d monte-carlo only, not to the " + route +
                                      " route");
  if (route != "quadrature" && is_given("--order", o.order, kDefault.order))
    throw InputError("--order", 0, "applies to --mean3d quadrature only, not to the " + route + " route");
  if (route != "analytic" && is_given("--precision", o.precision_bits, kDefault.precision_bits))
    throw InputError("--precision", 0,
                     "applies to --mean3d analytic only, not to the " + route + " route");
  if (has_images && !o.truth.empty())
    throw InputError("--truth", 0,
                     "with --images each scene gives its own true light (its \"truth\" member)");
  if (o.record && !has_images)
    throw InputError("--record", 0, "the record form applies to --images (a batch) only");
  if (o.record && (route != "analytic" || is_given("--precision", o.precision_bits, kDefault.precision_bits)))
    throw InputError(route != "analytic" ? "--mean3d" : "--precision", 0,
                     "--record scores the exact 3-D mean: the closed form (--mean3d analytic) at the "
                     "automatic precision only");
}

}  // namespace

std::vector<Colour> plausible_lights(const std::string& path) {
  const ColourTable lights = read_colour_csv(path);
  require_pixel_colours(lights, "--illuminants");
  for (std::size_t i = 0; i < lights.colours.size(); ++i) {
    const Colour& l = lights.colours[i];
    if (sgn(l.r) <= 0 || sgn(l.g) <= 0 || sgn(l.b) <= 0)
      throw InputError(path, lights.lines[i], "a plausible light needs every channel > 0");
  }
  return lights.colours;
}

Colour light_option(const std::string& name, const std::string& text) {
  try {
    const ColourTable c = parse_colour_csv(text, name);
    if (c.colours.size() != 1) throw InputError(name, 0, "expected one r,g,b");
    const Colour& l = c.colours[0];
    for (const Rational* x : {&l.r, &l.g, &l.b})
      if (sgn(*x) <= 0) throw InputError(name, 0, "every channel must be > 0");
    return l;
  } catch (const InputError& e) {
    // Keep the reader's reason (a digit limit, a malformed number, a channel <= 0), without its
    // "NAME:1:" prefix.
    std::string why = e.what();
    const std::string prefix = e.source() + (e.line() ? ":" + std::to_string(e.line()) : "") + ": ";
    if (why.compare(0, prefix.size(), prefix) == 0) why.erase(0, prefix.size());
    throw InputError(name, 0, quoted_text(text) + " is not a light r,g,b with channels > 0: " + why);
  }
}

CLI::App* add_select_command(CLI::App& app, SelectOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "select",
      "Feasible set of perspective diagonal maps for an image and a canonical gamut, and the "
      "three selection rules of Finlayson & Hordley (1999): max-area, 2-D mean, 3-D mean.");
  o.command = cmd;
  cmd->add_option("--canonical", o.canonical_path,
                  "canonical colours, one r,g,b per line (decimal or p/q, read exactly)")
      ->required();
  cmd->add_option("--image", o.image_path, "image colours, same format (or --images)");
  cmd->add_option("--images", o.images_path,
                  "batch: many images against the one canonical gamut, JSON Lines, one scene a "
                  "line {\"id\", \"colours\": [[r,g,b], ...], \"truth\": [r,g,b]}; prints JSON "
                  "Lines, one record a scene (docs/cli.md \"Batch selection\")");
  cmd->add_flag("--record", o.record,
                "with --images: one compact record a scene, certified doubles from enclosures, no "
                "exact rationals (docs/cli.md, \"Record contract\"); 3-5x faster");
  cmd->add_option("--threads", o.threads,
                  "with --images: worker threads (0: all cores); the records do not depend on it")
      ->capture_default_str();
  cmd->add_flag("--json", o.json, "print one JSON object (docs/cli.md, \"JSON output\") instead of a summary");
  cmd->add_option("--expand", o.expand_factor,
                  "expand the canonical gamut by this factor (0.1 = 10%; exact)")
      ->capture_default_str();
  cmd->add_option("--expand-policy", o.expand_policy, "none | centroid-clip | multiplicative")
      ->check(CLI::IsMember(expansion_policy_names()))
      ->capture_default_str();
  cmd->add_option("--mean3d", o.mean3d_method,
                  "route to the 3-D mean: analytic (closed form, certified bound), quadrature "
                  "(Duffy–Gauss–Legendre, estimated error) or monte-carlo (the paper's method, "
                  "standard error)")
      ->check(CLI::IsMember(mean3d_method_names()))
      ->capture_default_str();
  cmd->add_option("--precision", o.precision_bits,
                  "analytic: force one MPFI evaluation at this many bits, 53 to 2^20 "
                  "(default 0: automatic)");
  cmd->add_option("--order", o.order, "quadrature: Gauss–Legendre points per direction, 1 to 256")
      ->capture_default_str();
  cmd->add_option("--samples", o.samples, "monte-carlo: points drawn in the unit cube, 1 to 10^9")
      ->capture_default_str();
  cmd->add_option("--seed", o.seed, "monte-carlo: seed of the mt19937_64 generator, 0 to 2^64-1")
      ->capture_default_str();
  cmd->add_option("--canonical-illuminant", o.canonical_illuminant,
                  "r,g,b of the canonical light c, as the camera sees it: the maps c ⊘ e of "
                  "--illuminants and --truth, and the illuminant-space errors (exact numbers, "
                  "all > 0)")
      ->capture_default_str();
  cmd->add_option("--nonpositive-blue", o.nonpositive_blue,
                  "colours with b <= 0 have no chromaticity: drop (count them) or reject")
      ->check(CLI::IsMember(nonpositive_blue_policy_names()))
      ->capture_default_str();
  cmd->add_option("--illuminants", o.illuminants_path,
                  "plausible lights, one r,g,b per line: keep only the maps in the hull of their maps "
                  "c ⊘ e (Finlayson 1996; c is --canonical-illuminant, give it too); --space 3d: F3 "
                  "within the cone of their maps (Barnard's ECRULE), c white");
  cmd->add_option("--truth", o.truth,
                  "r,g,b of the true light under which the image was taken (as the camera sees "
                  "it): adds each rule's map-space, illuminant and reproduction errors against "
                  "its map c ⊘ e");
  cmd->add_option("--illuminant-worst-case", o.illuminant_worst_case,
                  "on: each rule's illuminant-space worst case (exact edge quartics, about a "
                  "third of a scene's time); off: leave it out")
      ->check(CLI::IsMember(switch_choices))
      ->capture_default_str();
  cmd->add_option("--on-empty", o.on_empty,
                  "when F is empty: none (report it), grow-canonical (least multiplicative "
                  "expansion of the canonical gamut, by bisection) or min-violation (maps of least "
                  "Chebyshev violation, exact LP)")
      ->check(CLI::IsMember(recovery_policy_names()))
      ->capture_default_str();
  cmd->add_option("--space", o.space,
                  "2d: perspective maps (d1/d3, d2/d3), the paper's rules; 3d: Forsyth's CRULE, "
                  "diagonal maps (d1, d2, d3) as an exact polytope, max-volume and centroid")
      ->check(CLI::IsMember(space_choices))
      ->capture_default_str();
  cmd->add_option("--black", o.black, "3d: include or exclude black (0,0,0) in the canonical gamut")
      ->check(CLI::IsMember(canonical_black_names()))
      ->capture_default_str();
  return cmd;
}

SelectSettings select_settings(const SelectOptions& o) {
  SelectSettings s;
  s.json = o.json;
  s.record = o.record;
  s.threads = static_cast<unsigned>(integer_option("--threads", o.threads, 0, 256));
  SelectSceneOptions& scene = s.scene;
  scene.on_empty = recovery_policy_from_string(o.on_empty);
  scene.nonpositive_blue = nonpositive_blue_policy_from_string(o.nonpositive_blue);
  scene.expansion = expansion_option(o.expand_factor, o.expand_policy);
  if (scene.on_empty == RecoveryPolicy::grow_canonical &&
      scene.expansion.policy == ExpansionPolicy::centroid_clip)
    throw InputError("--on-empty", 0,
                     "grow-canonical grows the gamut by the multiplicative policy; it cannot "
                     "continue a centroid-clip expansion (use --expand-policy multiplicative)");
  scene.illuminant_worst_case = o.illuminant_worst_case != "off";
  scene.canonical_illuminant = light_option("--canonical-illuminant", o.canonical_illuminant);
  s.canonical_illuminant_given = given(o, "--canonical-illuminant", o.canonical_illuminant, "1,1,1");
  if (!o.truth.empty()) s.truth = light_option("--truth", o.truth);

  Mean3dOptions& m = scene.mean3d;
  m.method = mean3d_method_from_string(o.mean3d_method);
  // Each value read exactly within its library range, then the library's own check; the CLI only
  // names the options its way.
  m.precision_bits = static_cast<unsigned>(integer_option("--precision", o.precision_bits, mean3d_precision_range));
  m.order = static_cast<unsigned>(integer_option("--order", o.order, mean3d_order_range));
  m.samples = integer_option("--samples", o.samples, mean3d_samples_range);
  m.seed = integer_option("--seed", o.seed, mean3d_seed_range);
  try {
    check_options(m);
  } catch (const OptionError& e) {
    throw InputError("--" + e.option, 0, e.what());
  }
  reject_inapplicable(o);  // after each value is checked: a malformed value is named as such
  return s;
}

InputError select_input_error(const SceneInputError& e, const ColourTable& canonical,
                              const ColourTable* image, const ColourTable* illuminants) {
  std::string problem = e.what();
  if (e.problem == SceneProblem::nonpositive_blue)
    problem += "; use --nonpositive-blue drop to skip such colours";
  auto in_table = [&](const ColourTable& t) {
    return InputError(t.file, e.index ? t.lines[*e.index] : 0, problem);
  };
  switch (e.input) {
    case SceneInput::canonical: return in_table(canonical);
    case SceneInput::image:
      if (!image) break;
      if (e.problem == SceneProblem::too_large && !e.index)
        problem = "against the canonical gamut of " + canonical.file + ", " + problem;
      return in_table(*image);
    case SceneInput::illuminants:
      if (illuminants) return in_table(*illuminants);
      return InputError("--illuminants", 0, problem);
    case SceneInput::truth: return InputError("--truth", 0, problem);
    case SceneInput::canonical_illuminant: return InputError("--canonical-illuminant", 0, problem);
    case SceneInput::expansion: return InputError("--expand", 0, problem);
    case SceneInput::on_empty: return InputError("--on-empty", 0, problem);
  }
  return InputError("--image", 0, problem);
}

std::string select_output(const SelectSettings& settings, const ColourTable& canonical,
                          const ColourTable& image, const ColourTable* illuminants) {
  SelectSceneOptions options = settings.scene;
  if (illuminants) options.illuminants = illuminants->colours;
  try {
    const PreparedCanonical prepared = prepare_canonical(canonical.colours, options);
    const SceneResult result = select_scene(prepared, image.colours, settings.truth);
    return settings.json ? select_json(prepared, result) : select_text(prepared, result);
  } catch (const SceneInputError& e) {
    throw select_input_error(e, canonical, &image, illuminants);
  }
}

void warn_default_canonical_illuminant(const std::string& option) {
  std::cerr << "gmcc: warning: " << option
            << ": the map c ⊘ e of a light uses the canonical light c, here the default 1,1,1; "
               "give --canonical-illuminant R,G,B (the canonical light as the camera sees it), "
               "or the maps may miss the true one (docs/cli.md \"gmcc select\")\n";
}

int run_select(const SelectOptions& o) {
  const SelectSettings settings = select_settings(o);
  if (o.space == "3d") return run_select_3d(o);
  if (!settings.canonical_illuminant_given) {
    if (!o.illuminants_path.empty()) warn_default_canonical_illuminant("--illuminants");
    if (settings.truth) warn_default_canonical_illuminant("--truth");
  }
  if (!o.images_path.empty()) return run_select_batch(o, settings);
  const ColourTable canonical = read_colour_csv(o.canonical_path);
  const ColourTable image = read_colour_csv(o.image_path);
  std::optional<ColourTable> illuminants;
  if (!o.illuminants_path.empty()) illuminants = read_colour_csv(o.illuminants_path);
  write_stdout(select_output(settings, canonical, image, illuminants ? &*illuminants : nullptr));
  return 0;
}

}  // namespace gmcc::cli
