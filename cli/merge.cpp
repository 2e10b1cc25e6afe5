#include "merge.h"

#include "benchmark_command.h"
#include "json_fields.h"
#include "limit_exit.h"
#include "reproduce.h"

#include <gmcc/input/input_error.h>
#include <gmcc/input/text_file.h>

#include <nlohmann/json.hpp>

#include <map>

namespace gmcc::cli {
namespace {

using nlohmann::json;

// Largest scene file accepted: 10^6 scenes of 64 lights and 24 surface counts do not fit, but a
// shard of them does (a record is about 600 bytes).
constexpr std::size_t kMaxSceneFileBytes = std::size_t(4) << 30;

Rational rational(const json& j, const Place& at) {
  try {
    return parse_rational(j.get<std::string>());
  } catch (const std::exception&) {
    bad(at, "a vertex coordinate is not an exact number");
  }
}

ConvexSet2 convex_set(const json& j, const Place& at) {
  ConvexSet2 set;
  const std::string kind = get<std::string>(j, "kind", at);
  bool known = false;
  for (ConvexKind k : {ConvexKind::empty, ConvexKind::point, ConvexKind::segment, ConvexKind::polygon})
    if (to_string(k) == kind) set.kind = k, known = true;
  if (!known) bad(at, "unknown kind " + quoted_text(kind));
  for (const json& v : member(j, "vertices", at)) {
    if (!v.is_array() || v.size() != 2) bad(at, "a vertex is not a pair");
    set.vertices.push_back({rational(v[0], at), rational(v[1], at)});
  }
  return set;
}

ConvexKind convex_kind(const std::string& kind, const Place& at) {
  for (ConvexKind k : {ConvexKind::empty, ConvexKind::point, ConvexKind::segment, ConvexKind::polygon})
    if (to_string(k) == kind) return k;
  bad(at, "unknown feasible-set kind " + quoted_text(kind));
}

// The run a setup line describes (everything the reports print; config.shard reset to 1/1).
ExperimentResult result_of(const json& h, const Place& at) {
  if (get<std::string>(h, "format", at) != "gmcc-reproduce" || get<int>(h, "format_version", at) != 1)
    bad(at, "not a gmcc reproduce --scenes-out file (format gmcc-reproduce, version 1)");
  ExperimentResult r;
  r.name = get<std::string>(h, "experiment", at);
  if (h.contains("baselines"))  // gehler-shi: its cells are light groups, which merge does not rebuild
    bad(at, "records of reproduce " + r.name + " (light groups, baselines) cannot be merged; "
            "its own --csv and --json hold the whole run");
  r.figure = get<std::string>(h, "figure", at);
  r.lights = get<std::vector<std::string>>(h, "lights", at);
  r.rules = get<std::vector<std::string>>(h, "rules", at);
  ExperimentConfig& c = r.config;
  c.min_surfaces = get<int>(h, "min_surfaces", at);
  c.max_surfaces = get<int>(h, "max_surfaces", at);
  c.scenes = get<std::uint64_t>(h, "scenes", at);
  c.seed = get<std::uint64_t>(h, "seed", at);
  // reproduce's own limits (docs/cli.md "Resource limits").
  const std::size_t max_rules = rule_count + max_experiment_rules_3d;
  if (c.min_surfaces < 1 || c.max_surfaces < c.min_surfaces || c.max_surfaces > 24 || c.scenes < 1 ||
      c.scenes > 1000000 || r.lights.empty() || r.lights.size() > 64 || r.rules.empty() || r.rules.size() > max_rules)
    bad(at, "the setup's counts are out of range (reproduce's limits: 1 to 24 surfaces, 1 to 10^6 scenes, "
            "1 to 64 lights, 1 to " + std::to_string(max_rules) + " rules)");
  const json& e = member(h, "expansion", at);
  try {
    c.expansion.policy = expansion_policy_from_string(get<std::string>(e, "policy", at));
    c.expansion.factor = parse_rational(get<std::string>(e, "factor", at));
    c.mean3d.method = mean3d_method_from_string(get<std::string>(h, "mean3d", at));
  } catch (const std::invalid_argument& x) {
    bad(at, x.what());
  }
  c.noise = get<double>(h, "noise", at);
  c.shading = get<double>(h, "shading", at);
  c.crule = get<bool>(h, "crule", at);
  // The seed-claim conditions (written only when set).
  if (h.contains("crule_black")) {
    const std::string black = get<std::string>(h, "crule_black", at);
    if (black != "exclude" && black != "include") bad(at, "\"crule_black\" must be include or exclude");
    c.crule_black = canonical_black_from_string(black);
  }
  if (h.contains("crule_extended")) c.crule_extended = get<bool>(h, "crule_extended", at);
  if (h.contains("specular")) c.specular = get<double>(h, "specular", at);
  if (h.contains("intensity")) c.intensity = get<double>(h, "intensity", at);
  if (r.rules.size() != rule_count + experiment_rule_names_3d(c).size()) bad(at, "\"rules\" do not match \"crule\"");
  r.canonical_gamut = convex_set(member(h, "canonical_gamut", at), at);
  if (!member(h, "constraint", at).is_null()) c.constraint = convex_set(h.at("constraint"), at);
  c.keep_scenes = true;
  return r;
}

// The members of a part's provenance that every part of one run shares: all but the inputs'
// paths (a cluster's nodes may see the data at other paths; sizes and digests must agree).
json same_run_provenance(json p) {
  if (p.is_object() && p.contains("inputs") && p["inputs"].is_array())
    for (json& input : p["inputs"])
      if (input.is_object()) input.erase("path");
  return p;
}

// A setup line without the members that differ between the shards of one run.
json comparable(json h) {
  h.erase("shard");
  h.erase("provenance");
  return h;
}

SceneRecord record_of(const json& j, const ExperimentResult& r, const Place& at) {
  SceneRecord s;
  s.light = get<std::size_t>(j, "light_index", at);
  if (s.light >= r.lights.size() || get<std::string>(j, "light", at) != r.lights[s.light])
    bad(at, "the light is not one of the setup's");
  s.surfaces = get<int>(j, "surfaces", at);
  s.scene = get<std::uint64_t>(j, "scene", at);
  if (s.surfaces < r.config.min_surfaces || s.surfaces > r.config.max_surfaces || s.scene >= r.config.scenes)
    bad(at, "the surface count or scene index is outside the setup's");
  s.drawn = get<std::vector<std::uint32_t>>(j, "drawn", at);
  if (s.drawn.size() != static_cast<std::size_t>(s.surfaces)) bad(at, "\"drawn\" does not hold \"surfaces\" indices");
  const json& f = member(j, "feasible_set", at);
  s.kind = convex_kind(get<std::string>(f, "kind", at), at);
  s.area = get<double>(f, "area", at);
  const json& rules = member(j, "rules", at);
  if (rules.is_null()) return s;
  if (!rules.is_object() || rules.size() != r.rules.size()) bad(at, "\"rules\" does not hold the setup's rules");
  for (const std::string& name : r.rules) {
    RuleRecord& x = s.rules.emplace_back();
    const json& v = member(rules, name.c_str(), at);
    if (v.is_null()) continue;
    x.scored = true;
    const auto map = get<std::vector<double>>(v, "map", at);
    if (map.size() != 2) bad(at, "a map is not a pair");
    x.map = {map[0], map[1]};
    x.error_deg = get<double>(v, "error_deg", at);
    x.worst_case_deg = get<double>(v, "worst_case_deg", at);
    x.truth_in_feasible_set = get<bool>(v, "truth_in_feasible_set", at);
    x.positive_map = !member(v, "illuminant_error_deg", at).is_null();
    if (x.positive_map) {
      x.illuminant_error_deg = get<double>(v, "illuminant_error_deg", at);
      x.reproduction_error_deg = get<double>(v, "reproduction_error_deg", at);
    }
  }
  return s;
}

}  // namespace

CLI::App* add_merge_command(CLI::App& app, MergeOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "merge", "Combine the --scenes-out files of the shards of one gmcc reproduce run (--shard K/N) "
               "into the whole run's outputs, byte for byte");
  cmd->add_option("files", o.files, "the shards' --scenes-out files, in any order")->required();
  cmd->add_option("--csv", o.csv_path, "write the whole run's CSV to this file");
  cmd->add_option("--json", o.json_path, "write the whole run's JSON to this file");
  cmd->add_option("--scenes-out", o.scenes_out_path, "write the whole run's per-scene records to this file");
  cmd->add_option("--plot", o.plot_dir, "write the whole run's figure to this folder, as reproduce --plot");
  cmd->add_option("--records", o.records_path,
                  "gmcc benchmark's shards (their --records files): write the whole run's records to this file");
  return cmd;
}

namespace {

// A scene record with its global index g (light, n, s) and where it was read: the records are
// sorted by g once all are read, so memory follows the records read, not the scene count a
// setup line claims.
struct Read {
  std::uint64_t g;
  Place at;
  SceneRecord scene;
};

// The records sorted by g; each scene of the run exactly once (else an InputError naming it).
void check_every_scene_once(std::vector<Read>& scenes, const ExperimentResult& r, std::size_t cells,
                            std::uint64_t total, const std::string& first_file) {
  std::stable_sort(scenes.begin(), scenes.end(), [](const Read& a, const Read& b) { return a.g < b.g; });
  auto name = [&](std::uint64_t g) {
    const std::uint64_t cell = g / r.config.scenes;
    return "scene " + std::to_string(g % r.config.scenes) + " of " + r.lights[cell / cells] + " with " +
           std::to_string(r.config.min_surfaces + static_cast<int>(cell % cells)) + " surfaces";
  };
  for (std::size_t i = 1; i < scenes.size(); ++i)
    if (scenes[i].g == scenes[i - 1].g)
      bad(scenes[i].at, name(scenes[i].g) + " is already in " + scenes[i - 1].at.file + ":" +
                            std::to_string(scenes[i - 1].at.line));
  for (std::uint64_t g = 0; g < total; ++g)
    if (g >= scenes.size() || scenes[g].g != g)
      throw InputError(first_file, 0, name(g) + " is in none of the files: a shard is missing");
}

// The merged outputs' provenance, from the parts' provenance lines.
struct MergedProvenance {
  std::string text;  // the first part's: the whole run's, as every part records the same run
  json same;         // what must agree between parts (same_run_provenance)
  std::string file;  // the first part's file
};

// The provenance line `j` (its text [first, last)) of `file`: the first part's kept, another's
// checked against it.
void merge_provenance(MergedProvenance& p, const json& j, std::string::const_iterator first,
                      std::string::const_iterator last, const std::string& file, const Place& at) {
  // Kept as written (member order too): the merged outputs' provenance. Every part records
  // the same run (--shard, --threads and the output paths are not recorded).
  // Checked against the first part's: the same software, build, command, options and input
  // contents (paths may differ between machines; the inputs' sizes and SHA-256 may not).
  const json same = same_run_provenance(j.at("provenance"));
  if (p.text.empty()) {
    p.text = nlohmann::ordered_json::parse(first, last).at("provenance").dump();
    p.same = same;
    p.file = file;
  } else if (same != p.same) {
    bad(at, "another run than " + p.file +
                "'s: its provenance names another build, command, options or inputs (the parts of one "
                "run come from one gmcc and the same data)");
  }
}

// Each cell's statistics from the merged scenes (in cell order, as reproduce computes them).
void summarise_cells(ExperimentResult& r, std::size_t cells) {
  for (std::size_t l = 0; l < r.lights.size(); ++l)
    for (std::size_t k = 0; k < cells; ++k) {
      std::vector<const SceneRecord*> cell;
      const std::size_t base = (l * cells + k) * r.config.scenes;
      for (std::size_t s = 0; s < r.config.scenes; ++s) cell.push_back(&r.scenes[base + s]);
      r.cells.push_back(summarise_cell(r.lights[l], r.config.min_surfaces + static_cast<int>(k),
                                             std::move(cell), r.rules.size()));
    }
}

}  // namespace

int run_merge(const MergeOptions& o) {
  if (!o.files.empty() && is_benchmark_records(o.files.front())) {
    if (!o.scenes_out_path.empty())
      throw InputError("--scenes-out", 0, "not for gmcc benchmark's records (use --records, --csv, --json, --plot)");
    return merge_benchmark(o.files, o.csv_path, o.json_path, o.records_path, o.plot_dir);
  }
  if (!o.records_path.empty())
    throw InputError("--records", 0, "is for gmcc benchmark's shards; reproduce's scene files merge with --scenes-out");
  std::optional<ExperimentResult> result;
  MergedProvenance provenance;
  std::optional<ExperimentOutputs> outputs;
  json setup;
  std::string first_file;
  std::vector<Read> scenes;
  std::uint64_t total = 0;
  std::size_t cells = 0;
  const TextFileRules rules{kMaxSceneFileBytes, "scene file", "JSON Lines from gmcc reproduce --scenes-out"};
  for (const std::string& file : o.files) {
    set_activity("reading " + file);
    const std::string text = read_text_file(file, rules);
    std::size_t line = 0, start = 0;
    bool header = true;
    while (start < text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      const Place at{file, ++line};
      const auto first = text.begin() + static_cast<std::ptrdiff_t>(start);
      const auto last = text.begin() + static_cast<std::ptrdiff_t>(end);
      start = end + 1;
      json j;
      try {
        j = json::parse(first, last);
      } catch (const json::exception&) {
        bad(at, "not a JSON object");
      }
      if (line == 1 && j.is_object() && j.size() == 1 && j.contains("provenance")) {
        merge_provenance(provenance, j, first, last, file, at);
        continue;
      }
      if (header) {
        header = false;
        if (!result) {
          result = result_of(j, at);
          setup = comparable(j);
          first_file = file;
          // Outputs opened once the run is known (the plot's stem is its name), before the work.
          outputs.emplace(ReportPaths{o.csv_path, o.json_path, o.scenes_out_path, o.plot_dir}, result->name);
          cells = static_cast<std::size_t>(result->config.max_surfaces - result->config.min_surfaces + 1);
          total = result->lights.size() * cells * result->config.scenes;
        } else if (comparable(j) != setup) {
          bad(at, "another run's setup than " + first_file + "'s (only \"shard\" and \"provenance\" may differ)");
        }
        continue;
      }
      if (j.is_object() && j.contains("format"))
        bad(at, "a second setup line: this file holds more than one run (reproduce expansion writes "
                "three); merge joins the shards of one run, a setup line and its scenes per file");
      SceneRecord s = record_of(j, *result, at);
      if (s.rules.size() != (s.kind == ConvexKind::empty ? 0 : result->rules.size()))
        bad(at, "\"rules\" must be null exactly when the feasible set is empty");
      const std::uint64_t g = (s.light * cells + static_cast<std::size_t>(s.surfaces - result->config.min_surfaces)) *
                                  result->config.scenes + s.scene;
      scenes.push_back({g, at, std::move(s)});
    }
    if (header) throw InputError(file, 0, "empty: no setup line");
  }
  set_activity("checking the scenes");
  check_every_scene_once(scenes, *result, cells, total, o.files.front());
  set_activity("merging the scenes");
  result->scenes.reserve(scenes.size());
  for (Read& r : scenes) result->scenes.push_back(std::move(r.scene));
  std::vector<Read>().swap(scenes);
  summarise_cells(*result, cells);
  return outputs->write(*result, provenance.text);
}

}  // namespace gmcc::cli
