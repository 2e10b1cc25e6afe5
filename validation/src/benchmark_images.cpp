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
      if (m == gm3d_method(rule)) n.gm3d = n.gamut3 = n.rule3[rule] = known = true;
    for (Rule rule : all_rules)
      if (m == gm2d_method(rule)) n.gm2d = n.rule2[rule] = known = true;
    for (Rule3 rule : all_rules_3)
      if (m == gm3d_constrained_method(rule)) n.gm3d = n.gamut3 = n.rule3c[rule] = known = true;
    for (Rule rule : all_rules)
      if (m == gm2d_constrained_method(rule)) n.gm2d = n.gm2dc = n.rule2c[rule] = known = true;
    if (m == kGcie) n.gcie = known = true;
    // An edge-based method needs the pixel colours too: their scale is its edge colours' scale;
    // the pixel canonical gamut only when it intersects the pixel feasible set (the n-jets).
    for (int k = 0; k < 4; ++k)
      if (m == kEdge[k]) {
        n.gm3d = n.edge[k] = known = true;
        n.gamut3 = n.gamut3 || kEdgeTypes[k][0];
        for (int o = 0; o < 2; ++o) n.order[o] = n.order[o] || kEdgeTypes[k][o + 1];
      }
    for (std::size_t b = 0; b < all_baselines.size() && !known; ++b)
      if (m == baseline_method(b)) n.baseline[b] = known = true;
    if (!known) throw std::invalid_argument("unknown benchmark method \"" + m + "\"");
  }
  return n;
}

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
  if (n.gm3d || n.gcie) sets.push_back(ColourSet::hull_3d);
  if (n.gm2d) sets.push_back(ColourSet::hull);
  std::vector<ImageColours> colours = image_hull_sets(image, rules, kept, sets);
  if (n.gm3d || n.gcie) r.hull3 = std::move(colours.front().colours);
  if (n.gm2d) r.lifts = std::move(colours.back().colours);
  for (int k = 0; k < 2; ++k)
    if (n.order[k]) {
      rules.colour_set = ColourSet::hull_3d;
      EdgeRules edges;
      edges.order = k == 0 ? DerivativeOrder::first : DerivativeOrder::second;
      edges.sigma = o.edge_sigma;
      r.edges[k] = edge_colours(image, rules, edges).colours;
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
