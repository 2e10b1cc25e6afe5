// The benchmark's run (benchmark.h): per fold, the canonical gamuts learned from the other folds
// and every method's record of the fold's images; the methods' names.
#include <gmcc/validation/benchmark.h>

#include "benchmark_methods.h"

#include <gmcc/geometry/perspective_image.h>
#include <gmcc/input/camera_image.h>
#include <gmcc/numerics/interrupt.h>
#include <gmcc/input/image_file.h>
#include <gmcc/input/input_error.h>
#include <gmcc/photo/edge_colours.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/grey_edge.h>
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

// The perspective map (m1, m2) of the map c ⊘ e that takes light e to the white canonical light.
Point2 true_perspective_map(const Colour& e) { return {Rational(e.b / e.r), Rational(e.b / e.g)}; }

}  // namespace

const std::vector<std::string>& benchmark_methods() {
  static const std::vector<std::string> m = [] {
    std::vector<std::string> names = {"gm3d-max-trace", "gm3d-max-volume", "gm3d-centroid"};
    for (Rule rule : all_rules) names.push_back(gm2d_method(rule));
    for (std::size_t b = 0; b < all_baselines.size(); ++b) names.push_back(baseline_method(b));
    names.insert(names.end(), std::begin(kEdge), std::end(kEdge));
    return names;
  }();
  return m;
}

bool is_edge_gamut_method(const std::string& method) {
  return std::find(std::begin(kEdge), std::end(kEdge), method) != std::end(kEdge);
}

const std::vector<std::string>& default_benchmark_methods() {
  static const std::vector<std::string> m(benchmark_methods().begin(), benchmark_methods().end() - std::size(kEdge));
  return m;
}

namespace {

// One fold's canonical gamuts, learned from the other folds' reduced images.
struct FoldCanonicals {
  std::optional<CanonicalConstraints3> gamut3;
  std::optional<CanonicalConstraints3> edges[2];  // absent when no training image has such colours
  std::optional<PreparedCanonical> gamut2;
};

FoldCanonicals learn_fold(int fold, const std::vector<BenchmarkImage>& images, const std::vector<Reduced>& reduced,
                          const BenchmarkOptions& o, const Needs& n) {
  CanonicalLearner3 learner3(o.intensity);
  CanonicalLearner2 learner2;
  // Edge colours scaled by their image's pixel factor (learn_canonical.h).
  CanonicalLearner3 edges[2];
  std::size_t training = 0;
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (images[i].fold == fold) continue;
    ++training;
    if (n.gm3d) learner3.add(reduced[i].hull3, images[i].light);
    if (n.gm2d) learner2.add(reduced[i].lifts, images[i].light);
    if (!n.order[0] && !n.order[1]) continue;
    Rational scale(1);
    if (o.intensity == CanonicalIntensity::max) scale = white_balanced_maximum(reduced[i].hull3, images[i].light);
    if (sgn(scale) == 0) continue;  // only black: the pixel gamut takes nothing of it either
    for (int k = 0; k < 2; ++k)
      if (n.order[k]) edges[k].add(reduced[i].edges[k], images[i].light, scale);
  }
  if (training == 0) throw std::invalid_argument("fold " + std::to_string(fold) + " has no training image (one fold only)");
  // Training images that give only black (a black level or saturation that leaves no colour):
  // no canonical gamut can be learned, a fault of the input, not of the program.
  if ((n.gm3d && learner3.contributing() == 0) || (n.gm2d && learner2.gamut().empty()))
    throw InputError("fold " + std::to_string(fold), 0,
                     "its " + std::to_string(training) + " training images give no colour above black (the black "
                     "level, saturation and dark rules leave none): no canonical gamut can be learned");
  FoldCanonicals c;
  if (n.gm3d) c.gamut3.emplace(learner3.gamut(), o.black);
  for (int k = 0; k < 2; ++k)
    if (n.order[k] && edges[k].contributing() > 0) c.edges[k].emplace(edges[k].gamut(), o.black);
  if (n.gm2d) {
    std::vector<Colour> lifts;
    for (const Point2& p : learner2.gamut()) lifts.push_back({p.x, p.y, Rational(1)});
    c.gamut2.emplace(prepare_canonical(lifts, SelectSceneOptions{}));
  }
  return c;
}

// A 3-D estimate from some gamut types' constraints, and whether the true light's map lies in
// its feasible set; no estimate when F3 is unbounded.
struct Estimate3InF {
  std::optional<ImageEstimate3> estimate;
  std::optional<bool> truth_in_feasible;
};
Estimate3InF estimate_in_f(const std::vector<GamutConstraint3>& types, const std::vector<Rule3>& rules,
                           const Colour& e) {
  Estimate3InF out;
  Estimate3Options eo;
  eo.rules = rules;
  try {
    out.estimate = estimate_3d(types, eo);
  } catch (const std::domain_error&) {  // unbounded F3: no estimate
    return out;
  }
  if (out.estimate->feasible.kind != ConvexKind3::empty) {
    const std::optional<ConvexSet2> image = perspective_image(out.estimate->feasible);
    out.truth_in_feasible = image && contains(*image, true_perspective_map(e));
  } else {
    out.truth_in_feasible = false;
  }
  return out;
}

// One 3-D rule's record from an estimate (light absent where the rule gave none).
BenchmarkRecord record_3d(const char* method, const Estimate3InF& est, Rule3 rule) {
  BenchmarkRecord rec;
  rec.method = method;
  if (est.estimate) {
    rec.feasible_kind = to_string(est.estimate->feasible.kind);
    rec.feasible_vertices = est.estimate->feasible.vertices.size();
    rec.truth_in_feasible = est.truth_in_feasible;
    const std::optional<ImageSelection3>& s = (*est.estimate)[rule];
    if (s && s->light) {
      rec.light = s->light;
      rec.answered = true;
      rec.worst_case_deg = s->selection.worst_case_deg;
    }
  }
  return rec;
}

// The 3-D rules' records of one image.
std::vector<BenchmarkRecord> records_3d(const CanonicalConstraints3& canonical, const Reduced& r, const Colour& e,
                                        const Needs& n) {
  std::vector<Rule3> rules;
  for (Rule3 rule : all_rules_3)
    if (n.rule3[static_cast<int>(rule)]) rules.push_back(rule);
  std::vector<BenchmarkRecord> out;
  if (rules.empty()) return out;
  const Estimate3InF est = estimate_in_f({{&canonical, &r.hull3}}, rules, e);
  for (Rule3 rule : rules) out.push_back(record_3d(kGm3d[static_cast<int>(rule)], est, rule));
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
      else types.push_back({&**gamuts[t], colours[t]});
    }
    BenchmarkRecord rec;
    rec.method = kEdge[k];
    if (available) rec = record_3d(kEdge[k], estimate_in_f(types, {Rule3::max_trace}, e), Rule3::max_trace);
    out.push_back(std::move(rec));
  }
  return out;
}

// The 2-D rules' records of one image: the select pipeline on its chromaticity lifts.
std::vector<BenchmarkRecord> records_2d(const PreparedCanonical& canonical, const Reduced& r, const Colour& e,
                                        const Needs& n) {
  std::optional<SceneResult> scene;
  if (!r.lifts.empty()) {
    try {
      scene = select_scene(canonical, r.lifts, e);
    } catch (const SceneInputError&) {  // no usable colour, a map beyond range: no estimate
    }
  }
  std::vector<BenchmarkRecord> out;
  for (Rule k : all_rules) {
    if (!n.rule2[k]) continue;
    BenchmarkRecord rec;
    rec.method = gm2d_method(k);
    if (scene) {
      rec.feasible_kind = to_string(scene->feasible.kind);
      rec.feasible_vertices = scene->feasible.vertices.size();
      if (scene->truth) rec.truth_in_feasible = scene->truth->in_feasible_set;
      const std::optional<Selection>& s = scene->selections[k];
      if (s && s->estimate.valid && s->estimate.map[0] > 0 && s->estimate.map[1] > 0) {
        // e = c ⊘ (m1, m2, 1), c white: (1/m1, 1/m2, 1), unit length.
        const double l[3] = {1 / s->estimate.map[0], 1 / s->estimate.map[1], 1.0};
        const double len = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
        rec.light = std::array<double, 3>{l[0] / len, l[1] / len, l[2] / len};
        rec.answered = true;
        rec.worst_case_deg = s->worst_case_illuminant_deg;
      }
    }
    out.push_back(std::move(rec));
  }
  return out;
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
  if (n.gm3d) keep(records_3d(*c.gamut3, r, e, n));
  keep(records_edges(c, r, e, n));
  if (n.gm2d) keep(records_2d(*c.gamut2, r, e, n));
  for (std::size_t b = 0; b < all_baselines.size(); ++b) {
    BenchmarkRecord rec;
    rec.method = baseline_method(b);
    rec.light = r.baselines[b];
    rec.answered = r.baselines[b].has_value();
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
  if (n.order[0] || n.order[1]) {
    if (!(o.edge_sigma > 0 && o.edge_sigma <= 64))
      throw std::invalid_argument("the edge-based methods' sigma must be in (0, 64] pixels");
    if (o.pixels.prefilter_sigma != 0)
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
