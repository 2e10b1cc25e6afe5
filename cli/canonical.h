#pragma once
// `gmcc canonical --from-images`: a canonical gamut learned from linear camera images with known
// lights (docs/cli.md "gmcc canonical"): each image's pixels, pre-processed as by
// `gmcc estimate`, divided by the image's true light, so that the canonical light is white; the
// hull of their chromaticities (2-D, perspective) or of the colours themselves (3-D, each image
// scaled as --intensity says), learned image by image (gmcc/photo/learn_canonical.h).

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "pixel_options.h"

namespace gmcc::cli {

struct CanonicalOptions {
  bool from_images = false;
  std::vector<std::string> images;
  std::string truths_path;  // CSV image,r,g,b
  std::string out_path;     // default: stdout
  std::string space = "2d";  // 2d: chromaticities (lifts); 3d: pixel colours
  std::string intensity = "max";  // 3d: how each image is scaled (CanonicalIntensity)
  PixelOptions pixels;
};

/// Register the subcommand and its options on `app`; returns the subcommand.
CLI::App* add_canonical_command(CLI::App& app, CanonicalOptions& options);

/// Run it. \throws InputError.
int run_canonical(const CanonicalOptions& options);

}  // namespace gmcc::cli
