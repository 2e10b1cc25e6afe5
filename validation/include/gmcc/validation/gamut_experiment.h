#pragma once
/// \file gamut_experiment.h
/// The experiment of Finlayson & Hordley (1999) §4: scenes of n distinct surfaces under a test
/// light, the feasible set against a canonical gamut, the three selection rules, and their
/// angular errors against the true map, averaged over many seeded scenes for n = 1…11.

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/selection/mean_3d.h>
#include <gmcc/selection/rule.h>
#include <gmcc/selection/rule_3.h>
#include <gmcc/validation/error_statistics.h>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// A test light: every surface's colour under it, and the true perspective map that takes its
/// colours to the canonical ones (exact where the diagonal model holds exactly).
struct TestLight {
  std::string name;  ///< as in the reports (e.g. `D75`, or an image's name)
  std::vector<Colour> surfaces;  ///< surfaces[i]: surface i under this light
  Point2 true_map;  ///< (d1/d3, d2/d3) of true_diagonal_map, exact: what errors are measured against
  Point3 true_diagonal_map;      ///< d with d ⊙ p = p_canonical (its perspective is true_map)
  /// With ExperimentSetup::canonical_chromaticity_sets: the set whose hull is this light's
  /// canonical gamut (each test image its own, as in a leave-one-out protocol).
  std::size_t canonical = 0;
  /// The cell this light's scenes are summarised in, with other lights of the same group (e.g.
  /// every image of one camera); empty: the light's own name, one cell row per light.
  std::string group;
  /// The ids recorded in SceneRecord::drawn for surfaces[i] (e.g. chart patch numbers); empty:
  /// the indices i themselves.
  std::vector<std::uint32_t> surface_ids;
};

/// What an experiment is made of (built by synthetic_setup or camera_setup).
struct ExperimentSetup {
  std::string name;  ///< the experiment's name in reports (`synthetic`, `camera`, …)
  std::string figure;                      ///< the paper's figure it reproduces, for the reports
  std::vector<Colour> canonical_surfaces;  ///< the canonical gamut's colours
  Colour canonical_light;                  ///< the canonical light as the sensors see it
  std::vector<TestLight> lights;  ///< the test lights, in report order
  /// When not empty: canonical gamut k is the hull of canonical_chromaticity_sets[k] (exact
  /// perspective chromaticities), and light ℓ's scenes use set lights[ℓ].canonical; the
  /// canonical surfaces are then not used for the 2-D gamut (and CRULE is not available).
  std::vector<std::vector<Point2>> canonical_chromaticity_sets;
  /// A light with fewer surfaces than a cell's count n draws no scenes in that cell (real
  /// images with few usable patches) instead of the run being refused.
  bool skip_short_lights = false;
  /// Also score the reference baselines of experiment_baselines in every scene, the empty ones
  /// included: grey world (the mean of the scene's colours) and max-RGB (their per-channel
  /// maximum), each an illuminant estimate e turned into the map m = (c_r·e_b/(e_r·c_b),
  /// c_g·e_b/(e_g·c_b)) for the canonical light c.
  bool baselines = false;
  /// What SceneRecord::drawn holds, for the records' setup line ("0-based" surface indices, or
  /// e.g. "chart patch numbers 1-24" with TestLight::surface_ids).
  std::string surface_indices = "0-based";
};

/// How to run it.
struct ExperimentConfig {
  /// The surface counts n run, min_surfaces..max_surfaces inclusive (the paper: 1 to 11).
  ///@{
  int min_surfaces = 1, max_surfaces = 11;
  ///@}
  std::uint64_t scenes = 500;  ///< per light and surface count
  std::uint64_t seed = 1;  ///< the run's seed: scene (light, n, s) draws from a generator seeded by (seed, light, n, s)
  Expansion expansion;         ///< of the canonical gamut (default none)
  double noise = 0;            ///< relative Gaussian sensor noise σ on image colours (0: none)
  Mean3dOptions mean3d;        ///< the 3-D mean's route (default: certified closed form)
  /// Finlayson's (1996) illumination constraint: when given, each scene's F is intersected with
  /// these plausible maps (illumination_constraint of a set of lights) before selection.
  std::optional<ConvexSet2> constraint;
  /// Also Forsyth's 3-D CRULE (crule_3d: rules `crule_max_volume`, `crule_centroid`, scored by
  /// their perspective maps). Costly: the exact 3-D feasible set takes ~0.1–0.3 s per scene.
  bool crule = false;
  /// Intensity variation (shading): when > 0, each image surface's colour is scaled by its own
  /// factor drawn uniformly from [shading, 1]. Chromaticities, hence the 2-D rules, are unchanged;
  /// 3-D CRULE sees it (Barnard et al. 2002).
  double shading = 0;
  /// With crule: whether black is in CRULE's canonical gamut G_c3 (docs/math.md §1b). The
  /// default `include` is the record's historical setting; `exclude` is Forsyth's own gamut.
  CanonicalBlack crule_black = CanonicalBlack::include;
  /// With crule: also the selections `crule_max_trace` (max_trace.h) and `crule_cone_mean`
  /// (perspective_cone_mean.h), after max-volume and the centroid (docs/math.md §1c).
  bool crule_extended = false;
  /// Specular highlights (the dichromatic model, a neutral interface reflection): when > 0, each
  /// image surface gets s·e added, e = c ⊘ d the test light's colour (the white surface under it
  /// where the diagonal model holds; c the canonical light, d the true diagonal map) and s drawn
  /// per surface uniformly from [0, specular], after shading (docs/reproduction.md "Scene
  /// generator"). Changes chromaticities: the 2-D rules see it too.
  double specular = 0;
  /// Intensity change of the whole scene: when > 0, every image colour is multiplied by one
  /// factor per scene drawn uniformly between `intensity` and 1 (below 1: darker, above:
  /// brighter), after every per-surface draw, when the scene's colours are computed (with noise,
  /// crule or specular; otherwise no rule could see it). Chromaticities are unchanged, and a
  /// factor k scales CRULE's F3 by 1/k, so no rule's perspective map moves; the true map may
  /// leave F3 (docs/reproduction.md §5b).
  double intensity = 0;
  /// Score scenes by the certified floating-point route (certified_rule_errors.h) where it applies and
  /// certifies its angles (the default analytic 3-D mean, no constraint), else exactly. false:
  /// the exact route for every scene (for cross-checks; results agree within
  /// rule_errors_accuracy).
  bool certified_fast_route = true;
  unsigned threads = 0;        ///< worker threads (0: the hardware's); results do not depend on it
  /// Run only part `shard_index` (1-based) of `shard_count` disjoint parts: the scenes in
  /// canonical order (light, then surface count, then scene index) numbered g = 0, 1, …, T − 1,
  /// part K holds ⌊(K−1)·T/N⌋ ≤ g < ⌊K·T/N⌋ (docs/reproduction.md "Sharding"). A scene's
  /// result never depends on the sharding. The cells then summarise only the part's scenes.
  ///@{
  std::uint64_t shard_index = 1, shard_count = 1;
  ///@}
  /// Keep every scene's record in ExperimentResult::scenes (for --scenes-out and merging).
  bool keep_scenes = false;
  /// Called now and then from the calling thread with (scenes done, scenes in all).
  std::function<void(std::uint64_t, std::uint64_t)> progress;
};

/// The 3-D rules an experiment scores after the 2-D rules (all_rules, rule.h) when
/// ExperimentConfig::crule is set: CRULE's own, max-volume and the centroid (Forsyth 1990;
/// crule_3d.h), or with ExperimentConfig::crule_extended every 3-D rule (rule_3.h), in report
/// order; none without CRULE.
std::vector<Rule3> experiment_rules_3(const ExperimentConfig& config);
/// The names of the 3-D columns of a report: `crule_` and each rule's key (to_string, rule_3.h),
/// then with crule_extended the cone mean of F3's perspective image, `crule_cone_mean`
/// (perspective_cone_mean.h).
std::vector<std::string> experiment_rule_names_3d(const ExperimentConfig& config);
/// The most 3-D columns a report may have: every 3-D rule and the cone mean.
inline constexpr std::size_t max_experiment_rules_3d = rule_3_count + 1;
/// The reference baselines (ExperimentSetup::baselines), in report order.
inline const std::array<const char*, 2> experiment_baselines{"grey_world", "max_rgb"};

/// Statistics of one rule over the scenes of a cell that had a feasible map (error_statistics.h).
struct RuleStats {
  ErrorStatistics error;         ///< map-space angular error (the paper's), degrees
  ErrorStatistics worst_case;    ///< map space, the largest angle to any map of F
  ErrorStatistics illuminant;    ///< recovery (illuminant-space) error, over scenes with a positive map
  ErrorStatistics reproduction;  ///< Finlayson & Zakizadeh (2014), over scenes with a positive map
  /// Scenes in which the true map lay in F (always, for an exact noise-free experiment).
  std::uint64_t truth_in_feasible_set = 0;
};

/// One rule's result in one scene.
struct RuleRecord {
  bool scored = false;                ///< the rule gave a map; the members below are then set
  std::array<double, 2> map{};        ///< the perspective map (CRULE: (d1/d3, d2/d3)), as doubles
  /// Map-space angular error against the true map, and the worst case over F, degrees.
  ///@{
  double error_deg = 0, worst_case_deg = 0;
  ///@}
  bool positive_map = false;          ///< both components > 0: the next two are then set
  /// Illuminant-space (recovery) and reproduction angular errors, degrees.
  ///@{
  double illuminant_error_deg = 0, reproduction_error_deg = 0;
  ///@}
  bool truth_in_feasible_set = false; ///< CRULE: the true diagonal map in the 3-D feasible set
};

/// One scene: which surfaces were drawn and what every rule made of them.
struct SceneRecord {
  std::size_t light = 0;     ///< index into the setup's lights
  int surfaces = 0;          ///< n
  std::uint64_t scene = 0;   ///< s, 0-based within the (light, n) cell
  std::vector<std::uint32_t> drawn;  ///< 0-based surface indices (data file columns), in draw order
  ConvexKind kind = ConvexKind::empty;  ///< of F (F ∩ C with an illumination constraint)
  double area = 0;           ///< F's area as a double (0 unless a polygon)
  std::vector<RuleRecord> rules;  ///< in ExperimentResult::rules order; empty when F is empty
  /// With ExperimentSetup::baselines: in experiment_baselines order, in every scene (worst case
  /// and truth_in_feasible_set not meaningful: 0 and false).
  std::vector<RuleRecord> baselines;
};

/// One (light, surface count) cell.
struct ExperimentCell {
  std::string light;  ///< the light's name (or its group's, TestLight::group)
  int surfaces = 0;   ///< n, the number of distinct surfaces per scene
  std::uint64_t scenes = 0;        ///< drawn
  std::uint64_t empty = 0;         ///< of those, with an empty feasible set (no map)
  std::vector<RuleStats> rules;  ///< in ExperimentResult::rules order, over the non-empty scenes
  /// With baselines: in ExperimentResult::baselines order, over the same non-empty scenes as
  /// the rules (comparable with them) and over every scene of the cell.
  ///@{
  std::vector<RuleStats> baselines, baselines_all;
  ///@}
};

/// What run_gamut_experiment returns (and a merge of shards rebuilds): the setup's description,
/// the configuration, and the aggregates per cell, with every scene's record when kept.
struct ExperimentResult {
  std::string name;  ///< ExperimentSetup::name
  std::string figure;                 ///< ExperimentSetup::figure
  std::vector<std::string> lights;    ///< the test lights' names, in setup order
  ExperimentConfig config;  ///< the configuration it ran with (seed, counts, shard, …)
  ConvexSet2 canonical_gamut;  ///< G_c, exactly (after any expansion)
  std::vector<std::string> rules;     ///< to_string of all_rules, then experiment_rule_names_3d(config)
  std::vector<std::string> baselines; ///< experiment_baselines when the setup asks for them
  std::string surface_indices = "0-based";  ///< ExperimentSetup::surface_indices
  /// With canonical_chromaticity_sets: every set's gamut (canonical_gamut is then the first).
  std::vector<ConvexSet2> canonical_gamuts;
  /// Lights (or their groups, TestLight::group, in order of first appearance) in setup order,
  /// then surfaces ascending.
  std::vector<ExperimentCell> cells;
  /// With ExperimentConfig::keep_scenes: every scene run, in canonical order (light, n, s).
  std::vector<SceneRecord> scenes;
};

/// The cell of `light` and `n` summarised from its scenes' records (any order of scenes is
/// taken in ascending (light index, scene index)): the one aggregation used by
/// run_gamut_experiment and by a merge of shards. \param light the cell's light (or group) name;
/// \param n its surface count; \param scenes the records of its scenes (not owned);
/// \param rules the number of rules each
/// non-empty record carries; \param baselines the number of baselines every record carries.
ExperimentCell summarise_cell(const std::string& light, int n, std::vector<const SceneRecord*> scenes,
                              std::size_t rules, std::size_t baselines = 0);

/// Run the experiment. Scene (light ℓ, count n, index s) draws n distinct surfaces uniformly with
/// its own generator, std::mt19937_64 seeded by std::seed_seq of the six 32-bit words
/// {seed low, seed high, ℓ, n, s low, s high} (both fully specified by the C++ standard; the
/// draw is docs/reproduction.md "Scene generator"), so the result is identical for any thread
/// count, any sharding and on any platform.
/// \throws std::invalid_argument if a cell asks for more surfaces than there are.
ExperimentResult run_gamut_experiment(const ExperimentSetup& setup, const ExperimentConfig& config);

}  // namespace gmcc
