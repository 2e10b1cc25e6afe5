#pragma once
/// \file image_rules.h
/// The pixel rules that hold for one image: a run's rules (command line, Python, the benchmark's
/// options) composed with the image's own (a truth-table row or a dataset's files: black level,
/// saturation, chart polygon, mask image) and with the levels its reading found (a camera raw
/// file's metadata, camera_image.h). The one composition every front end calls
/// (docs/conventions.md §8, "Which rules hold for an image").

#include <gmcc/geometry/point.h>
#include <gmcc/input/camera_image.h>
#include <gmcc/input/image_file.h>
#include <gmcc/input/truth_table.h>
#include <gmcc/photo/image_pixels.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// A run's pixel rules as a front end parsed them, with the two choices that depend on the image.
struct RunPixelRules {
  PixelRules rules;  ///< the rules (black level and saturation as given, or their defaults)
  /// Without a saturation in `rules` or the image's own: drop pixels with a channel at the
  /// image's largest code, 2^bits − 1.
  bool saturation_max = false;
  /// `rules.black_level` was given: it replaces a camera raw file's own (raw_file.h), which is
  /// used otherwise.
  bool black_level_given = false;
};

/// One image's own rules, replacing or adding to the run's (a truth-table row, truth_table.h).
struct ImagePixelRules {
  /// The image's black level and saturation, replacing the run's.
  ///@{
  std::optional<std::uint32_t> black_level, saturation;
  ///@}
  std::vector<std::vector<Point2>> exclude_polygons;  ///< added to the run's (a chart's corners)
};

/// A truth-table row's own rules: its black level, saturation and chart polygon (its mask image,
/// a file, is the front end's to read).
ImagePixelRules image_pixel_rules(const TruthRow& row);

/// The levels to read the image with (read_camera_image): the image's own, else the run's
/// saturation and, when given, its black level.
ImageLevels levels_to_read(const RunPixelRules& run, const ImagePixelRules& own);

/// The rules that hold for `read` (read with levels_to_read(run, own)): the run's, with the
/// black level and saturation its reading found (saturation_max: 2^bits − 1 when neither the run
/// nor the image gave one), the image's polygons added, and `mask` (when given: nonzero keeps a
/// pixel) as the rules' `keep`.
/// \param run the run's rules. \param own the image's own. \param read the image as read.
/// \param path the image, named in messages. \param mask the mask image, or none.
/// \param mask_path the mask's file, named in messages.
/// \throws InputError naming the image when the mask's size is not the image's.
PixelRules rules_for_image(const RunPixelRules& run, const ImagePixelRules& own, const CameraImage& read,
                           const std::string& path, const RgbImage* mask = nullptr,
                           const std::string& mask_path = "");

}  // namespace gmcc
