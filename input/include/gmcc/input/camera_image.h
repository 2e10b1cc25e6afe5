#pragma once
/// \file camera_image.h
/// One entry for every camera image a command reads: a PNG or TIFF as stored (image_file.h), or
/// a camera raw file reduced to quads (raw_file.h), with the black level and saturation that hold
/// for its pixels (docs/conventions.md §8). What the pixel rules make of them is gmcc::photo's
/// (image_rules.h).

#include <gmcc/input/image_file.h>
#include <gmcc/input/raw_file.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// The black level and saturation a user gave for an image (command line, truth table, Python);
/// absent: for a raw file its own metadata, for a PNG or TIFF the run's.
struct ImageLevels {
  std::optional<std::uint32_t> black;       ///< the black level
  std::optional<std::uint32_t> saturation;  ///< the saturation threshold (a raw file: its white level)
  /// A PNG or TIFF's black level when `black` is absent (the run's default, recorded as "run").
  std::uint32_t run_black = 0;
};

/// A camera image as read, with the levels that hold for its pixels.
struct CameraImage {
  RgbImage image;  ///< the pixels (a raw file's with its black level subtracted)
  /// What to subtract from `image`: 0 for a raw file (subtracted when read), else ImageLevels'
  /// `black` or, absent, `run_black`.
  std::uint32_t black_level = 0;
  /// Where a channel counts as saturated: raw_saturated_value for a raw file, else ImageLevels'
  /// `saturation`; absent: the run's rule decides (image_rules.h).
  std::optional<std::uint32_t> saturation;
  /// A raw file's metadata (pattern, levels, camera, saturated quads; its `image` empty); for a
  /// PNG or TIFF, default (an empty pattern).
  RawImage raw;
};

/// Read the camera image at `path`. A raw file (is_raw_file_name, or by its content
/// is_raw_file_content: a TIFF of CFA data under any name) is read by decode_raw_image with
/// `levels` replacing its metadata; any other file by decode_image, with `levels` as given.
/// The levels used are recorded for the provenance (image_levels_used).
/// \param path the image file. \param levels the black level and saturation given for it.
/// \throws InputError naming the file, as read_image and read_raw_image.
CameraImage read_camera_image(const std::string& path, const ImageLevels& levels);

/// The levels read_camera_image used for one image, for the provenance every output records
/// (docs/cli.md "Provenance"): what was subtracted and where pixels count as saturated, which a
/// dataset's own files or a raw file's metadata may have set rather than the command line.
struct ImageLevelsUsed {
  std::string path;                         ///< the image as given
  std::vector<std::uint32_t> black;         ///< one level, or a raw file's four (its pattern's order)
  std::optional<std::uint32_t> saturation;  ///< a raw file's white level, or the level given; none: the run's rule
  std::string black_from;       ///< "file" (raw metadata), "given" (command line, truth table, dataset file) or "run"
  std::string saturation_from;  ///< the same, "run" meaning the run's --saturation max or none
};

/// Every image read_camera_image has read in this process, each once, in the order first read.
/// Thread-safe.
std::vector<ImageLevelsUsed> image_levels_used();

}  // namespace gmcc
