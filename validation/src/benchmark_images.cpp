// The benchmark's images (benchmark.h): the dataset from the truth table and the folds, and each
// image read and reduced to what the methods asked for need of it.
#include <gmcc/validation/benchmark.h>

#include "benchmark_methods.h"

#include <gmcc/geometry/perspective_image.h>
#include <gmcc/input/camera_image.h>
#include <gmcc/photo/image_rules.h>
#include <gmcc/numerics/interrupt.h>
#include <gmcc/input/image_file.h>
#include <gmcc/input/input_error.h>
#include <gmcc/photo/edge_colours.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/image_hull_sets.h>
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
namespace internal {

Needs needs_of(const std::vector<std::string>& methods) {
  Needs n;
  n.baseline[0] = true;  // grey world: every gamut method's fallback
  std::set<std::string> seen;
  for (const std::string& m : methods) {
    if (!seen.insert(m).second) throw std::invalid_argument("benchmark method \"" + m + "\" is given twice");
    bool known = false;
    for (Rule3 rule : all_rules_3)
      if (m == gm3d_method(rule)) n.gm3d = n.hull3 = n.gamut3 = n.rule3[rule] = known = true;
    for (Rule rule : all_rules)
      if (m == gm2d_method(rule)) n.gm2d = n.rule2[rule] = known = true;
    for (Rule3 rule : all_rules_3)
      if (m == gm3d_constrained_method(rule)) n.gm3d = n.hull3 = n.gamut3 = n.rule3c[rule] = known = true;
    for (Rule rule : all_rules)
      if (m == gm2d_constrained_method(rule)) n.gm2d = n.gm2dc = n.rule2c[rule] = known = true;
    if (m == kGcie) n.gcie = known = true;
    // An edge-based method needs the pixel colours too: their scale is its edge colours' scale;
    // their hull and the pixel canonical gamut only when it intersects the pixel feasible set (the
    // n-jets).
    for (int k = 0; k < 4; ++k)
      if (m == kEdge[k]) {
        n.gm3d = n.edge[k] = known = true;
        n.hull3 = n.hull3 || kEdgeTypes[k][0];
        n.gamut3 = n.gamut3 || kEdgeTypes[k][0];
        for (int o = 0; o < 2; ++o) n.order[o] = n.order[o] || kEdgeTypes[k][o + 1];
      }
    for (std::size_t b = 0; b < all_baselines.size() && !known; ++b)
      if (m == baseline_method(b)) n.baseline[b] = known = true;
    if (!known) throw std::invalid_argument("unknown benchmark method \"" + m + "\"");
  }
  return n;
}

namespace {

// The kept pixels' largest linear channels (image_hull_sets' colours: the sample minus the black
// level, clamped at 0), from their hull's vertices when it was made (each channel's largest value
// is a vertex's: a linear function's maximum over conv(S) is reached at a vertex), else from every
// kept pixel: the same colour either way, and white_balanced_maximum({top}, e) is that of the
// colours, max over colours c and channels k of c_k/e_k, since every e_k > 0.
Colour largest_channels(const RgbImage& image, std::uint32_t black_level, const KeptPixels& kept,
                        const std::vector<Colour>& hull) {
  if (!hull.empty()) {
    Colour top{Rational(0), Rational(0), Rational(0)};
    for (const Colour& c : hull) top = {std::max(top.r, c.r), std::max(top.g, c.g), std::max(top.b, c.b)};
    return top;
  }
  std::array<std::uint32_t, 3> top{0, 0, 0};
  for (std::size_t i = 0; i < kept.kept.size(); ++i)
    if (kept.kept[i])
      for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t v = image.samples[3 * i + k];
        top[k] = std::max(top[k], v > black_level ? v - black_level : 0);
      }
  return {Rational(top[0]), Rational(top[1]), Rational(top[2])};
}

}  // namespace

Reduced reduce(const BenchmarkImage& im, const BenchmarkOptions& o, const Needs& n) {
  CameraImage read = read_camera_image(im.path, levels_to_read(o.pixels, im.own));
  std::optional<RgbImage> mask;
  if (!im.mask_path.empty()) mask = read_mask_image(im.mask_path);
  PixelRules rules = rules_for_image(o.pixels, im.own, read, im.path, mask ? &*mask : nullptr, im.mask_path);
  rules.bin = 1;
  const RgbImage& image = read.image;
  Reduced r;
  KeptPixels kept;
  try {
    kept = kept_pixels(image, rules);
  } catch (const std::invalid_argument& e) {  // the rules against this image (polygon work)
    throw InputError(im.path, 0, e.what());
  }
  if (kept.counts.kept == 0)
    throw InputError(im.path, 0, "no usable pixel after the mask, saturation and dark or bright rules");
  // The 3-D hull's colours and the 2-D lifts from one sieve of the kept pixels (no distinct count).
  std::vector<ColourSet> sets;
  if (n.hull3 || n.gcie) sets.push_back(ColourSet::hull_3d);
  if (n.gm2d) sets.push_back(ColourSet::hull);
  std::vector<ImageColours> colours = image_hull_sets(image, rules, kept, sets);
  if (n.hull3 || n.gcie) r.hull3 = std::move(colours.front().colours);
  if (n.gm2d) r.lifts = std::move(colours.back().colours);
  if (n.gm3d) r.top = largest_channels(image, rules.black_level, kept, r.hull3);
  if (n.order[0] || n.order[1]) {
    rules.colour_set = ColourSet::hull_3d;
    EdgeRules edges;
    edges.sigma = o.edge_sigma;
    edges.count_colours = false;  // only the hull's vertices are read
    if (n.order[0] && n.order[1]) {  // one sweep of the derivatives for both (the 2-jet)
      std::array<ImageColours, 2> both = edge_colours_both_orders(image, rules, edges);
      for (int k = 0; k < 2; ++k) r.edges[k] = std::move(both[k].colours);
    } else {
      edges.order = n.order[0] ? DerivativeOrder::first : DerivativeOrder::second;
      r.edges[n.order[0] ? 0 : 1] = edge_colours(image, rules, edges).colours;
    }
  }
  // The baselines together, sharing their sweeps of the pixels and of the derivatives; grey edge
  // at the run's derivative scale (the edge-based methods' σ).
  std::vector<std::size_t> asked;
  std::vector<GreyEdgeParameters> parameters;
  for (std::size_t b = 0; b < all_baselines.size(); ++b)
    if (n.baseline[b]) {
      GreyEdgeParameters p = baseline_parameters(all_baselines[b]);
      if (p.order != DerivativeOrder::zero) p.sigma = o.edge_sigma;
      asked.push_back(b), parameters.push_back(p);
    }
  const auto estimates = grey_edge_estimates(image, rules.black_level, kept.kept, parameters);
  for (std::size_t k = 0; k < asked.size(); ++k) r.baselines[asked[k]] = estimates[k];
  return r;
}

}  // namespace internal

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
    im.own = image_pixel_rules(r);
    if (!r.mask.empty()) im.mask_path = (std::filesystem::path(images_dir) / r.mask).string();
    images.push_back(std::move(im));
  }
  // The folds checked against the dataset: every image the folds file names is in it, and at least
  // two folds hold images (each fold's gamuts are learned from the others).
  std::set<std::string> names;
  std::set<int> used;
  for (const BenchmarkImage& im : images) {
    names.insert(im.name);
    used.insert(im.fold);
  }
  const std::string source = folds ? folds_path : "--folds";
  if (folds)
    for (const auto& [name, fold] : *folds)
      if (!names.count(name)) throw InputError(folds_path, 0, "image " + name + " is not in the dataset");
  if (used.size() < 2)
    throw InputError(source, 0, "every image is in one fold (" + std::to_string(images.size()) +
                                    " images): cross-validation needs images in at least 2 folds, each fold's "
                                    "gamuts learned from the others");
  return images;
}

}  // namespace gmcc
