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

// Uniform integer in [0, n), unbiased (Lemire's multiply-and-reject), platform-independent.
// The scene generator: std::mt19937_64's output, twisted lazily (a scene draws a dozen numbers).
using Generator = internal::LazyMt19937_64;

std::uint64_t below(Generator& g, std::uint64_t n) {
  numerics::WideProduct m = numerics::multiply_wide(g(), n);
  if (m.low < n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (m.low < threshold) m = numerics::multiply_wide(g(), n);
  }
  return m.high;
}

double uniform01(Generator& g) { return static_cast<double>(g() >> 11) * 0x1p-53; }

// Standard normal by Box–Muller (one of the pair), from the scene's own generator.
double normal(Generator& g) {
  const double u = 1 - uniform01(g), v = uniform01(g);  // u in (0, 1]
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * static_cast<double>(numerics::pi) * v);
}

// A rule's errors as its record: `truth` says whether the true map lies in F (F3 for CRULE).
RuleRecord record(const RuleErrors& e, bool truth) {
  RuleRecord x;
  x.scored = true;
  x.map = e.map;
  x.error_deg = e.map_error_deg;
  x.worst_case_deg = e.worst_case_deg;
  x.truth_in_feasible_set = truth;
  x.positive_map = e.positive_map;
  x.illuminant_error_deg = e.illuminant_error_deg;
  x.reproduction_error_deg = e.reproduction_error_deg;
  return x;
}

// A baseline's illuminant estimate e scored like a rule's map: m = (c_r·e_b/(e_r·c_b),
// c_g·e_b/(e_g·c_b)), the map that takes e to the canonical light c. Unscored unless e > 0.
RuleRecord score_estimate(const Colour& e, const Point2& truth, const Colour& c) {
  if (sgn(e.r) <= 0 || sgn(e.g) <= 0 || sgn(e.b) <= 0 || sgn(c.b) <= 0) return {};
  const Point2 m{Rational(c.r * e.b / (e.r * c.b)), Rational(c.g * e.b / (e.g * c.b))};
  return record(exact_rule_errors(m, truth, c), false);
}

// Grey world and max-RGB on a scene's colours as the rules see them (noise, shading): its own
// colours when it has them, else the light's surfaces pool[0..n).
std::vector<RuleRecord> baseline_records(const ExperimentSetup& setup, const TestLight& light,
                                         const std::vector<std::size_t>& pool, int n,
                                         const std::vector<Colour>& image_colours) {
  Colour sum{0, 0, 0}, max{0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const Colour& c = image_colours.size() == static_cast<std::size_t>(n)
                          ? image_colours[static_cast<std::size_t>(i)]
                          : light.surfaces[pool[static_cast<std::size_t>(i)]];
    sum.r += c.r, sum.g += c.g, sum.b += c.b;
    if (c.r > max.r) max.r = c.r;
    if (c.g > max.g) max.g = c.g;
    if (c.b > max.b) max.b = c.b;
  }
  // Grey world's mean is the sum / n: the same direction, hence the same map.
  return {score_estimate(sum, light.true_map, setup.canonical_light),
          score_estimate(max, light.true_map, setup.canonical_light)};
}

// The same scene in 3-D (Forsyth's CRULE against crule_gamut, G_c3 prepared once with black in it
// or not as configured): its rules' maps scored by their perspective (d1/d3, d2/d3) into
// rec.rules after the 2-D rules: max-volume, the centroid (and with crule_extended max-trace and
// the cone mean of F3's perspective image), each worst case over F3. CRULE's certified route (crule_3d.h): F3, max-volume and
// max-trace exact, the centroid certified (its double map, taken exactly, is what is scored).
void score_crule(const ExperimentSetup& setup, const ExperimentConfig& config, const CanonicalConstraints3& crule_gamut,
                 const TestLight& light, const std::vector<Colour>& image_colours, SceneRecord& rec) {
  const Crule3d c3 = crule_3d(crule_gamut, image_colours, Crule3dRoute::certified);
  const bool truth3_inside = contains(c3.feasible, light.true_diagonal_map);
  // The 3-D map d of a selection, its worst case over F3 given: scored when d3 > 0.
  auto score = [&](std::size_t slot, const Point3& d, double worst_case_deg) {
    if (sgn(d.z) <= 0) return;  // the zero map (or one in the plane d3 = 0) has no perspective
    RuleErrors x = exact_rule_errors({Rational(d.x / d.z), Rational(d.y / d.z)}, light.true_map, setup.canonical_light);
    x.worst_case_deg = worst_case_deg;
    rec.rules[slot] = record(x, truth3_inside);
  };
  const std::array<const std::optional<Selection3>*, 2> rules3{&c3.max_volume, &c3.centroid};
  for (std::size_t r = 0; r < 2; ++r)
    if (*rules3[r] && (*rules3[r])->worst_case_deg)
      score(rule_count + r, measured_map((*rules3[r])->estimate), *(*rules3[r])->worst_case_deg);
  if (!config.crule_extended || c3.feasible.kind == ConvexKind3::empty) return;
  const Point3 trace = measured_map(max_trace(c3.feasible));
  if (sgn(trace.z) > 0) score(rule_count + 2, trace, worst_case_map_deg_3d(c3.feasible, trace));
  const std::optional<MapEstimate> cone = perspective_cone_mean(c3.feasible, config.mean3d);
  if (cone && cone->valid) {
    const Point2 m = measured_map(*cone);
    const Point3 lift{m.x, m.y, Rational(1)};
    score(rule_count + 3, lift, worst_case_map_deg_3d(c3.feasible, lift));
  }
}

// Scenes s_begin <= s < s_end of cell (light_index, n), each with its own generator.
// One surface as the scene shows it: its colour under the light, with the configured noise,
// shading factor and highlight drawn from g in that order ("Scene generator", docs/reproduction.md).
Colour observed_colour(const ExperimentSetup& setup, const ExperimentConfig& config, const TestLight& light,
                       std::size_t surface, Generator& g) {
  Colour c = light.surfaces[surface];
  if (config.noise > 0)
    for (Rational* x : {&c.r, &c.g, &c.b})
      *x *= rational_from_double(std::max(0.0, 1 + config.noise * normal(g)));
  if (config.shading > 0) {
    const Rational scale = rational_from_double(config.shading + (1 - config.shading) * uniform01(g));
    for (Rational* x : {&c.r, &c.g, &c.b}) *x *= scale;
  }
  if (config.specular > 0) {  // + s·e, e = c ⊘ d the test light's colour
    const Rational s_k = rational_from_double(config.specular * uniform01(g));
    const Colour& cl = setup.canonical_light;
    const Point3& d = light.true_diagonal_map;
    c.r += s_k * cl.r / d.x, c.g += s_k * cl.g / d.y, c.b += s_k * cl.b / d.z;
  }
  return c;
}

// The whole scene scaled by one factor from U[min(K, 1), max(K, 1)], drawn last.
void scale_scene(double intensity, std::vector<Colour>& image_colours, Generator& g) {
  const double lo = std::min(intensity, 1.0), hi = std::max(intensity, 1.0);
  const Rational k = rational_from_double(lo + (hi - lo) * uniform01(g));
  for (Colour& c : image_colours)
    for (Rational* x : {&c.r, &c.g, &c.b}) *x *= k;
}

std::vector<SceneRecord> run_cell(const ExperimentSetup& setup, const ExperimentConfig& config,
                                  const CanonicalConstraints& gamut, const CanonicalConstraints3* crule_gamut,
                                  const std::vector<Point2>& chromaticities,
                                  std::size_t light_index, int n, std::uint64_t s_begin, std::uint64_t s_end,
                                  std::atomic<std::uint64_t>& done) {
  const TestLight& light = setup.lights[light_index];
  const std::size_t R = 3 + experiment_rules_3d_count(config);
  std::vector<SceneRecord> records;
  if (static_cast<std::size_t>(n) > light.surfaces.size()) {  // setup.skip_short_lights: no scenes
    done += s_end - s_begin;
    return records;
  }
  records.reserve(static_cast<std::size_t>(s_end - s_begin));
  std::vector<std::size_t> pool(light.surfaces.size());
  ScoreOptions score_options;
  score_options.mean3d = config.mean3d;
  score_options.certified_route = config.certified_fast_route;
  for (std::uint64_t s = s_begin; s < s_end; ++s, ++done) {
    check_interrupt();  // a caller's Ctrl-C (interrupt.h): between scenes
    SceneRecord& rec = records.emplace_back();
    rec.light = light_index;
    rec.surfaces = n;
    rec.scene = s;
    // std::seed_seq{these six words}, computed faster with the same output.
    internal::SeedSequence<6> seq({static_cast<std::uint32_t>(config.seed), static_cast<std::uint32_t>(config.seed >> 32),
                                   static_cast<std::uint32_t>(light_index), static_cast<std::uint32_t>(n),
                                   static_cast<std::uint32_t>(s), static_cast<std::uint32_t>(s >> 32)});
    Generator g(seq);
    for (std::size_t i = 0; i < pool.size(); ++i) pool[i] = i;
    // The surfaces first (partial Fisher–Yates: n distinct), then noise and shading factors from
    // the same generator, so that options which draw more numbers never change the surfaces.
    for (int i = 0; i < n; ++i)
      std::swap(pool[static_cast<std::size_t>(i)],
                pool[static_cast<std::size_t>(i) + below(g, pool.size() - static_cast<std::size_t>(i))]);
    if (config.keep_scenes)  // only records need it
      for (int i = 0; i < n; ++i) {
        const std::size_t surface = pool[static_cast<std::size_t>(i)];
        rec.drawn.push_back(light.surface_ids.empty() ? static_cast<std::uint32_t>(surface)
                                                      : light.surface_ids.at(surface));
      }
    // The scene's chromaticities by address: the light's precomputed ones, or this scene's own.
    std::vector<const Point2*> image;
    std::vector<Point2> own;
    own.reserve(static_cast<std::size_t>(n));
    std::vector<Colour> image_colours;
    for (int i = 0; i < n; ++i) {
      const std::size_t surface = pool[static_cast<std::size_t>(i)];
      // Without noise or highlights the chromaticities are the light's, computed once (shading
      // and intensity scale a colour, not its chromaticity); the colours themselves are kept
      // only for 3-D CRULE (and when they are computed anyway).
      if (config.noise <= 0 && !config.crule && config.specular <= 0) {
        if (sgn(light.surfaces[surface].b) > 0) image.push_back(&chromaticities[surface]);
        continue;
      }
      Colour c = observed_colour(setup, config, light, surface, g);
      if (sgn(c.b) > 0) own.push_back(perspective_chromaticity(c)), image.push_back(&own.back());
      image_colours.push_back(std::move(c));
    }
    if (config.intensity > 0 && !image_colours.empty()) scale_scene(config.intensity, image_colours, g);
    if (setup.baselines) rec.baselines = baseline_records(setup, light, pool, n, image_colours);
    if (image.empty()) continue;
    const FeasiblePolygon P = feasible_polygon(gamut, image);
    rec.kind = P.kind();
    if (P.kind() == ConvexKind::empty) continue;
    rec.rules.resize(R);
    // With Finlayson's constraint, `gamut` carries C too: P is F ∩ C.
    const bool truth_inside = P.contains(light.true_map);
    // The route (certified where it applies and can certify, else exact) is score_rules' choice.
    const ScoredRules scored = score_rules(P, light.true_map, setup.canonical_light, score_options);
    rec.area = scored.area;
    for (Rule r : all_rules)
      if (scored.rules[r]) rec.rules[static_cast<std::size_t>(r)] = record(*scored.rules[r], truth_inside);
    if (crule_gamut) score_crule(setup, config, *crule_gamut, light, image_colours, rec);
  }
  return records;
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

// The result's description before any scene: names, rules, baselines and the canonical gamut(s).
ExperimentResult result_header(const ExperimentSetup& setup, const ExperimentConfig& config) {
  ExperimentResult result;
  result.name = setup.name;
  result.figure = setup.figure;
  for (const TestLight& l : setup.lights) result.lights.push_back(l.name);
  result.config = config;
  result.config.progress = nullptr;
  for (Rule r : all_rules) result.rules.push_back(to_string(r));
  result.rules.insert(result.rules.end(), experiment_rules_3d.begin(),
                      experiment_rules_3d.begin() + static_cast<std::ptrdiff_t>(experiment_rules_3d_count(config)));
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
        records[j] = run_cell(setup, config, gamuts[setup.canonical_chromaticity_sets.empty() ? 0 : setup.lights[l].canonical],
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
