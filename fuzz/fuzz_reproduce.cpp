// Fuzz target: `gmcc reproduce synthetic|camera`'s options, light names and spectral setup.
// Input: one byte of flags, then newline-separated option values in a fixed order (see `fields`
// below); a value present, even empty, is passed on the command line, an absent one is left at
// its default. The arguments go through the command line's own parser (add_reproduce_command,
// CLI11) and option checks (config_from in cli/reproduce.cpp), then the setup is built as
// `synthetic`/`camera` in cli/reproduce.cpp build it, from spectral tables read once from the
// shipped data/. In one run in two a small experiment follows: one scene per cell, at most two
// lights and two surfaces, one thread.
//
// Every run must either stop at a clear error — CLI11's ParseError (usage, exit 2), gmcc's
// InputError, or std::invalid_argument / std::domain_error from the light names (cli/reproduce.cpp
// turns both into an InputError naming --canonical or --lights) — with a non-empty one-line
// message, or build a setup in which every light's three channels (as the sensors see it,
// canonical and test) are > 0 and finite, and so are the true maps, as doubles too (the
// experiments report doubles); the surfaces' colours are >= 0. The small experiment must then
// give finite angles in [0°, 180°]; for the synthetic experiment (narrow-band sensors: the
// diagonal model holds exactly) every scene's feasible set holds the true map
// (docs/reproduction.md).

#include "fuzz_support.h"

// cli/reproduce.cpp's option checks and defaults live in its anonymous namespace; including the
// file (not linking it) makes them callable here unchanged.
#include "reproduce.cpp"

#include <gmcc/validation/experiment_report.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace {

// The spectral tables, read once per process (the Munsell and SFU tables are large).
struct Tables {
  gmcc::SpectralTable munsell, basis, sensors, sfu1995, macbeth, sfu_lights;
};

const Tables& tables() {
  static const Tables t = [] {
    const gmcc::cli::ReproduceOptions o;  // data_dir empty: the shipped data/
    using gmcc::cli::data_file;
    return Tables{gmcc::read_spectral_csv(data_file(o, "munsell_matt_1269_joensuu_5nm.csv")),
                  gmcc::read_spectral_csv(data_file(o, "cie_daylight_basis_S0_S1_S2.csv")),
                  gmcc::read_spectral_csv(data_file(o, "camera_sony_dxc930_sfu_4nm.csv")),
                  gmcc::read_spectral_csv(data_file(o, "sfu_reflect_db_1995_4nm.csv")),
                  gmcc::read_spectral_csv(data_file(o, "sfu_macbeth_24_4nm.csv")),
                  gmcc::read_spectral_csv(data_file(o, "sfu_lab_11_illuminants_4nm.csv"))};
  }();
  return t;
}

// The options whose values the input gives, in input order.
const char* const fields[] = {"--canonical", "--lights", "--scenes", "--surfaces", "--seed",
                              "--expand", "--expand-policy", "--shading", "--mean3d", "--noise",
                              "--canonical-surfaces"};

bool positive_finite(const gmcc::Rational& x) {
  if (sgn(x) <= 0) return false;
  const double d = gmcc::to_double_nearest(x);
  return std::isfinite(d) && d > 0;
}

void check_light(const gmcc::Rational (&channel)[3], const std::string& what) {
  for (int k = 0; k < 3; ++k)
    FUZZ_CHECK(positive_finite(channel[k]),
               what + ": channel " + std::to_string(k) + " = " + gmcc::to_string(channel[k]) +
                   " is not > 0 and finite as a double");
}

void check_setup(const gmcc::ExperimentSetup& setup, std::size_t lights_asked) {
  const gmcc::Colour& c = setup.canonical_light;
  const gmcc::Rational canonical[3] = {c.r, c.g, c.b};
  check_light(canonical, "canonical light");
  FUZZ_CHECK(setup.lights.size() == lights_asked, "lights: " + std::to_string(setup.lights.size()) +
                                                      " for " + std::to_string(lights_asked) + " names");
  FUZZ_CHECK(!setup.canonical_surfaces.empty(), "no canonical surfaces");
  for (const gmcc::TestLight& t : setup.lights) {
    const gmcc::Point3& d = t.true_diagonal_map;
    const gmcc::Rational map[3] = {d.x, d.y, d.z};
    check_light(map, t.name + ": true diagonal map");
    // The light as the sensors see it: d_k = canonical_k / light_k.
    const gmcc::Rational light[3] = {gmcc::Rational(c.r / d.x), gmcc::Rational(c.g / d.y),
                                     gmcc::Rational(c.b / d.z)};
    check_light(light, t.name);
    const gmcc::Rational perspective[3] = {t.true_map.x, t.true_map.y, gmcc::Rational(1)};
    check_light(perspective, t.name + ": true map");
    FUZZ_CHECK(t.true_map.x == d.x / d.z && t.true_map.y == d.y / d.z, t.name + ": true map is not d1/d3, d2/d3");
    FUZZ_CHECK(t.surfaces.size() >= 2, t.name + ": fewer than two surfaces");
    for (const gmcc::Colour& s : t.surfaces)
      FUZZ_CHECK(sgn(s.r) >= 0 && sgn(s.g) >= 0 && sgn(s.b) >= 0, t.name + ": a negative surface colour");
  }
}

void check_angle(double a, const std::string& what) {
  FUZZ_CHECK(std::isfinite(a) && a >= 0 && a <= 180, what + " = " + std::to_string(a));
}

void check_experiment(const gmcc::ExperimentResult& r, bool exact_model) {
  for (const gmcc::ExperimentCell& cell : r.cells) {
    const std::string where = cell.light + ", " + std::to_string(cell.surfaces) + " surfaces: ";
    FUZZ_CHECK(cell.scenes == r.config.scenes && cell.empty <= cell.scenes, where + "scene counts");
    FUZZ_CHECK(!exact_model || cell.empty == 0, where + "an empty feasible set under the exact diagonal model");
    FUZZ_CHECK(cell.rules.size() == r.rules.size(), where + "rule count");
    if (cell.empty == cell.scenes) continue;
    for (std::size_t k = 0; k < cell.rules.size(); ++k) {
      const gmcc::RuleStats& s = cell.rules[k];
      const std::string rule = where + r.rules[k];
      check_angle(s.error.mean, rule + " mean error");
      check_angle(s.error.median, rule + " median error");
      check_angle(s.error.max, rule + " max error");
      check_angle(s.worst_case.mean, rule + " mean worst case");
      check_angle(s.reproduction.mean, rule + " mean reproduction error");
      FUZZ_CHECK(!exact_model || s.truth_in_feasible_set == cell.scenes,
                 rule + ": the true map outside F under the exact diagonal model");
    }
  }
}

void check_message(const std::string& message) {
  FUZZ_CHECK(!message.empty(), "an empty message");
  FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line: " + message);
}

// The command line the input spells: one field's value a line, in `fields` order.
std::vector<std::string> arguments(bool camera, const std::string& text) {
  std::vector<std::string> args{"gmcc", "reproduce", camera ? "camera" : "synthetic"};
  std::size_t start = 0;
  for (std::size_t i = 0; i < std::size(fields) && start <= text.size(); ++i) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string value = text.substr(start, end - start);
    start = end + 1;
    if (std::string(fields[i]) == "--canonical-surfaces" && !camera) continue;  // camera only
    if (std::string(fields[i]) == "--noise" && !camera) continue;
    // `--lights=` keeps a value that starts with '-' a value (CLI11 reads `--lights -x` as two options).
    args.push_back(std::string(fields[i]) + "=" + value);
  }
  return args;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t flags = data[0];
  const bool camera = flags & 1, run_scene = flags & 2;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);

  const std::vector<std::string> args = arguments(camera, text);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());

  CLI::App app{"gmcc"};
  gmcc::cli::ReproduceOptions o;
  gmcc::cli::add_reproduce_command(app, o);
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    check_message(e.what());
    return 0;
  }

  const Tables& t = tables();
  gmcc::ExperimentConfig config;
  gmcc::ExperimentSetup setup;
  std::size_t lights_asked = 0;
  try {
    config = gmcc::cli::config_from(o);
    // As cli/reproduce.cpp's synthetic(o) and camera(o), with the tables already read: the light
    // count first, then the names (which those wrappers check one by one to blame --canonical or
    // --lights; the setup throws the same errors unwrapped).
    gmcc::cli::check_light_count(o.lights);
    if (camera) {
      setup = gmcc::camera_setup(t.sensors, o.canonical_surfaces == "macbeth" ? t.macbeth : t.sfu1995, t.macbeth,
                                 t.sfu_lights, o.canonical.empty() ? "solux-4700" : o.canonical,
                                 o.lights.empty() ? gmcc::cli::camera_lights : o.lights);
      lights_asked = o.lights.empty() ? gmcc::cli::camera_lights.size() : o.lights.size();
    } else {
      setup = gmcc::synthetic_setup(t.munsell, t.basis, o.canonical.empty() ? "D55" : o.canonical,
                                    o.lights.empty() ? gmcc::cli::paper_lights : o.lights);
      lights_asked = o.lights.empty() ? gmcc::cli::paper_lights.size() : o.lights.size();
    }
  } catch (const gmcc::InputError& e) {
    check_message(e.what());
    return 0;
  } catch (const std::invalid_argument& e) {
    FUZZ_CHECK(!camera, std::string("camera setup: std::invalid_argument: ") + e.what());
    check_message(e.what());
    return 0;
  } catch (const std::domain_error& e) {
    FUZZ_CHECK(!camera, std::string("camera setup: std::domain_error: ") + e.what());
    check_message(e.what());
    return 0;
  }
  check_setup(setup, lights_asked);
  if (!run_scene) return 0;

  // A small experiment: one scene per cell, at most two lights and two surface counts.
  config.scenes = 1;
  config.max_surfaces = std::min(config.max_surfaces, 2);
  config.threads = 1;
  config.progress = nullptr;
  config.mean3d.samples = 1000;  // Monte Carlo's default 10^6 samples would take seconds a scene
  if (setup.lights.size() > 2) setup.lights.resize(2);
  gmcc::ExperimentResult result;
  try {
    result = gmcc::run_gamut_experiment(setup, config);
  } catch (const std::invalid_argument& e) {  // more surfaces than there are (report(): --surfaces)
    check_message(e.what());
    return 0;
  }
  check_experiment(result, !camera);
  FUZZ_CHECK(!gmcc::experiment_table(result).empty(), "an empty table");
  return 0;
}
