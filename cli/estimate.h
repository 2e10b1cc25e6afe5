#pragma once
// `gmcc estimate`: gamut mapping on linear camera images (PNG, TIFF), each image's pixels made
// into colours by explicit pre-processing (docs/conventions.md §8), then the select pipeline of
// gmcc/selection/select_scene.h against one canonical gamut (docs/cli.md "gmcc estimate").

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
  bool json = false;
  std::string corrected_dir;
};

/// Register the subcommand and its options on `app`; returns the subcommand.
CLI::App* add_estimate_command(CLI::App& app, EstimateOptions& options);

/// Run it: the report on stdout, corrected images into --corrected DIR. \throws InputError.
int run_estimate(const EstimateOptions& options);

}  // namespace gmcc::cli
