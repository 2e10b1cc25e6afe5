#pragma once
// `gmcc estimate`: gamut mapping on linear camera images (PNG, TIFF), each image's pixels made
// into colours by explicit pre-processing (docs/conventions.md §8), then, against one canonical
// gamut, the select pipeline of gmcc/selection/select_scene.h (--space 2d) or 3-D gamut mapping
// on the pixel colours, gmcc/photo/estimate_3d.h (--space 3d) (docs/cli.md "gmcc estimate").

#include <CLI/CLI.hpp>

#include "pixel_options.h"

#include <string>
#include <vector>

namespace gmcc::cli {

struct EstimateOptions {
  std::string canonical_path;
  std::vector<std::string> images;
  PixelOptions pixels;
  std::string truth;                          // r,g,b of the true light (one image)
  std::string truths_path;                    // CSV image,r,g,b: each image's true light
  std::string canonical_illuminant = "1,1,1";
  std::string expand_policy = "none";
  std::string expand_factor = "0";
  std::string on_empty = "none";
  std::string illuminant_worst_case = "on";
  std::string illuminants_path;               // plausible lights, r,g,b per line (the constraint)
  bool json = false;
  std::string corrected_dir;
  std::string space = "2d";            // 2d: the perspective route; 3d: CRULE on pixel colours
  std::vector<std::string> rules_3d;   // 3d: which rules (default all)
  std::string black = "include";       // 3d: whether black joins the canonical gamut
  std::string centroid = "certified";  // 3d: the centroid certified or exact
};

/// Register the subcommand and its options on `app`; returns the subcommand.
CLI::App* add_estimate_command(CLI::App& app, EstimateOptions& options);

/// Run it: the report on stdout, corrected images into --corrected DIR. \throws InputError.
int run_estimate(const EstimateOptions& options);

}  // namespace gmcc::cli
