#pragma once
// `gmcc reproduce`: the experiments of Finlayson & Hordley (1999) §4 from spectral data
// (docs/reproduction.md): `synthetic` (Fig. 3), `camera` (a Fig. 5 analogue), `expansion`
// (the canonical-gamut expansion sensitivity table), `gehler-shi` (Fig. 5 on measured charts).

#include "output_files.h"

#include <gmcc/validation/gamut_experiment.h>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gmcc::cli {

struct ReproduceOptions {
  std::string data_dir;  // default: the shipped data/ (GMCC_DATA_DIR)
  std::string scenes = "500", seed = "1", max_surfaces = "11", threads = "0";
  std::string canonical;                 // default per experiment
  std::vector<std::string> lights;       // default per experiment
  std::string expand_factor = "0", expand_policy = "none";
  std::string noise = "0";
  std::string canonical_surfaces = "sfu1995";  // camera: sfu1995 | macbeth
  std::string mean3d_method = "analytic";
  std::string csv_path, plot_dir;
  std::string json_path;         // the aggregates as JSON
  std::string scenes_out_path;   // per-scene records, JSON Lines
  std::string shard;             // K/N: run only part K of N
  std::string illuminants_path;  // plausible lights for the illumination constraint
  bool crule = false;            // also 3-D CRULE
  std::string shading = "0";     // intensity variation: image colours scaled by U[shading, 1]
  std::string crule_black = "include";  // black in CRULE's canonical gamut: include | exclude
  bool crule_extended = false;   // also CRULE max-trace and the cone mean of F3's perspective image
  std::string specular = "0";    // highlights: + s·(light colour), s from U[0, specular] per surface
  std::string intensity = "0";   // whole-scene factor from U between intensity and 1 (0: none)
  // gehler-shi
  std::string gehler_scenes = "5";  // its own default --scenes: 568 images, not 4 lights
  std::string protocol = "leave-one-out";
  std::vector<std::string> cameras{"Canon1D", "Canon5D"};
  std::string dark = "0.002", clip = "0.95";
  std::vector<std::string> exclude_patches;  // patch numbers 1-24
};

/// Where an experiment's reports go (each optional; the table always goes to stdout).
struct ReportPaths {
  std::string csv, json, scenes_out, plot_dir;
};

/// The output files of an experiment's reports, opened at construction (before the work, so a
/// bad path is reported first) and written whole by write(). Shared by reproduce and merge.
class ExperimentOutputs {
 public:
  ExperimentOutputs(const ReportPaths& paths, const std::string& stem);
  /// Write every requested file and the table (stdout), then draw with gnuplot if --plot.
  /// `provenance` (a JSON object, docs/cli.md "Provenance") heads the CSV, JSON and records.
  /// Returns the exit status. `table`: false leaves the table (and the figure) to the caller.
  int write(const ExperimentResult& result, const std::string& provenance, bool table = true);

 private:
  ReportPaths paths_;
  std::string stem_;
  std::optional<PendingFile> csv_, json_, scenes_, dat_, gp_;
};

/// Register `reproduce` with its subcommands `synthetic`, `camera`, `expansion`, `gehler-shi`.
CLI::App* add_reproduce_command(CLI::App& app, ReproduceOptions& options);

/// Run whichever subcommand was given. Returns the exit status.
int run_reproduce(const CLI::App& reproduce, const ReproduceOptions& options);

}  // namespace gmcc::cli
