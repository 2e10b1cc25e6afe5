#pragma once
/// \file benchmark.h
/// A colour-constancy dataset benchmark (docs/photographs.md §6 "The benchmark"): every image
/// estimated by a canonical gamut learned only from the images of the other cross-validation
/// folds, by every gamut-mapping method (3-D pixel gamut mapping with max-trace, max-volume and
/// centroid; the 2-D perspective route with max-area, 2-D mean and 3-D mean) and by the field's
/// statistical baselines (grey world, white patch, shades of grey, 1st- and 2nd-order grey edge,
/// grey_edge.h), all on exactly the pixels the pixel rules keep; the recovery angular error
/// against the measured light, and the statistics papers report (Hordley & Finlayson 2006:
/// mean, median, trimean, best and worst 25%). Every estimate of a gamut method comes with its
/// feasible set, so the benchmark also says how often the true light lies in it and how well the
/// certified worst case predicts the error.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/input/truth_table.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/photo/image_rules.h>
#include <gmcc/photo/learn_canonical.h>
#include <gmcc/validation/error_statistics.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// One image of a dataset: its file, measured light, fold and any per-image pixel rules.
struct BenchmarkImage {
  std::string name;  ///< as the truth file names it (reports use it)
  std::string path;  ///< the PNG, TIFF or camera raw file to read (camera_image.h)
  Colour light;      ///< the measured light, every channel > 0
  int fold = 0;      ///< its cross-validation fold, >= 0
  /// Per-image pixel rules replacing or adding to the run's (a dataset's black level or
  /// saturation per camera or image; a chart polygon; image_rules.h).
  ImagePixelRules own;
  std::string mask_path;  ///< a mask image of the same size, 0 excluded; empty for none
};

/// A dataset's images from its truth table (truth_table.h): each image's path under
/// `images_dir`, its light, its own pixel rules, and its fold — from `folds` (image → fold, a
/// dataset's own split) when given, else the data line's index modulo `k` (k >= 2).
/// \throws InputError naming `folds_path` when an image has no fold; std::invalid_argument for
/// k < 2 without folds.
std::vector<BenchmarkImage> benchmark_dataset(const std::string& images_dir, const std::vector<TruthRow>& rows,
                                              const std::map<std::string, int>* folds, const std::string& folds_path,
                                              int k);

/// The methods, by name: `gm3d-max-trace`, `gm3d-max-volume`, `gm3d-centroid`, `gm2d-max-area`,
/// `gm2d-mean-2d`, `gm2d-mean-3d`, `grey-world`, `white-patch`, `shades-of-grey`,
/// `grey-edge-1`, `grey-edge-2`, then the edge-based gamut methods of Gijsenij, Gevers & van de
/// Weijer (2010 §4), each with max-trace: `gm3d-edge1-max-trace` (the gamut of 1st-order
/// derivative magnitudes), `gm3d-edge2-max-trace` (2nd order), `gm3d-1jet-max-trace` (the
/// intersection of the pixel and 1st-order feasible sets), `gm3d-2jet-max-trace` (pixel, 1st and
/// 2nd order), in that order (docs/photographs.md §5); then the six gamut rules with the
/// illumination constraint learned per fold (the training images' lights as the plausible lights,
/// never the test fold's): `gm3d-max-trace-constrained`, `gm3d-max-volume-constrained`,
/// `gm3d-centroid-constrained` (F3 ∩ the cone of their maps, Barnard's ECRULE,
/// illumination_cone_3d.h), `gm2d-max-area-constrained`, `gm2d-mean-2d-constrained`,
/// `gm2d-mean-3d-constrained` (F ∩ the hull of their perspective maps, Finlayson 1996 §5).
const std::vector<std::string>& benchmark_methods();

/// The methods a run takes when none are named: the first eleven of benchmark_methods() (every
/// pixel gamut method and baseline; the edge-based and constrained methods are asked for by name).
const std::vector<std::string>& default_benchmark_methods();

/// Whether `method` is a gamut-mapping method (`gm3d-…`, `gm2d-…`): it has a feasible set, an
/// empty count and a fallback.
inline bool is_gamut_method(const std::string& method) { return method.rfind("gm", 0) == 0; }

/// Whether `method` is one of the edge-based gamut methods (`gm3d-edge1-max-trace`, …,
/// `gm3d-2jet-max-trace`): it takes the image's derivatives, so no pre-filter.
bool is_edge_gamut_method(const std::string& method);

/// How the benchmark runs.
struct BenchmarkOptions {
  std::vector<std::string> methods = default_benchmark_methods();  ///< a subset, in any order
  /// The run's pixel rules (colour_set and bin are set per method), with `saturation_max` (what
  /// `gmcc estimate --saturation max` does) and whether the black level was given
  /// (image_rules.h).
  RunPixelRules pixels;
  CanonicalIntensity intensity = CanonicalIntensity::max;  ///< 3-D learning (learn_canonical.h)
  CanonicalBlack black = CanonicalBlack::include;          ///< 3-D canonical gamut with black
  /// The derivative scale σ, in pixels, in (0, 64], of the edge-based methods (edge_colours.h; the
  /// neighbourhood rule is its default) and of the grey-edge baselines (grey_edge.h), so that the
  /// two families see the same derivatives. The edge colours are scaled by the same factor as the
  /// image's pixel colours, so that every gamut type shares one intensity scale.
  double edge_sigma = 1;
  unsigned threads = 0;  ///< worker threads; 0: the machine's cores
  /// Shard K of N: only the images whose index i has i mod N = K − 1 are estimated (every image
  /// is still read and reduced: the canonical gamuts need them all). 1 of 1: the whole run.
  ///@{
  std::size_t shard_index = 1, shard_count = 1;
  ///@}
  /// Called from the calling thread now and then: images done, images in all.
  std::function<void(std::size_t, std::size_t)> progress;
};

/// One image under one method.
struct BenchmarkRecord {
  std::size_t image = 0;  ///< index into the images given
  std::string method;     ///< its name (benchmark_methods())
  /// The light estimated, unit length: the method's own, or grey world's when it gave none
  /// (`fallback`); absent when neither gave one.
  std::optional<std::array<double, 3>> light;
  std::optional<double> error_deg;  ///< recovery angular error against the measured light
  bool answered = false;            ///< the method itself gave the light
  std::string fallback;             ///< "grey_world" when the light is grey world's, else empty
  /// Why the method gave no light of its own (empty when `answered`): gamut methods `empty` (F
  /// empty), `no_positive_map` (F holds maps, the rule's has a zero component: no light),
  /// `unbounded` (every kept colour of a type has a zero channel), `no_colours` (no kept colour,
  /// or none of an edge type, in the image or in the fold's training images); baselines
  /// `no_light` (nothing to average: a black or constant image).
  std::string unanswered;
  /// Gamut methods: the feasible set's kind and vertex count (empty kind: no feasible set was
  /// formed, `unanswered` says why); whether the true light's map lies in it, decided exactly
  /// (2-D: the true perspective map in F; 3-D: some positive multiple of c ⊘ e in F3, on F3's
  /// rows, feasible_ray_3d.h), absent without a feasible set; the rule's certified worst case in
  /// degrees and the space it bounds (`illuminant` in 2-D, `map` in 3-D and in 2-D where F or the
  /// map touches an axis), with the answer's error in that same space, computed from the same
  /// exact maps as the worst case (map: the angle between the rule's map and c ⊘ e; illuminant:
  /// between their lights), absent when the method did not answer. Whenever the truth is in F,
  /// that error is at most the worst case.
  ///@{
  std::string feasible_kind;
  std::size_t feasible_vertices = 0;
  std::optional<bool> truth_in_feasible;
  std::optional<double> worst_case_deg;
  std::string worst_case_space;
  std::optional<double> worst_case_space_error_deg;
  ///@}
};

/// One method over the dataset.
struct BenchmarkSummary {
  std::string method;        ///< its name
  std::size_t images = 0;    ///< estimated (every image of the dataset)
  std::size_t answered = 0;  ///< answered by the method itself
  std::size_t empty = 0;     ///< gamut methods: F empty, or no positive map (then grey world)
  /// Gamut methods: no feasible set formed (no colour of a type it needs, or an unbounded F3);
  /// baselines: no light. Every method's answered + empty + unanswered_other = images.
  std::size_t unanswered_other = 0;
  ErrorStatistics errors;    ///< over every image with a light (answered or fallback)
  /// Gamut methods: images whose true light lies in F (decided exactly, of every image); the
  /// share of answered images whose error in the worst case's own space (BenchmarkRecord::
  /// worst_case_space_error_deg) is at most the worst case; the Spearman rank correlation of
  /// worst case and that error over them (absent with fewer than 3).
  ///@{
  std::size_t truth_in_feasible = 0;
  std::optional<double> worst_case_covers, worst_case_correlation;
  ///@}
};

/// The whole run: records image-major (every method of image 0, then image 1, …) and one summary
/// per method, in the order asked.
struct BenchmarkResult {
  std::vector<BenchmarkRecord> records;     ///< image-major, methods in the order asked
  std::vector<BenchmarkSummary> summaries;  ///< one per method, in the order asked
};

/// Run the benchmark. Images are read and reduced to what the methods need (the pixel colours
/// on their 3-D hull, the chromaticity lifts of their 2-D hull, the baselines' estimates) in
/// parallel, a few at a time; per fold, the canonical gamuts are learned from the other folds'
/// reduced images and the fold's images estimated in parallel. Deterministic: the same inputs
/// give the same records whatever the threads.
/// An edge-based method's image with no edge colour of a type it needs (no kept pixel whose
/// neighbourhood is kept), or a fold whose training images have none, has no feasible set: it
/// takes grey world's light, like an empty one, but has no feasible kind.
/// \throws InputError (a file: unreadable, not an image, a mask of the wrong size, no usable
///         pixel); std::invalid_argument (an unknown method, no image, a fold with no training
///         image, an edge-based method with binning or a pre-filter in the pixel rules, or
///         edge_sigma outside (0, 64]).
BenchmarkResult run_benchmark(const std::vector<BenchmarkImage>& images, const BenchmarkOptions& options);

/// The summaries of some records (of `methods`, over `images` images): what run_benchmark
/// reports, recomputed from records (merged shards, a subset). O(records log records).
std::vector<BenchmarkSummary> summarise_benchmark(const std::vector<BenchmarkRecord>& records,
                                                  const std::vector<std::string>& methods);

}  // namespace gmcc
