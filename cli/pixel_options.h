#pragma once
// The image pre-processing options shared by `gmcc estimate` and `gmcc canonical --from-images`
// (docs/conventions.md §8; docs/cli.md "gmcc estimate").

#include <gmcc/input/image_file.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/input/raw_file.h>
#include <gmcc/input/truth_table.h>
#include <gmcc/photo/image_rules.h>

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace gmcc::cli {

struct PixelOptions {
  std::string black_level = "0";
  std::string saturation = "max";  // max (2^bits - 1), none, or a value
  std::vector<std::string> exclude_polygons;
  std::string mask_path;
  std::string dark = "0";                 // absolute dark threshold, after the black level
  std::string dark_fraction, bright_fraction;  // of the image's largest value; empty: none
  std::string pixel_rule = "none";        // none | gijsenij
  std::string prefilter = "0";            // Gaussian pre-filter sigma, 0 for none
  std::string bin = "1";
  std::string colour_set = "hull";  // hull | distinct | hull-3d
  const CLI::App* command = nullptr;
};

/// Register the IMAGE... argument (PNG or TIFF files, linear RGB; required).
void add_images_argument(CLI::App& command, std::vector<std::string>& images);

/// Register --truths: a CSV with header image,r,g,b giving each image's true light; `use` ends
/// its help text (what the command does with them).
CLI::Option* add_truths_option(CLI::App& command, std::string& path, const std::string& use);

/// Register --black-level, --saturation, --exclude-polygon, --mask, --dark, --dark-fraction,
/// --bright-fraction, --pixel-rule, --bin, --colour-set.
void add_pixel_options(CLI::App& command, PixelOptions& options);

/// The rules those options give, checked (the mask image is read by image_colours_of).
/// \throws InputError naming the option.
struct PixelSettings {
  RunPixelRules run;  // the rules, --saturation max and whether --black-level was given
  std::optional<RgbImage> mask;
  std::string mask_path;
};
PixelSettings pixel_settings(const PixelOptions& options);

/// Read the image at `path` and apply the settings to it (the mask must have its size), with the
/// image's own rules from its truth-table row when given (black level, saturation, chart polygon,
/// and a mask image whose path is relative to the folder of `truths_path`). `raw_out`, when
/// given and the file is a camera raw file: what its reading used (read_camera_image).
/// \throws InputError naming the file.
ImageColours image_colours_of(const std::string& path, const PixelSettings& settings,
                              RgbImage* image_out = nullptr, PixelRules* rules_out = nullptr,
                              const TruthRow* row = nullptr, const std::string& truths_path = "",
                              RawImage* raw_out = nullptr);

}  // namespace gmcc::cli
