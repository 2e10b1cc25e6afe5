#include "reproduce.h"

#include <gmcc/selection/select_scene_options.h>

#include "integer_option.h"
#include "limit_exit.h"
#include "output_files.h"
#include "exit_cleanup.h"
#include "expansion_option.h"
#include "provenance.h"
#include "write_stdout.h"

#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/validation/camera_experiment.h>
#include <gmcc/input/colour_csv.h>
#include <gmcc/validation/experiment_report.h>
#include <gmcc/input/gehler_shi.h>
#include <gmcc/validation/gehler_shi_experiment.h>
#include <gmcc/validation/gehler_shi_report.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <algorithm>
#include <optional>
#include <tuple>

#ifndef GMCC_DATA_DIR
#define GMCC_DATA_DIR "data"
#endif

namespace gmcc::cli {
namespace {

// The paper's synthetic setting (§4) and our camera analogue's defaults.
const std::vector<std::string> paper_lights{"D75", "D100", "P2856", "P15000"};
const std::vector<std::string> camera_lights{"syl-50MR16Q", "solux-4700+3202"};

void add_common_options(CLI::App* cmd, ReproduceOptions& o) {
  cmd->add_option("--scenes", o.scenes, "scenes per light and surface count")->capture_default_str();
  cmd->add_option("--seed", o.seed, "seed of the scene generators (mt19937_64)")->capture_default_str();
  cmd->add_option("--surfaces", o.max_surfaces, "largest number of surfaces per scene (1 to it)")
      ->capture_default_str();
  cmd->add_option("--threads", o.threads, "worker threads (0: all cores); results do not depend on it")
      ->capture_default_str();
  cmd->add_option("--data", o.data_dir, "folder of the spectral data (default: the shipped data/)");
  cmd->add_option("--mean3d", o.mean3d_method, "route to the 3-D mean")
      ->check(CLI::IsMember(mean3d_method_names()))
      ->capture_default_str();
}

void add_output_options(CLI::App* cmd, ReproduceOptions& o) {
  cmd->add_option("--csv", o.csv_path, "write one row per (light, surfaces, rule) to this CSV file");
  cmd->add_option("--json", o.json_path, "write every cell's statistics as one JSON document to this file");
  cmd->add_option("--scenes-out", o.scenes_out_path,
                  "write one JSON Lines record per scene to this file (a setup line, then the "
                  "scenes: surfaces drawn, F, every rule's map and errors)");
  cmd->add_option("--shard", o.shard,
                  "run only part K of N disjoint parts of the scenes (K/N, e.g. 2/8); needs "
                  "--scenes-out; combine the parts with gmcc merge");
  cmd->add_option("--plot", o.plot_dir,
                  "write <experiment>.dat/.gp to this folder and draw .png/.svg with gnuplot");
  cmd->add_option("--canonical", o.canonical, "the canonical light");
  cmd->add_flag("--crule", o.crule,
                "also Forsyth's 3-D CRULE (max-volume and centroid), scored by their perspective "
                "maps; slow: ~0.2 s per scene");
  cmd->add_option("--shading", o.shading,
                  "intensity variation: each image colour scaled by a factor drawn from [S, 1] "
                  "(0: none); the 2-D rules do not see it, 3-D CRULE does")
      ->capture_default_str();
  cmd->add_option("--crule-black", o.crule_black,
                  "with --crule: black in CRULE's canonical gamut (include) or Forsyth's hull of the "
                  "canonical colours alone (exclude)")
      ->check(CLI::IsMember(canonical_black_names()))
      ->capture_default_str();
  cmd->add_flag("--crule-extended", o.crule_extended,
                "with --crule: also CRULE max-trace (max d1+d2+d3) and the 3-D cone mean of the "
                "perspective image of F3");
  cmd->add_option("--specular", o.specular,
                  "specular highlights: each image colour gets s times the test light's colour "
                  "added, s drawn from [0, S] per surface (0: none); every rule sees it")
      ->capture_default_str();
  cmd->add_option("--intensity", o.intensity,
                  "intensity change of the whole scene: every image colour scaled by one factor "
                  "drawn between K and 1 (K > 1: brighter; 0: none); the 2-D rules do not see it")
      ->capture_default_str();
  cmd->add_option("--illuminants", o.illuminants_path,
                  "plausible lights (r,g,b as the sensors see them): intersect every feasible set "
                  "with their maps (Finlayson 1996's illumination constraint)");
  cmd->add_option("--lights", o.lights, "the test lights")->delimiter(',');
  cmd->add_option("--expand", o.expand_factor, "expand the canonical gamut by this factor (0.1 = 10%)")
      ->capture_default_str();
  cmd->add_option("--expand-policy", o.expand_policy, "none | centroid-clip | multiplicative")
      ->check(CLI::IsMember(expansion_policy_names()))
      ->capture_default_str();
}

// At most kMaxLights test lights (docs/cli.md "Resource limits"): each is a column of every table.
constexpr std::size_t kMaxLights = 64;
void check_light_count(const std::vector<std::string>& lights) {
  if (lights.size() > kMaxLights)
    throw InputError("--lights", 0, std::to_string(lights.size()) + " lights given; at most " +
                                        std::to_string(kMaxLights));
}

std::string data_file(const ReproduceOptions& o, const char* name) {
  return (o.data_dir.empty() ? std::string(GMCC_DATA_DIR) : o.data_dir) + "/" + name;
}

// A non-negative option written as an exact decimal or fraction, at most `max` (or below it),
// as the nearest double (a positive value too small for one is refused); `range` says the rule.
double bounded_option(const char* name, const std::string& text, long max, bool max_allowed, const char* range) {
  try {
    const Rational q = parse_rational(text);
    if (sgn(q) < 0 || (max_allowed ? q > max : q >= max)) throw std::invalid_argument(range);
    const double d = to_double_nearest(q);
    if (sgn(q) > 0 && d <= 0) throw std::invalid_argument("too small to be a double");
    return d;
  } catch (const std::invalid_argument& e) {
    throw InputError(name, 0, e.what());
  }
}

// --shard K/N: this run's part, which needs --scenes-out and refuses the whole run's tables.
void set_shard(const ReproduceOptions& o, ExperimentConfig& c) {
  const std::string& t = o.shard;
  const std::size_t slash = t.find('/');
  const std::string why = "expected K/N with 1 <= K <= N <= 1000000 (part K of N), e.g. 2/8; got " + quoted_text(t);
  auto digits = [](const std::string& x) {
    return !x.empty() && x.size() <= 7 && x.find_first_not_of("0123456789") == std::string::npos;
  };
  if (slash == std::string::npos || !digits(t.substr(0, slash)) || !digits(t.substr(slash + 1)))
    throw InputError("--shard", 0, why);
  c.shard_index = std::stoull(t.substr(0, slash));
  c.shard_count = std::stoull(t.substr(slash + 1));
  if (c.shard_index < 1 || c.shard_index > c.shard_count || c.shard_count > 1000000)
    throw InputError("--shard", 0, why);
  if (o.scenes_out_path.empty())
    throw InputError("--shard", 0, "a shard needs --scenes-out FILE: gmcc merge combines the shards' files");
  for (const auto& [path, option] : {std::pair{&o.csv_path, "--csv"}, {&o.json_path, "--json"}, {&o.plot_dir, "--plot"}})
    if (!path->empty())
      throw InputError(option, 0, "not with --shard: a shard's statistics cover only its part; write "
                                  "--scenes-out and run gmcc merge on the shards' files for the whole tables");
}

ExperimentConfig config_from(const ReproduceOptions& o) {
  ExperimentConfig c;
  c.scenes = integer_option("--scenes", o.scenes, 1, 1000000);  // docs/cli.md "Resource limits"
  c.seed = integer_option("--seed", o.seed, 0, ~std::uint64_t(0));
  c.max_surfaces = static_cast<int>(integer_option("--surfaces", o.max_surfaces, 1, 24));
  c.threads = static_cast<unsigned>(integer_option("--threads", o.threads, 0, 256));
  c.mean3d.method = mean3d_method_from_string(o.mean3d_method);
  c.expansion = expansion_option(o.expand_factor, o.expand_policy);
  c.noise = bounded_option("--noise", o.noise, 1, true, "must be from 0 to 1");
  c.crule = o.crule;
  c.shading = bounded_option("--shading", o.shading, 1, false, "must be from 0 to below 1");
  c.crule_black = canonical_black_from_string(o.crule_black);
  c.crule_extended = o.crule_extended;
  if ((c.crule_extended || c.crule_black == CanonicalBlack::exclude) && !c.crule)
    throw InputError(c.crule_extended ? "--crule-extended" : "--crule-black", 0, "needs --crule");
  c.specular = bounded_option("--specular", o.specular, 100, true, "must be from 0 to 100");
  c.intensity = bounded_option("--intensity", o.intensity, 100, true, "must be from 0 to 100");
  if (!o.shard.empty()) set_shard(o, c);
  c.keep_scenes = !o.scenes_out_path.empty();
  if (::isatty(STDERR_FILENO))
    c.progress = [](std::uint64_t done, std::uint64_t total) {
      const int width = 40, filled = static_cast<int>(width * done / std::max<std::uint64_t>(total, 1));
      std::fprintf(stderr, "\r[%s%s] %llu/%llu scenes", std::string(filled, '#').c_str(),
                   std::string(width - filled, ' ').c_str(), static_cast<unsigned long long>(done),
                   static_cast<unsigned long long>(total));
      if (done == total) std::fputc('\n', stderr);
      std::fflush(stderr);
      set_progress_line_open(done != total);
    };
  return c;
}

}  // namespace

ExperimentOutputs::ExperimentOutputs(const ReportPaths& paths, const std::string& stem) : paths_(paths), stem_(stem) {
  if (!paths.csv.empty()) csv_.emplace(paths.csv);
  if (!paths.json.empty()) json_.emplace(paths.json);
  if (!paths.scenes_out.empty()) scenes_.emplace(paths.scenes_out);
  if (!paths.plot_dir.empty()) {
    ensure_directory(paths.plot_dir);
    dat_.emplace(std::filesystem::path(paths.plot_dir) / (stem + ".dat"));
    gp_.emplace(std::filesystem::path(paths.plot_dir) / (stem + ".gp"));
  }
}

int ExperimentOutputs::write(const ExperimentResult& result, const std::string& provenance, bool table) {
  set_activity("writing the reports");
  if (scenes_) scenes_->commit(experiment_scenes_jsonl(result, provenance));
  if (csv_) csv_->commit(experiment_csv(result, provenance));
  if (json_) json_->commit(experiment_json(result, provenance));
  if (dat_) dat_->commit(experiment_plot_data(result));
  if (gp_) gp_->commit(experiment_plot_script(result, stem_));
  if (result.config.shard_count > 1) {
    std::uint64_t scenes = 0;
    for (const ExperimentCell& c : result.cells) scenes += c.scenes;
    write_stdout("gmcc reproduce " + result.name + ": shard " + std::to_string(result.config.shard_index) + "/" +
                 std::to_string(result.config.shard_count) + ", " + std::to_string(scenes) +
                 " scenes written to " + paths_.scenes_out + " (gmcc merge combines the shards)\n");
    return 0;
  }
  if (!table) return 0;
  write_stdout(experiment_table(result));
  return paths_.plot_dir.empty() ? 0 : draw_with_gnuplot(paths_.plot_dir, stem_, "gmcc reproduce");
}

namespace {

// Runs an experiment and writes its table, CSV, JSON, scene records and figure, each file whole
// or not at all.
int report(const ExperimentSetup& setup, ExperimentConfig config, const ReproduceOptions& o) {
  if (!o.illuminants_path.empty()) {
    set_activity("reading " + o.illuminants_path);
    const ColourTable lights = read_colour_csv(o.illuminants_path);
    try {
      config.constraint = illumination_constraint(lights.colours, setup.canonical_light);
    } catch (const NonPositiveIlluminant& e) {
      throw InputError(lights.file, lights.lines[e.index], "an illuminant needs every channel > 0");
    }
  }
  ExperimentOutputs outputs({o.csv_path, o.json_path, o.scenes_out_path, o.plot_dir}, setup.name);
  ExperimentResult result;
  set_activity("running the " + setup.name + " experiment");
  try {
    result = run_gamut_experiment(setup, config);
  } catch (const SceneInputError& e) {
    throw InputError(e.input == SceneInput::expansion ? "--expand" : "--surfaces", 0, e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError("--surfaces", 0, e.what());
  }
  return outputs.write(result, provenance_json().dump());
}

ExperimentSetup synthetic(const ReproduceOptions& o) {
  const SpectralTable munsell = read_spectral_csv(data_file(o, "munsell_matt_1269_joensuu_5nm.csv"));
  const SpectralTable basis = read_spectral_csv(data_file(o, "cie_daylight_basis_S0_S1_S2.csv"));
  const std::string canonical = o.canonical.empty() ? "D55" : o.canonical;
  const std::vector<std::string>& lights = o.lights.empty() ? paper_lights : o.lights;
  // Each name checked against its own option first, so a message blames the right one.
  auto check = [&](const std::string& option, const std::string& name) {
    try {
      named_light(name, basis);
    } catch (const std::invalid_argument& e) {
      throw InputError(option, 0, e.what());
    } catch (const std::domain_error& e) {
      throw InputError(option, 0, e.what());
    }
  };
  check_light_count(lights);
  check("--canonical", canonical);
  for (const std::string& name : lights) check("--lights", name);
  return synthetic_setup(munsell, basis, canonical, lights);
}

ExperimentSetup camera(const ReproduceOptions& o) {
  const SpectralTable sfu_lights = read_spectral_csv(data_file(o, "sfu_lab_11_illuminants_4nm.csv"));
  const std::string canonical = o.canonical.empty() ? "solux-4700" : o.canonical;
  const std::vector<std::string>& lights = o.lights.empty() ? camera_lights : o.lights;
  auto check = [&](const std::string& option, const std::string& name) {
    std::string known;
    for (const Spectrum& s : sfu_lights.spectra) {
      if (s.name == name) return;
      known += (known.empty() ? "" : ", ") + s.name;
    }
    throw InputError(option, 0, "unknown light " + quoted_text(name) + " (the SFU lab lights: " + known + ")");
  };
  check_light_count(lights);
  check("--canonical", canonical);
  for (const std::string& name : lights) check("--lights", name);
  return camera_setup(read_spectral_csv(data_file(o, "camera_sony_dxc930_sfu_4nm.csv")),
                      read_spectral_csv(data_file(o, o.canonical_surfaces == "macbeth"
                                                         ? "sfu_macbeth_24_4nm.csv"
                                                         : "sfu_reflect_db_1995_4nm.csv")),
                      read_spectral_csv(data_file(o, "sfu_macbeth_24_4nm.csv")),
                      sfu_lights, canonical, lights);
}

// The expansion sensitivity table: the synthetic experiment with no expansion and with the
// paper's 10% under each policy; mean error per rule over all lights, for 1–5 and 6–11 surfaces.
int expansion_table(const ReproduceOptions& o) {
  const ExperimentSetup setup = synthetic(o);
  ExperimentConfig base = config_from(o);
  base.progress = nullptr;
  // The three runs' CSV rows (prefixed by the expansion) and scene records (a section each).
  std::optional<PendingFile> csv_file, scenes_file;
  if (!o.csv_path.empty()) csv_file.emplace(o.csv_path);
  if (!o.scenes_out_path.empty()) scenes_file.emplace(o.scenes_out_path);
  std::string csv, scenes;
  struct Row {
    std::string label;
    Expansion expansion;
  };
  const std::vector<Row> rows{{"none", {ExpansionPolicy::none, 0}},
                              {"centroid-clip 10%", {ExpansionPolicy::centroid_clip, Rational(1, 10)}},
                              {"multiplicative 10%", {ExpansionPolicy::multiplicative, Rational(1, 10)}}};
  std::cout << "gmcc reproduce expansion: synthetic experiment, " << base.scenes
            << " scenes per light and count, seed " << base.seed << "\n"
            << "mean map-space error (deg) over all lights; the true map lies in F in every scene "
               "for every policy\n\n"
            << "  policy                gamut     n = 1-5: max-area  2-D mean  3-D mean   n = 6-"
            << base.max_surfaces << ": max-area  2-D mean  3-D mean\n";
  for (const Row& row : rows) {
    ExperimentConfig c = base;
    c.expansion = row.expansion;
    const ExperimentResult r = run_gamut_experiment(setup, c);
    if (csv_file) {
      const std::string rows = experiment_csv(r);
      const std::string prefix = to_string(c.expansion.policy) + "," + to_string(c.expansion.factor) + ",";
      for (std::size_t start = 0, end; start < rows.size(); start = end + 1) {
        end = rows.find('\n', start);
        if (start == 0 && csv.empty()) csv += "expansion_policy,expansion_factor," + rows.substr(0, end + 1);
        else if (start != 0) csv += prefix + rows.substr(start, end + 1 - start);
      }
    }
    if (scenes_file) scenes += experiment_scenes_jsonl(r);
    double sum[2][3] = {}, count[2] = {};
    for (const ExperimentCell& cell : r.cells) {
      const int band = cell.surfaces <= 5 ? 0 : 1;
      count[band] += 1;
      for (int k = 0; k < 3; ++k) sum[band][k] += cell.rules[k].error.mean;
    }
    char line[256];
    std::snprintf(line, sizeof line, "  %-20s %3zu vertices %16.3f %9.3f %9.3f %20.3f %9.3f %9.3f\n",
                  row.label.c_str(), r.canonical_gamut.vertices.size(), sum[0][0] / count[0],
                  sum[0][1] / count[0], sum[0][2] / count[0], sum[1][0] / std::max(count[1], 1.0),
                  sum[1][1] / std::max(count[1], 1.0), sum[1][2] / std::max(count[1], 1.0));
    std::cout << line;
  }
  const std::string provenance = provenance_json().dump();
  if (csv_file) csv_file->commit("# gmcc-provenance: " + provenance + "\n" + csv);
  if (scenes_file) scenes_file->commit("{\"provenance\":" + provenance + "}\n" + scenes);
  return 0;
}

// The real-camera test on the Gehler–Shi charts: one run over both cameras (their images are
// the lights, grouped by camera, or camera and light group), the table of gehler_shi_report.h.
int gehler_shi(ReproduceOptions o) {
  o.scenes = o.gehler_scenes;
  if (!o.shard.empty())
    throw InputError("--shard", 0, "not for gehler-shi: gmcc merge does not know its light groups");
  ExperimentConfig config = config_from(o);
  GehlerShiOptions options;
  options.protocol = gehler_shi_protocol_from_string(o.protocol);  // checked by CLI11 already
  options.cameras.clear();
  for (const std::string& camera : o.cameras) {
    if (camera != "Canon1D" && camera != "Canon5D")
      throw InputError("--cameras", 0, "unknown camera " + quoted_text(camera) + " (Canon1D, Canon5D)");
    if (std::find(options.cameras.begin(), options.cameras.end(), camera) == options.cameras.end())
      options.cameras.push_back(camera);
  }
  for (const auto& [text, option, bound] : {std::tuple{&o.dark, "--dark", &options.dark}, {&o.clip, "--clip", &options.clip}}) {
    try {
      *bound = parse_rational(*text);
      if (sgn(*bound) < 0) throw std::invalid_argument("must be >= 0");
    } catch (const std::invalid_argument& e) {
      throw InputError(option, 0, e.what());
    }
  }
  if (options.dark >= options.clip) throw InputError("--dark", 0, "must be below --clip");
  // Patch numbers as written: digits between commas ("1.0", "1e1" and an empty field "1,,2" are
  // refused rather than read as numbers or skipped).
  for (const std::string& list : o.exclude_patches) {
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = list.find(',', start);
      const std::string k = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (k.empty() || k.find_first_not_of("0123456789") != std::string::npos)
        throw InputError("--exclude-patches", 0,
                         "expected patch numbers 1 to 24 separated by commas, not " + quoted_text(list));
      options.exclude_patches.push_back(static_cast<std::uint32_t>(integer_option("--exclude-patches", k, 1, 24)));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  const std::string patches = data_file(o, "gehler_shi_568_colorchecker_patch_rgb_rec2018.csv");
  const std::string truth = data_file(o, "gehler_shi_568_groundtruth.csv");
  set_activity("reading " + patches + " and " + truth);
  const ChartDataset data = read_gehler_shi(patches, truth);
  GehlerShiSetup setup;
  try {
    setup = gehler_shi_setup(data, options);
  } catch (const GehlerShiNothingUsable& e) {  // the options, not the file
    throw InputError(o.exclude_patches.empty() ? "--dark/--clip" : "--dark/--clip/--exclude-patches", 0, e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(patches, 0, e.what());
  }
  // The figure's files: gehler-shi.* (leave-one-out) or gehler-shi-paper.*.
  const std::string stem = setup.setup.name + (options.protocol == GehlerShiProtocol::paper ? "-paper" : "");
  ExperimentOutputs outputs({o.csv_path, o.json_path, o.scenes_out_path, o.plot_dir}, stem);
  set_activity("running the gehler-shi experiment");
  ExperimentResult result;
  try {
    result = run_gamut_experiment(setup.setup, config);
  } catch (const SceneInputError& e) {
    throw InputError(e.input == SceneInput::expansion ? "--expand" : "--surfaces", 0, e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError("--surfaces", 0, e.what());
  }
  outputs.write(result, provenance_json().dump(), false);
  write_stdout(gehler_shi_table(result, setup));
  return o.plot_dir.empty() ? 0 : draw_with_gnuplot(o.plot_dir, stem, "gmcc reproduce");
}

}  // namespace

CLI::App* add_reproduce_command(CLI::App& app, ReproduceOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "reproduce", "Reproduce the experiments of Finlayson & Hordley (1999) §4 from spectral data");
  cmd->require_subcommand(1);
  CLI::App* syn = cmd->add_subcommand(
      "synthetic", "Fig. 3: narrow-band sensors 610/540/450 nm, 1269 Munsell chips, canonical D55, "
                   "lights D75, D100, P2856, P15000");
  add_common_options(syn, o);
  add_output_options(syn, o);
  CLI::App* cam = cmd->add_subcommand(
      "camera", "Fig. 5 analogue: SONY DXC-930; canonical gamut of SFU's 1995 reflectances under "
                "solux-4700; scenes of the 24 Macbeth patches under syl-50MR16Q and solux-4700+3202");
  add_common_options(cam, o);
  add_output_options(cam, o);
  cam->add_option("--canonical-surfaces", o.canonical_surfaces,
                  "the canonical gamut's reflectances: sfu1995 (all 1995 SFU surfaces, as Barnard "
                  "et al. 2002) or macbeth (the 24 patches the scenes are drawn from)")
      ->check(CLI::IsMember({"sfu1995", "macbeth"}))
      ->capture_default_str();
  cam->add_option("--noise", o.noise, "relative Gaussian sensor noise on image colours (e.g. 0.02)")
      ->capture_default_str();
  CLI::App* exp = cmd->add_subcommand(
      "expansion", "the synthetic experiment without expansion and with 10% under each policy");
  add_common_options(exp, o);
  exp->add_option("--csv", o.csv_path,
                  "write one row per (expansion, light, surfaces, rule): expansion_policy, "
                  "expansion_factor, then the columns of reproduce synthetic --csv");
  exp->add_option("--scenes-out", o.scenes_out_path,
                  "write the three runs' per-scene records (JSON Lines), each run a setup line "
                  "followed by its scenes");
  CLI::App* gs = cmd->add_subcommand(
      "gehler-shi", "Fig. 5 on measured chart colours: the 568 Gehler-Shi images' ColorChecker patches and "
                    "ground-truth lights, per camera, leave-one-out or the paper's protocol");
  gs->add_option("--scenes", o.gehler_scenes, "scenes per image and patch count")->capture_default_str();
  gs->add_option("--seed", o.seed, "seed of the scene generators (mt19937_64)")->capture_default_str();
  gs->add_option("--surfaces", o.max_surfaces, "largest number of patches per scene (1 to it)")
      ->capture_default_str();
  gs->add_option("--threads", o.threads, "worker threads (0: all cores); results do not depend on it")
      ->capture_default_str();
  gs->add_option("--data", o.data_dir, "folder of the data files (default: the shipped data/)");
  gs->add_option("--mean3d", o.mean3d_method, "route to the 3-D mean")
      ->check(CLI::IsMember(mean3d_method_names()))
      ->capture_default_str();
  gs->add_option("--protocol", o.protocol,
                 "leave-one-out (each image's canonical gamut: every other same-camera image) or paper "
                 "(one whitish daylight chart; yellowish and bluish test groups)")
      ->check(CLI::IsMember(gehler_shi_protocol_names()))
      ->capture_default_str();
  gs->add_option("--cameras", o.cameras, "the cameras, each its own rows: Canon1D, Canon5D")
      ->delimiter(',')
      ->capture_default_str();
  gs->add_option("--dark", o.dark, "drop patches with a channel <= this (near-black)")->capture_default_str();
  gs->add_option("--clip", o.clip, "drop patches with a channel >= this (clipped)")->capture_default_str();
  gs->add_option("--exclude-patches", o.exclude_patches,
                 "leave these patch numbers (1-24) out of every image, e.g. 19,20,21,22,23,24 (the "
                 "achromatic row, on which the ground truth was measured)");
  gs->add_option("--expand", o.expand_factor, "expand the canonical gamut by this factor (0.1 = 10%)")
      ->capture_default_str();
  gs->add_option("--expand-policy", o.expand_policy, "none | centroid-clip | multiplicative")
      ->check(CLI::IsMember(expansion_policy_names()))
      ->capture_default_str();
  gs->add_option("--csv", o.csv_path, "write one row per (group, patches, rule or baseline) to this CSV file");
  gs->add_option("--json", o.json_path, "write every cell's statistics as one JSON document to this file");
  gs->add_option("--scenes-out", o.scenes_out_path,
                 "write one JSON Lines record per scene (patch numbers drawn, F, every rule's and "
                 "baseline's map and errors)");
  gs->add_option("--plot", o.plot_dir,
                 "write gehler-shi.dat/.gp (paper protocol: gehler-shi-paper.*) to this folder and draw "
                 ".png/.svg with gnuplot");
  return cmd;
}

int run_reproduce(const CLI::App& reproduce, const ReproduceOptions& o) {
  if (reproduce.got_subcommand("synthetic")) return report(synthetic(o), config_from(o), o);
  if (reproduce.got_subcommand("camera")) return report(camera(o), config_from(o), o);
  if (reproduce.got_subcommand("expansion")) return expansion_table(o);
  if (reproduce.got_subcommand("gehler-shi")) return gehler_shi(o);
  return 2;
}

}  // namespace gmcc::cli
