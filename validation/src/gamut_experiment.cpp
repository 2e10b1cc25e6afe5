// The gamut-mapping experiment run (gamut_experiment.h): the setup checked, the cells shared out
// among threads (their scenes: gamut_scenes.cpp) and each cell summarised.
#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/numerics/interrupt.h>
#include <gmcc/selection/select_scene_options.h>

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_trace.h>
#include <gmcc/selection/perspective_cone_mean.h>
#include <gmcc/selection/score_rules.h>

#include <gmcc/numerics/constants.h>
#include <gmcc/numerics/wide_multiply.h>

#include "gamut_scenes.h"
#include "lazy_mt19937_64.h"
#include "seed_sequence.h"

#include <mpfr.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <deque>
#include <cmath>
#include <random>
#include <stdexcept>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>

namespace gmcc {
namespace {

// Up to `count` threads running `f`: fewer if the system refuses one (a thread's stack is
// address space, so under gmcc's --memory-limit a thread may not be made). The work is shared
// out by an atomic counter and the results do not depend on the number of threads, so the run
// goes on with the threads there are, rather than std::terminate for threads left unjoined.
template <class F>
std::vector<std::thread> start_threads(std::size_t count, const F& f) {
  std::vector<std::thread> threads;
  threads.reserve(count);  // no reallocation below, with threads already running
  for (std::size_t t = 0; t < count; ++t) {
    try {
      threads.emplace_back(f);
    } catch (const std::exception&) {  // std::system_error, or std::bad_alloc for its state
      break;
    }
  }
  return threads;
}

}  // namespace

ExperimentCell summarise_cell(const std::string& light, int n, std::vector<const SceneRecord*> scenes,
                              std::size_t R, std::size_t B) {
  std::sort(scenes.begin(), scenes.end(), [](const SceneRecord* a, const SceneRecord* b) {
    return a->light != b->light ? a->light < b->light : a->scene < b->scene;
  });
  ExperimentCell cell;
  cell.light = light;
  cell.surfaces = n;
  cell.rules.resize(R);
  std::vector<std::vector<double>> error(R), worst(R), illuminant(R), reproduction(R);
  // Baselines: [0, B) over the answered scenes, [B, 2B) over all.
  std::vector<std::vector<double>> b_error(2 * B), b_illuminant(2 * B), b_reproduction(2 * B);
  for (const SceneRecord* rec : scenes) {
    ++cell.scenes;
    for (std::size_t b = 0; b < B && b < rec->baselines.size(); ++b) {
      const RuleRecord& x = rec->baselines[b];
      if (!x.scored) continue;
      for (std::size_t slot : {b + B, rec->rules.empty() ? 2 * B : b}) {
        if (slot >= 2 * B) continue;
        b_error[slot].push_back(x.error_deg);
        if (x.positive_map) {
          b_illuminant[slot].push_back(x.illuminant_error_deg);
          b_reproduction[slot].push_back(x.reproduction_error_deg);
        }
      }
    }
    if (rec->rules.empty()) {
      ++cell.empty;
      continue;
    }
    for (std::size_t r = 0; r < R && r < rec->rules.size(); ++r) {
      const RuleRecord& x = rec->rules[r];
      if (!x.scored) continue;
      error[r].push_back(x.error_deg);
      worst[r].push_back(x.worst_case_deg);
      cell.rules[r].truth_in_feasible_set += x.truth_in_feasible_set;
      if (x.positive_map) {
        illuminant[r].push_back(x.illuminant_error_deg);
        reproduction[r].push_back(x.reproduction_error_deg);
      }
    }
  }
  for (std::size_t r = 0; r < R; ++r) {
    RuleStats& st = cell.rules[r];
    st.error = error_statistics(std::move(error[r]));
    st.worst_case = error_statistics(std::move(worst[r]));
    st.illuminant = error_statistics(std::move(illuminant[r]));
    st.reproduction = error_statistics(std::move(reproduction[r]));
  }
  cell.baselines.resize(B);
  cell.baselines_all.resize(B);
  for (std::size_t slot = 0; slot < 2 * B; ++slot) {
    RuleStats& st = slot < B ? cell.baselines[slot] : cell.baselines_all[slot - B];
    st.error = error_statistics(std::move(b_error[slot]));
    st.illuminant = error_statistics(std::move(b_illuminant[slot]));
    st.reproduction = error_statistics(std::move(b_reproduction[slot]));
  }
  return cell;
}

namespace {

// The setup and config make sense together. \throws std::invalid_argument saying what does not.
void check_experiment(const ExperimentSetup& setup, const ExperimentConfig& config) {
  if (config.min_surfaces < 1 || config.max_surfaces < config.min_surfaces)
    throw std::invalid_argument("surface counts must satisfy 1 <= min <= max");
  for (const TestLight& l : setup.lights) {
    if (!setup.skip_short_lights && static_cast<std::size_t>(config.max_surfaces) > l.surfaces.size())
      throw std::invalid_argument("light " + l.name + " has only " +
                                  std::to_string(l.surfaces.size()) + " surfaces");
    if (!setup.canonical_chromaticity_sets.empty() && l.canonical >= setup.canonical_chromaticity_sets.size())
      throw std::invalid_argument("light " + l.name + " names a canonical set that is not there");
    if (!l.surface_ids.empty() && l.surface_ids.size() != l.surfaces.size())
      throw std::invalid_argument("light " + l.name + " has not one surface id per surface");
  }
  if (!setup.canonical_chromaticity_sets.empty() && config.crule)
    throw std::invalid_argument("3-D CRULE needs one set of canonical surfaces, not a canonical set per light");
  if (!(config.specular >= 0) || !(config.intensity >= 0) || !std::isfinite(config.specular) ||
      !std::isfinite(config.intensity))
    throw std::invalid_argument("specular and intensity must be finite and >= 0");
  if (config.crule_extended && !config.crule)
    throw std::invalid_argument("the extended CRULE selections need CRULE");
  if (config.shard_count < 1 || config.shard_index < 1 || config.shard_index > config.shard_count)
    throw std::invalid_argument("a shard K/N needs 1 <= K <= N");
}

}  // namespace

std::vector<Rule3> experiment_rules_3(const ExperimentConfig& config) {
  if (!config.crule) return {};
  if (config.crule_extended) return {all_rules_3.begin(), all_rules_3.end()};
  return {Rule3::max_volume, Rule3::centroid};
}

std::vector<std::string> experiment_rule_names_3d(const ExperimentConfig& config) {
  std::vector<std::string> names;
  for (Rule3 rule : experiment_rules_3(config)) names.push_back("crule_" + to_string(rule));
  if (config.crule && config.crule_extended) names.push_back("crule_cone_mean");
  return names;
}

namespace {

// The result's description before any scene: names, rules, baselines and the canonical gamut(s).
ExperimentResult result_header(const ExperimentSetup& setup, const ExperimentConfig& config) {
  ExperimentResult result;
  result.name = setup.name;
  result.figure = setup.figure;
  for (const TestLight& l : setup.lights) result.lights.push_back(l.name);
  result.config = config;
  result.config.progress = nullptr;
  for (Rule r : all_rules) result.rules.push_back(to_string(r));
  for (const std::string& name : experiment_rule_names_3d(config)) result.rules.push_back(name);
  result.surface_indices = setup.surface_indices;
  if (setup.baselines) result.baselines.assign(experiment_baselines.begin(), experiment_baselines.end());
  if (setup.canonical_chromaticity_sets.empty()) {
    result.canonical_gamut =
        canonical_gamut(perspective_chromaticities(setup.canonical_surfaces, NonPositiveBluePolicy::drop).points,
                        config.expansion);
  } else {
    for (const std::vector<Point2>& set : setup.canonical_chromaticity_sets)
      result.canonical_gamuts.push_back(canonical_gamut(set, config.expansion));
    result.canonical_gamut = result.canonical_gamuts.front();
  }
  // The limit every command applies (docs/cli.md "Input files"): coordinates up to 1e150.
  for (const ConvexSet2* g : {&result.canonical_gamut})
    for (const Point2& v : g->vertices)
      if (v.x > max_scene_coordinate() || v.y > max_scene_coordinate())
        throw SceneInputError(SceneInput::expansion, SceneProblem::too_large, std::nullopt,
                              "the expanded canonical gamut exceeds 1e150, the largest coordinate gmcc accepts "
                              "(it reports doubles)");
  for (const ConvexSet2& g : result.canonical_gamuts)
    for (const Point2& v : g.vertices)
      if (v.x > max_scene_coordinate() || v.y > max_scene_coordinate())
        throw SceneInputError(SceneInput::expansion, SceneProblem::too_large, std::nullopt,
                              "the expanded canonical gamut exceeds 1e150, the largest coordinate gmcc accepts "
                              "(it reports doubles)");
  return result;
}

// The cells' rows: each light's group (its own name when it has none), in order of first
// appearance; light ℓ's scenes go to row `of`[ℓ]. `grouped` when any light names a group.
struct LightGroups {
  std::vector<std::string> names;
  std::vector<std::size_t> of;
  bool grouped = false;
};
LightGroups light_groups(const ExperimentSetup& setup) {
  LightGroups r;
  for (const TestLight& l : setup.lights) {
    const std::string& g = l.group.empty() ? l.name : l.group;
    r.grouped = r.grouped || !l.group.empty();
    const auto at = std::find(r.names.begin(), r.names.end(), g);
    r.of.push_back(static_cast<std::size_t>(at - r.names.begin()));
    if (at == r.names.end()) r.names.push_back(g);
  }
  return r;
}

// The shard's scenes: global indices [first, last) of the canonical order (light, n, s) over
// `jobs` cells of config.scenes scenes each. T = scenes·jobs (and so base = scenes·j) fits in 64
// bits, checked; T·K may not, so the share ⌊T·K/N⌋ is divided from its 128-bit product.
struct ShardScenes {
  std::uint64_t first = 0, last = 0, scenes = 0;
  // Cell j's scenes [begin, end) within the cell.
  std::pair<std::uint64_t, std::uint64_t> of_cell(std::size_t j) const {
    const std::uint64_t base = scenes * j;
    auto clamp = [&](std::uint64_t g) { return g <= base ? 0 : std::min<std::uint64_t>(g - base, scenes); };
    return {clamp(first), clamp(last)};
  }
};
ShardScenes shard_scenes(const ExperimentConfig& config, std::size_t jobs) {
  if (jobs && config.scenes > std::numeric_limits<std::uint64_t>::max() / jobs)
    throw std::invalid_argument("more scenes than 2^64 in all");
  const std::uint64_t T = config.scenes * jobs;
  return {numerics::divide_wide(numerics::multiply_wide(T, config.shard_index - 1), config.shard_count),
          numerics::divide_wide(numerics::multiply_wide(T, config.shard_index), config.shard_count), config.scenes};
}

// G_c (and Finlayson's constraint C, when given) prepared once for every scene: one per
// canonical set.
std::deque<CanonicalConstraints> prepared_gamuts(const ExperimentResult& result, const ExperimentConfig& config) {
  std::deque<CanonicalConstraints> gamuts;
  for (const ConvexSet2& g : result.canonical_gamuts.empty() ? std::vector<ConvexSet2>{result.canonical_gamut}
                                                              : result.canonical_gamuts) {
    if (config.constraint) gamuts.emplace_back(g, *config.constraint);
    else gamuts.emplace_back(g);
  }
  return gamuts;
}

// Without noise a scene's colours are the light's surfaces as given: their chromaticities are
// computed once per light (b <= 0 left as a placeholder; scenes skip those surfaces). Lights are
// shared out among the threads (each light's list is written by one thread only). With noise:
// empty lists.
std::vector<std::vector<Point2>> light_chromaticities(const ExperimentSetup& setup, const ExperimentConfig& config,
                                                      unsigned threads) {
  std::vector<std::vector<Point2>> chromaticities(setup.lights.size());
  if (config.noise <= 0) {
    std::atomic<std::size_t> next_light{0};
    auto precompute = [&] {
      for (std::size_t l; (l = next_light++) < setup.lights.size();) {
        chromaticities[l].reserve(setup.lights[l].surfaces.size());
        for (const Colour& c : setup.lights[l].surfaces)
          chromaticities[l].push_back(sgn(c.b) > 0 ? perspective_chromaticity(c) : Point2{});
      }
    };
    std::vector<std::thread> helpers =
        start_threads(std::max<std::size_t>(std::min<std::size_t>(threads, setup.lights.size()), 1) - 1,
                      precompute);
    precompute();
    for (std::thread& t : helpers) t.join();
  }
  return chromaticities;
}

// One cell of scenes: light `light` (index into the setup's lights) with n surfaces.
struct Job {
  std::size_t light;
  int n;
};

// The cells when lights are grouped: per group and surface count, the scenes of every light of
// the group (jobs[j]'s scenes are records[j]).
std::vector<ExperimentCell> group_cells(const LightGroups& groups, const std::vector<Job>& jobs,
                                        const std::vector<std::vector<SceneRecord>>& records,
                                        const ExperimentConfig& config, const ExperimentResult& result) {
  std::vector<ExperimentCell> cells;
  const std::size_t counts = static_cast<std::size_t>(config.max_surfaces - config.min_surfaces + 1);
  for (std::size_t g = 0; g < groups.names.size(); ++g)
    for (std::size_t k = 0; k < counts; ++k) {
      std::vector<const SceneRecord*> scenes;
      for (std::size_t j = 0; j < jobs.size(); ++j)
        if (groups.of[jobs[j].light] == g && static_cast<std::size_t>(jobs[j].n - config.min_surfaces) == k)
          for (const SceneRecord& rec : records[j]) scenes.push_back(&rec);
      cells.push_back(summarise_cell(groups.names[g], config.min_surfaces + static_cast<int>(k), std::move(scenes),
                                     result.rules.size(), result.baselines.size()));
    }
  return cells;
}

}  // namespace

ExperimentResult run_gamut_experiment(const ExperimentSetup& setup, const ExperimentConfig& config) {
  check_experiment(setup, config);
  ExperimentResult result = result_header(setup, config);
  const LightGroups groups = light_groups(setup);

  std::vector<Job> jobs;
  for (std::size_t l = 0; l < setup.lights.size(); ++l)
    for (int n = config.min_surfaces; n <= config.max_surfaces; ++n) jobs.push_back({l, n});
  result.cells.resize(jobs.size());
  const ShardScenes shard = shard_scenes(config, jobs.size());
  std::vector<std::vector<SceneRecord>> records(jobs.size());

  const std::deque<CanonicalConstraints> gamuts = prepared_gamuts(result, config);
  // G_c3 prepared once for every scene's CRULE (the canonical colours, black in it or not).
  const std::optional<CanonicalConstraints3> crule_gamut =
      config.crule ? std::optional<CanonicalConstraints3>(CanonicalConstraints3(setup.canonical_surfaces, config.crule_black))
                   : std::nullopt;
  const unsigned threads = config.threads ? config.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::vector<std::vector<Point2>> chromaticities = light_chromaticities(setup, config, threads);
  std::atomic<std::size_t> next{0};
  std::atomic<std::uint64_t> done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::atomic<bool> failed{false};
  auto worker = [&] {
    for (std::size_t j; (j = next++) < jobs.size();) {
      try {
        const auto [s_begin, s_end] = shard.of_cell(j);
        const std::size_t l = jobs[j].light;
        records[j] = internal::run_cell(setup, config, gamuts[setup.canonical_chromaticity_sets.empty() ? 0 : setup.lights[l].canonical],
                                        crule_gamut ? &*crule_gamut : nullptr, chromaticities[l], l, jobs[j].n, s_begin, s_end, done);
        if (groups.grouped) continue;  // summarised per group below, once every light's scenes are in
        std::vector<const SceneRecord*> scenes;
        for (const SceneRecord& rec : records[j]) scenes.push_back(&rec);
        result.cells[j] = summarise_cell(setup.lights[jobs[j].light].name, jobs[j].n, std::move(scenes),
                                         result.rules.size(), result.baselines.size());
        if (!config.keep_scenes) std::vector<SceneRecord>().swap(records[j]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        failed = true;
      }
    }
  };
  // A worker thread's MPFR constant caches (π for the angles) are thread-local: free them when
  // the thread ends, or every run leaks them (LeakSanitizer).
  auto thread_worker = [&worker] {
    worker();
    mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
  };
  std::vector<std::thread> pool =
      start_threads(std::max<std::size_t>(std::min<std::size_t>(threads, jobs.size()), 1) - 1, thread_worker);
  const std::uint64_t total = shard.last - shard.first;
  std::vector<std::thread> reporter_free_worker;
  if (config.progress) reporter_free_worker = start_threads(1, thread_worker);
  if (!reporter_free_worker.empty()) {  // report from this thread while the others work, then join in
    while (done < total && !failed) {
      config.progress(done, total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    reporter_free_worker.front().join();
    config.progress(done, total);
  } else {
    worker();
  }
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (groups.grouped) result.cells = group_cells(groups, jobs, records, config, result);
  if (config.keep_scenes)
    for (std::vector<SceneRecord>& cell : records)
      for (SceneRecord& rec : cell) result.scenes.push_back(std::move(rec));
  return result;
}

}  // namespace gmcc
