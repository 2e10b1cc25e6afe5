// The benchmark's run (benchmark.h): per fold, the canonical gamuts learned from the other folds
// and every method's record of the fold's images; the methods' names.
#include <gmcc/validation/benchmark.h>

#include "benchmark_methods.h"

#include <gmcc/geometry/feasible_set.h>
#include <gmcc/input/camera_image.h>
#include <gmcc/numerics/interrupt.h>
#include <gmcc/input/image_file.h>
#include <gmcc/input/input_error.h>
#include <gmcc/photo/edge_colours.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/grey_edge.h>
#include <gmcc/selection/gcie.h>
#include <gmcc/selection/prepare_canonical.h>
#include <gmcc/selection/select_scene.h>

#include <mpfr.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>

namespace gmcc {
using namespace internal;
namespace {

// f(i) for i in [0, n) on `threads` threads; the first exception (by index) rethrown; progress
// reported from the calling thread.
void parallel_for(std::size_t n, unsigned threads, const std::function<void(std::size_t)>& f,
                  const std::function<void(std::size_t)>& progress) {
  std::atomic<std::size_t> next{0}, done{0};
  std::vector<std::exception_ptr> errors(n);
  auto work = [&] {
    for (std::size_t i; (i = next++) < n;) {
      try {
        check_interrupt();  // a caller's Ctrl-C (interrupt.h): between images
        f(i);
      } catch (...) {
        errors[i] = std::current_exception();
        next = n;  // stop handing out work
      }
      ++done;
    }
  };
  const unsigned t = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(std::max<std::size_t>(n, 1))));
  std::vector<std::thread> pool;
  // A worker's MPFR constant caches (π for the angles) are thread-local: freed as it ends.
  for (unsigned k = 1; k < t; ++k)
    pool.emplace_back([&work] {
      work();
      mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
    });
  if (progress && t > 1) {
    while (done < n && next < n) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      progress(done);
    }
  }
  work();
  for (std::thread& th : pool) th.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  if (progress) progress(done);
}

}  // namespace

const std::vector<std::string>& benchmark_methods() {
  static const std::vector<std::string> m = [] {
    std::vector<std::string> names;
    for (Rule3 rule : benchmark_rules_3()) names.push_back(gm3d_method(rule));
    for (Rule rule : all_rules) names.push_back(gm2d_method(rule));
    for (std::size_t b = 0; b < all_baselines.size(); ++b) names.push_back(baseline_method(b));
    names.insert(names.end(), std::begin(kEdge), std::end(kEdge));
    for (Rule3 rule : benchmark_rules_3()) names.push_back(gm3d_constrained_method(rule));
    for (Rule rule : all_rules) names.push_back(gm2d_constrained_method(rule));
    names.push_back(kGcie);
    return names;
  }();
  return m;
}

bool is_edge_gamut_method(const std::string& method) {
  return std::find(std::begin(kEdge), std::end(kEdge), method) != std::end(kEdge);
}

const std::vector<std::string>& default_benchmark_methods() {
  static const std::vector<std::string> m(
      benchmark_methods().begin(), benchmark_methods().begin() + rule_3_count + all_rules.size() + all_baselines.size());
  return m;
}

namespace {

// One fold's canonical gamuts, learned from the other folds' reduced images.
struct FoldCanonicals {
  std::optional<CanonicalConstraints3> gamut3;
  std::optional<CanonicalConstraints3> edges[2];  // absent when no training image has such colours
  std::optional<PreparedCanonical> gamut2;
  std::vector<Colour> lights;  // the training images' lights: the constrained methods' plausible lights
  std::optional<PreparedCanonical> gamut2c;  // gamut2 with the illumination constraint of `lights`
  std::optional<GcieGamuts> gcie;  // GCIE: the canonical gamut (the training colours' perspective hull) under each light
};

FoldCanonicals learn_fold(int fold, const std::vector<BenchmarkImage>& images, const std::vector<Reduced>& reduced,
                          const BenchmarkOptions& o, const Needs& n) {
  CanonicalLearner3 learner3(o.intensity);
  // GCIE learns its perspective gamut from the 3-D hulls' vertices, the colours it scores.
  CanonicalLearner2 learner2, learner_gcie;
  // Edge colours scaled by their image's pixel factor (learn_canonical.h).
  CanonicalLearner3 edges[2];
  std::size_t training = 0;
  std::size_t colourful = 0;  // training images with a pixel colour above black (the pixel gamut's contributors)
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (images[i].fold == fold) continue;
    ++training;
    // The reduced colours are their hull's vertices already (ColourSet::hull_3d, reduce()).
    if (n.gamut3) learner3.add_hull_vertices(reduced[i].hull3, images[i].light);
    if (n.gm2d) learner2.add(reduced[i].lifts, images[i].light);
    if (n.gcie) learner_gcie.add(reduced[i].hull3, images[i].light);
    if (!n.gm3d) continue;
    const Colour& e = images[i].light;
    if (sgn(e.r) <= 0 || sgn(e.g) <= 0 || sgn(e.b) <= 0)  // as the learners say it
      throw std::invalid_argument("a training light needs every channel > 0");
    // The pixel colours' scale from their largest channels: the same as from every colour.
    const Rational top = white_balanced_maximum({reduced[i].top}, e);
    if (sgn(top) > 0) ++colourful;
    const Rational scale = o.intensity == CanonicalIntensity::max ? top : Rational(1);
    if (sgn(scale) == 0) continue;  // only black: the pixel gamut takes nothing of it either
    for (int k = 0; k < 2; ++k)
      if (n.order[k]) edges[k].add_hull_vertices(reduced[i].edges[k], images[i].light, scale);
  }
  if (training == 0) throw std::invalid_argument("fold " + std::to_string(fold) + " has no training image (one fold only)");
  // Training images that give only black (a black level or saturation that leaves no colour):
  // no canonical gamut can be learned, a fault of the input, not of the program.
  if ((n.gm3d && colourful == 0) || (n.gm2d && learner2.gamut().empty()) ||
      (n.gcie && learner_gcie.gamut().empty()))
    throw InputError("fold " + std::to_string(fold), 0,
                     "its " + std::to_string(training) + " training images give no colour above black (the black "
                     "level, saturation and dark rules leave none): no canonical gamut can be learned");
  FoldCanonicals c;
  for (std::size_t i = 0; i < images.size(); ++i)
    if (images[i].fold != fold) c.lights.push_back(images[i].light);
  if (n.gamut3) c.gamut3.emplace(learner3.gamut(), o.black);
  if (n.gcie) c.gcie.emplace(learner_gcie.gamut(), Colour{Rational(1), Rational(1), Rational(1)}, c.lights);
  for (int k = 0; k < 2; ++k)
    if (n.order[k] && edges[k].contributing() > 0) c.edges[k].emplace(edges[k].gamut(), o.black);
  if (n.gm2d) {
    std::vector<Colour> lifts;
    for (const Point2& p : learner2.gamut()) lifts.push_back({p.x, p.y, Rational(1)});
    c.gamut2.emplace(prepare_canonical(lifts, SelectSceneOptions{}));
    if (n.gm2dc) {
      SelectSceneOptions constrained;
      constrained.illuminants = c.lights;
      c.gamut2c.emplace(prepare_canonical(lifts, constrained));
    }
  }
  return c;
}

// A 3-D estimate from some gamut types' constraints, with the truth's errors and whether the
// true light's map lies in F3 (estimate_3d.h); none when F3 is unbounded.
std::optional<ImageEstimate3> estimate_in_f(const std::vector<GamutConstraint3>& types, const std::vector<Rule3>& rules,
                                            const Colour& e, const std::vector<Colour>& plausible = {}) {
  Estimate3Options eo;
  eo.rules = rules;
  eo.truth = e;
  eo.illuminants = plausible;
  try {
    return estimate_3d(types, eo);
  } catch (const UnboundedFeasibleSet&) {
    return std::nullopt;
  }
}

// One 3-D rule's record from an estimate (light absent where the rule gave none).
BenchmarkRecord record_3d(const std::string& method, const std::optional<ImageEstimate3>& est, Rule3 rule) {
  BenchmarkRecord rec;
  rec.method = method;
  if (!est) {
    rec.unanswered = "unbounded";
    return rec;
  }
  rec.feasible_kind = to_string(est->lazy_feasible.kind());
  rec.feasible_vertices = est->lazy_feasible.size();
  rec.truth_in_feasible = est->truth_in_feasible;
  rec.worst_case_space = "map";
  const std::optional<ImageSelection3>& s = (*est)[rule];
  if (s) rec.worst_case_deg = s->selection.worst_case_deg;
  if (s && s->light) {
    rec.light = s->light;
    rec.answered = true;
    rec.worst_case_space_error_deg = s->map_error_deg;
  } else {
    rec.unanswered = s ? "no_positive_map" : "empty";
  }
  return rec;
}

// The 3-D rules' records of one image: unconstrained, and with the fold's training lights as the
// plausible lights (F3 ∩ the cone of their maps).
std::vector<BenchmarkRecord> records_3d(const FoldCanonicals& c, const Reduced& r, const Colour& e, const Needs& n) {
  std::vector<BenchmarkRecord> out;
  for (const bool constrained : {false, true}) {
    std::vector<Rule3> rules;
    for (Rule3 rule : all_rules_3)
      if ((constrained ? n.rule3c : n.rule3)[rule]) rules.push_back(rule);
    if (rules.empty()) continue;
    const std::optional<ImageEstimate3> est =
        estimate_in_f({{&*c.gamut3, &r.hull3, true}}, rules, e, constrained ? c.lights : std::vector<Colour>{});
    for (Rule3 rule : rules)
      out.push_back(record_3d(constrained ? gm3d_constrained_method(rule) : gm3d_method(rule), est, rule));
  }
  return out;
}

// The edge-based methods' records of one image: max-trace on the joint feasible set of their
// gamut types; no feasible set when a type has no canonical gamut or no colour in this image.
std::vector<BenchmarkRecord> records_edges(const FoldCanonicals& c, const Reduced& r, const Colour& e,
                                           const Needs& n) {
  std::vector<BenchmarkRecord> out;
  for (int k = 0; k < 4; ++k) {
    if (!n.edge[k]) continue;
    std::vector<GamutConstraint3> types;
    bool available = true;
    const std::optional<CanonicalConstraints3>* gamuts[3] = {&c.gamut3, &c.edges[0], &c.edges[1]};
    const std::vector<Colour>* colours[3] = {&r.hull3, &r.edges[0], &r.edges[1]};
    for (int t = 0; t < 3; ++t) {
      if (!kEdgeTypes[k][t]) continue;
      if (!*gamuts[t] || colours[t]->empty()) available = false;
      else types.push_back({&**gamuts[t], colours[t], true});  // reduce() kept hull vertices only
    }
    BenchmarkRecord rec;
    rec.method = kEdge[k];
    rec.unanswered = "no_colours";
    if (available) rec = record_3d(kEdge[k], estimate_in_f(types, {Rule3::max_trace}, e), Rule3::max_trace);
    out.push_back(std::move(rec));
  }
  return out;
}

// The 2-D rules' records of one image: the select pipeline on its chromaticity lifts, against
// the fold's gamut, or with `constrained` against it with the illumination constraint.
std::vector<BenchmarkRecord> records_2d(const FoldCanonicals& c, const Reduced& r, const Colour& e, const Needs& n,
                                        bool constrained) {
  const PreparedCanonical& canonical = constrained ? *c.gamut2c : *c.gamut2;
  const PerRule<bool>& asked = constrained ? n.rule2c : n.rule2;
  if (std::none_of(all_rules.begin(), all_rules.end(), [&](Rule k) { return asked[k]; })) return {};
  std::optional<SceneResult> scene;
  if (!r.lifts.empty()) {
    try {
      scene = select_scene(canonical, r.lifts, e);
    } catch (const SceneInputError&) {  // no usable colour, a map beyond range: no estimate
    }
  }
  std::vector<BenchmarkRecord> out;
  for (Rule k : all_rules) {
    if (!asked[k]) continue;
    BenchmarkRecord rec;
    rec.method = constrained ? gm2d_constrained_method(k) : gm2d_method(k);
    rec.unanswered = "no_colours";
    if (scene) {
      rec.feasible_kind = to_string(scene->feasible.kind);
      rec.feasible_vertices = scene->feasible.vertices.size();
      if (scene->truth) rec.truth_in_feasible = scene->truth->in_feasible_set;
      rec.worst_case_space = "illuminant";
      rec.unanswered = scene->feasible.kind == ConvexKind::empty ? "empty" : "no_positive_map";
      const std::optional<Selection>& s = scene->selections[k];
      if (s && s->estimate.valid && s->estimate.map[0] > 0 && s->estimate.map[1] > 0) {
        rec.light = light_of_perspective_map(s->estimate.map, Colour{Rational(1), Rational(1), Rational(1)});
        rec.answered = true;
        rec.unanswered.clear();
        // The illuminant-space worst case, or, where F or the map touches an axis (lights
        // without bound: no illuminant worst case), the map-space one with the map-space error.
        const std::optional<RuleErrors>* t = scene->truth ? &scene->truth->errors[k] : nullptr;
        if (s->worst_case_illuminant_deg) {
          rec.worst_case_deg = s->worst_case_illuminant_deg;
          if (t && *t && (*t)->positive_map) rec.worst_case_space_error_deg = (*t)->illuminant_error_deg;
        } else {
          rec.worst_case_space = "map";
          rec.worst_case_deg = s->worst_case_deg;
          if (t && *t) rec.worst_case_space_error_deg = (*t)->map_error_deg;
        }
      }
    }
    out.push_back(std::move(rec));
  }
  return out;
}

// GCIE's record of one image: the fold's training light whose gamut is most consistent with the
// image's colours (gcie.h); no light when the image kept no colour.
BenchmarkRecord record_gcie(const FoldCanonicals& c, const Reduced& r) {
  BenchmarkRecord rec;
  rec.method = kGcie;
  if (r.hull3.empty()) {
    rec.unanswered = "no_light";
    return rec;
  }
  const Colour& l = c.lights[c.gcie->select(r.hull3).light];
  // The light as the unit doubles of the map c ⊘ l it implies (light_of_map_3: scale-safe).
  rec.light = light_of_map_3({Rational(1 / l.r), Rational(1 / l.g), Rational(1 / l.b)},
                             Colour{Rational(1), Rational(1), Rational(1)});
  rec.answered = true;
  return rec;
}

// Every method's record of image i, in the order asked: grey world where a method gave no light,
// and the error against the measured light.
std::vector<BenchmarkRecord> records_of(std::size_t i, const FoldCanonicals& c, const Reduced& r, const Colour& e,
                                        const BenchmarkOptions& o, const Needs& n) {
  std::map<std::string, BenchmarkRecord> made;
  auto keep = [&](std::vector<BenchmarkRecord> recs) {
    for (BenchmarkRecord& rec : recs) {
      const std::string name = rec.method;
      made[name] = std::move(rec);
    }
  };
  if (n.gm3d) keep(records_3d(c, r, e, n));
  keep(records_edges(c, r, e, n));
  if (n.gm2d) keep(records_2d(c, r, e, n, false));
  if (n.gm2dc) keep(records_2d(c, r, e, n, true));
  if (n.gcie) keep({record_gcie(c, r)});
  for (std::size_t b = 0; b < all_baselines.size(); ++b) {
    BenchmarkRecord rec;
    rec.method = baseline_method(b);
    rec.light = r.baselines[b];
    rec.answered = r.baselines[b].has_value();
    if (!rec.answered) rec.unanswered = "no_light";
    keep({std::move(rec)});
  }
  std::vector<BenchmarkRecord> out;
  for (const std::string& m : o.methods) {
    BenchmarkRecord rec = std::move(made.at(m));
    rec.image = i;
    if (!rec.light && !rec.answered && r.baselines[0]) {
      rec.light = r.baselines[0];
      rec.fallback = "grey_world";
    }
    if (rec.light) rec.error_deg = recovery_angular_error_deg(*rec.light, e);
    out.push_back(std::move(rec));
  }
  return out;
}

}  // namespace

BenchmarkResult run_benchmark(const std::vector<BenchmarkImage>& images, const BenchmarkOptions& o) {
  if (images.empty()) throw std::invalid_argument("the benchmark has no image");
  if (o.shard_count < 1 || o.shard_index < 1 || o.shard_index > o.shard_count)
    throw std::invalid_argument("a shard K/N needs 1 <= K <= N");
  const Needs n = needs_of(o.methods);
  const bool grey_edge = n.baseline[static_cast<std::size_t>(Baseline::grey_edge_1)] ||
                         n.baseline[static_cast<std::size_t>(Baseline::grey_edge_2)];
  if ((n.order[0] || n.order[1] || grey_edge) && !(o.edge_sigma > 0 && o.edge_sigma <= 64))
    throw std::invalid_argument("the edge-based methods' and grey edge's sigma must be in (0, 64] pixels");
  if (n.order[0] || n.order[1]) {
    if (o.pixels.rules.prefilter_sigma != 0)
      throw std::invalid_argument("the edge-based methods take no pre-filter (their derivatives are Gaussian already)");
  }
  const unsigned threads = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t total = images.size();
  std::set<int> folds;
  for (const BenchmarkImage& im : images) {
    if (im.fold < 0) throw std::invalid_argument("image " + im.name + ": a fold must be >= 0");
    folds.insert(im.fold);
  }
  // 1. Every image reduced, in parallel (the first half of the progress).
  std::vector<Reduced> reduced(total);
  parallel_for(total, threads, [&](std::size_t i) { reduced[i] = reduce(images[i], o, n); },
               [&](std::size_t done) {
                 if (o.progress) o.progress(std::min(total, done / 2), total);
               });
  // 2. Per fold: the canonical gamuts from the other folds, then the fold's images (this shard's).
  std::vector<std::vector<BenchmarkRecord>> per_image(total);
  std::size_t estimated = 0;
  for (int fold : folds) {
    std::vector<std::size_t> test;
    for (std::size_t i = 0; i < total; ++i)
      if (images[i].fold == fold && i % o.shard_count == o.shard_index - 1) test.push_back(i);
    if (test.empty()) continue;  // another shard's
    const FoldCanonicals c = learn_fold(fold, images, reduced, o, n);
    parallel_for(
        test.size(), threads,
        [&](std::size_t k) { per_image[test[k]] = records_of(test[k], c, reduced[test[k]], images[test[k]].light, o, n); },
        [&](std::size_t done) {
          if (o.progress) o.progress(std::min(total, (total + estimated + done) / 2), total);
        });
    estimated += test.size();
  }
  BenchmarkResult result;
  for (std::vector<BenchmarkRecord>& v : per_image)
    for (BenchmarkRecord& r : v) result.records.push_back(std::move(r));
  result.summaries = summarise_benchmark(result.records, o.methods);
  return result;
}

}  // namespace gmcc
