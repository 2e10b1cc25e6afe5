#include <gmcc/validation/benchmark.h>

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
namespace {

const char* const kGm3d[3] = {"gm3d-max-volume", "gm3d-centroid", "gm3d-max-trace"};
// A key with dashes for underscores: how methods are named.
std::string dashed(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

// The 2-D perspective route's method for `rule` (gm2d-max-area, …), and a baseline's (grey-world, …).
std::string gm2d_method(Rule rule) { return "gm2d-" + dashed(to_string(rule)); }
std::string baseline_method(std::size_t b) { return dashed(to_string(all_baselines[b])); }
// The edge-based methods (max-trace): edge-1, edge-2, 1-jet (pixel ∩ edge-1), 2-jet (∩ edge-2).
const char* const kEdge[4] = {"gm3d-edge1-max-trace", "gm3d-edge2-max-trace", "gm3d-1jet-max-trace",
                              "gm3d-2jet-max-trace"};
// Which gamut types edge-based method k intersects: pixel, 1st-order, 2nd-order.
constexpr bool kEdgeTypes[4][3] = {{false, true, false}, {false, false, true}, {true, true, false}, {true, true, true}};

// What an image is reduced to: all the methods need of it.
struct Reduced {
  std::vector<Colour> hull3;  // pixel colours on their 3-D hull
  std::vector<Colour> lifts;  // chromaticity lifts of their 2-D hull
  std::vector<Colour> edges[2];  // 1st- and 2nd-order edge colours on their 3-D hull
  std::array<std::optional<std::array<double, 3>>, all_baselines.size()> baselines;
};

// Which families the methods asked for need.
struct Needs {
  bool gm3d = false, gm2d = false;  // gm3d: the pixel colours' 3-D hull and canonical gamut
  std::array<bool, 3> rule3{};
  PerRule<bool> rule2{};
  std::array<bool, 4> edge{};  // the edge-based methods
  std::array<bool, 2> order{};  // the 1st- and 2nd-order edge colours and canonical gamuts
  std::array<bool, all_baselines.size()> baseline{};
};

Needs needs_of(const std::vector<std::string>& methods) {
  Needs n;
  n.baseline[0] = true;  // grey world: every gamut method's fallback
  for (const std::string& m : methods) {
    bool known = false;
    for (int k = 0; k < 3; ++k)
      if (m == kGm3d[k]) n.gm3d = n.rule3[k] = known = true;
    for (Rule rule : all_rules)
      if (m == gm2d_method(rule)) n.gm2d = n.rule2[rule] = known = true;
    // An edge-based method needs the pixel colours too: their scale is its edge colours' scale.
    for (int k = 0; k < 4; ++k)
      if (m == kEdge[k]) {
        n.gm3d = n.edge[k] = known = true;
        for (int o = 0; o < 2; ++o) n.order[o] = n.order[o] || kEdgeTypes[k][o + 1];
      }
    for (std::size_t b = 0; b < all_baselines.size() && !known; ++b)
      if (m == baseline_method(b)) n.baseline[b] = known = true;
    if (!known) throw std::invalid_argument("unknown benchmark method \"" + m + "\"");
  }
  return n;
}

// The run's pixel rules with the image's own.
PixelRules rules_of(const BenchmarkImage& im, const PixelRules& run) {
  PixelRules r = run;
  r.exclude_polygons.insert(r.exclude_polygons.end(), im.exclude_polygons.begin(), im.exclude_polygons.end());
  r.bin = 1;
  return r;
}

Reduced reduce(const BenchmarkImage& im, const BenchmarkOptions& o, const Needs& n) {
  PixelRules rules = rules_of(im, o.pixels);
  ImageLevels levels;
  if (o.black_level_given) levels.black = o.pixels.black_level;
  levels.saturation = o.pixels.saturation;
  if (im.black_level) levels.black = im.black_level;
  if (im.saturation) levels.saturation = im.saturation;
  const RgbImage image = read_camera_image(im.path, levels, rules);
  if (!im.mask_path.empty()) {
    const RgbImage mask = read_mask_image(im.mask_path);
    if (mask.width != image.width || mask.height != image.height)
      throw InputError(im.mask_path, 0, "the mask is " + std::to_string(mask.width) + "x" +
                                            std::to_string(mask.height) + ", its image " + im.path + " is " +
                                            std::to_string(image.width) + "x" + std::to_string(image.height));
    rules.keep.resize(image.width * image.height);
    for (std::size_t p = 0; p < rules.keep.size(); ++p)
      rules.keep[p] = mask.samples[3 * p] || mask.samples[3 * p + 1] || mask.samples[3 * p + 2];
  }
  if (o.saturation_max && !levels.saturation) rules.saturation = (1u << image.bits) - 1;
  Reduced r;
  KeptPixels kept;
  try {
    kept = kept_pixels(image, rules);
  } catch (const std::invalid_argument& e) {  // the rules against this image (polygon work)
    throw InputError(im.path, 0, e.what());
  }
  if (kept.counts.kept == 0)
    throw InputError(im.path, 0, "no usable pixel after the mask, saturation and dark or bright rules");
  if (n.gm3d) {
    rules.colour_set = ColourSet::hull_3d;
    r.hull3 = image_colours(image, rules).colours;
  }
  for (int k = 0; k < 2; ++k)
    if (n.order[k]) {
      rules.colour_set = ColourSet::hull_3d;
      EdgeRules edges;
      edges.order = k == 0 ? DerivativeOrder::first : DerivativeOrder::second;
      edges.sigma = o.edge_sigma;
      r.edges[k] = edge_colours(image, rules, edges).colours;
    }
  if (n.gm2d) {
    rules.colour_set = ColourSet::hull;
    r.lifts = image_colours(image, rules).colours;
  }
  const DoubleImage linear = linear_image(image, rules.black_level);
  for (std::size_t b = 0; b < all_baselines.size(); ++b)
    if (n.baseline[b]) r.baselines[b] = grey_edge_estimate(linear, kept.kept, baseline_parameters(all_baselines[b]));
  return r;
}

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

// Spearman's rank correlation (average ranks for ties); absent below 3 pairs or with no spread.
std::optional<double> spearman(const std::vector<std::pair<double, double>>& xy) {
  const std::size_t n = xy.size();
  if (n < 3) return std::nullopt;
  auto ranks = [n](std::vector<double> v) {
    std::vector<std::size_t> idx(n);
    for (std::size_t i = 0; i < n; ++i) idx[i] = i;
    std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    std::vector<double> r(n);
    for (std::size_t i = 0; i < n;) {
      std::size_t j = i;
      while (j + 1 < n && v[idx[j + 1]] == v[idx[i]]) ++j;
      for (std::size_t k = i; k <= j; ++k) r[idx[k]] = 0.5 * double(i + j) + 1;
      i = j + 1;
    }
    return r;
  };
  std::vector<double> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = xy[i].first, y[i] = xy[i].second;
  const std::vector<double> rx = ranks(x), ry = ranks(y);
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += rx[i], my += ry[i];
  mx /= double(n), my /= double(n);
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (rx[i] - mx) * (ry[i] - my);
    sxx += (rx[i] - mx) * (rx[i] - mx);
    syy += (ry[i] - my) * (ry[i] - my);
  }
  if (sxx == 0 || syy == 0) return std::nullopt;
  return sxy / std::sqrt(sxx * syy);
}

}  // namespace

std::vector<BenchmarkImage> benchmark_dataset(const std::string& images_dir, const std::vector<TruthRow>& rows,
                                              const std::map<std::string, int>* folds, const std::string& folds_path,
                                              int k) {
  if (!folds && k < 2) throw std::invalid_argument("a benchmark needs at least 2 folds");
  std::vector<BenchmarkImage> images;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const TruthRow& r = rows[i];
    BenchmarkImage im;
    im.name = r.image;
    im.path = (std::filesystem::path(images_dir) / r.image).string();
    im.light = r.light;
    if (folds) {
      const auto f = folds->find(r.image);
      if (f == folds->end())
        throw InputError(folds_path, 0, "no fold for image " + r.image + " (truth table line " + std::to_string(r.line) + ")");
      im.fold = f->second;
    } else {
      im.fold = static_cast<int>(i % static_cast<std::size_t>(k));
    }
    im.black_level = r.black_level;
    im.saturation = r.saturation;
    if (!r.chart.empty()) im.exclude_polygons.push_back(r.chart);
    if (!r.mask.empty()) im.mask_path = (std::filesystem::path(images_dir) / r.mask).string();
    images.push_back(std::move(im));
  }
  return images;
}

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

std::vector<BenchmarkSummary> summarise_benchmark(const std::vector<BenchmarkRecord>& records,
                                                  const std::vector<std::string>& methods) {
  std::vector<BenchmarkSummary> out;
  for (const std::string& m : methods) {
    BenchmarkSummary s;
    s.method = m;
    std::vector<double> errors;
    std::vector<std::pair<double, double>> wc;
    std::size_t covered = 0;
    bool gamut = false;
    for (const BenchmarkRecord& r : records) {
      if (r.method != m) continue;
      ++s.images;
      gamut = gamut || !r.feasible_kind.empty();
      if (r.answered) ++s.answered;
      if (!r.feasible_kind.empty() && !r.answered) ++s.empty;
      if (r.error_deg) errors.push_back(*r.error_deg);
      if (r.truth_in_feasible && *r.truth_in_feasible) ++s.truth_in_feasible;
      if (r.answered && r.worst_case_deg && r.error_deg) {
        wc.push_back({*r.worst_case_deg, *r.error_deg});
        covered += *r.error_deg <= *r.worst_case_deg;
      }
    }
    s.errors = error_statistics(errors);
    if (gamut && !wc.empty()) {
      s.worst_case_covers = double(covered) / double(wc.size());
      s.worst_case_correlation = spearman(wc);
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace gmcc
