// The gamut-mapping experiment's scenes (gamut_experiment.h, "Scene generator" in
// docs/reproduction.md): each drawn from its own generator, its rules and baselines scored, in 2-D
// and with CRULE in 3-D.
#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/numerics/interrupt.h>
#include <gmcc/selection/select_scene_options.h>

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/geometry/lazy_convex_set_3.h>
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
// the cone mean of F3's perspective image), each worst case over F3. CRULE's certified route
// (crule_3d.h) on F3 kept symbolic (feasible_set_3d_lazy: the same answers as on the exact set,
// docs/math.md §1b "The lazy form"): max-volume and max-trace exact, the centroid certified (its
// double map, taken exactly, is what is scored); F3 is made exact only for the cone mean.
void score_crule(const ExperimentSetup& setup, const ExperimentConfig& config, const CanonicalConstraints3& crule_gamut,
                 const TestLight& light, const std::vector<Colour>& image_colours, SceneRecord& rec) {
  const LazyConvexSet3 F = feasible_set_3d_lazy({{&crule_gamut, &image_colours}});
  const bool truth3_inside = contains(F, light.true_diagonal_map);
  // The 3-D map d of a selection, its worst case over F3 given: scored when d3 > 0.
  auto score = [&](std::size_t slot, const Point3& d, double worst_case_deg) {
    if (sgn(d.z) <= 0) return;  // the zero map (or one in the plane d3 = 0) has no perspective
    RuleErrors x = exact_rule_errors({Rational(d.x / d.z), Rational(d.y / d.z)}, light.true_map, setup.canonical_light);
    x.worst_case_deg = worst_case_deg;
    rec.rules[slot] = record(x, truth3_inside);
  };
  if (F.kind() == ConvexKind3::empty) return;
  const std::vector<Rule3> rules3 = experiment_rules_3(config);
  for (std::size_t r = 0; r < rules3.size(); ++r) {
    const Selection3 s = with_worst_case(F, select_rule_3(rules3[r], F, Crule3dRoute::certified));
    if (s.worst_case_deg) score(rule_count + r, measured_map(s.estimate), *s.worst_case_deg);
  }
  if (!config.crule_extended) return;
  const std::optional<MapEstimate> cone = perspective_cone_mean(F.exact(), config.mean3d);
  if (cone && cone->valid) {
    const Point2 m = measured_map(*cone);
    const Point3 lift{m.x, m.y, Rational(1)};
    score(rule_count + rules3.size(), lift, worst_case_map_deg_3d(F, lift));
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
}  // namespace

namespace internal {

std::vector<SceneRecord> run_cell(const ExperimentSetup& setup, const ExperimentConfig& config,
                                  const CanonicalConstraints& gamut, const CanonicalConstraints3* crule_gamut,
                                  const std::vector<Point2>& chromaticities,
                                  std::size_t light_index, int n, std::uint64_t s_begin, std::uint64_t s_end,
                                  std::atomic<std::uint64_t>& done) {
  const TestLight& light = setup.lights[light_index];
  const std::size_t R = rule_count + experiment_rule_names_3d(config).size();
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

}  // namespace internal
}  // namespace gmcc
