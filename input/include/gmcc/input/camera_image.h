#pragma once
/// \file camera_image.h
/// One entry for every camera image a command reads: a PNG or TIFF as stored (image_file.h), or
/// a camera raw file reduced to quads (raw_file.h), with the pixel rules' black level and
/// saturation set to match (docs/conventions.md §8).

#include <gmcc/input/image_file.h>
#include <gmcc/input/image_pixels.h>
#include <gmcc/input/raw_file.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// The black level and saturation a user gave for an image (command line, truth table, Python);
/// absent: for a raw file its own metadata, for a PNG or TIFF what `rules` already holds.
struct ImageLevels {
  std::optional<std::uint32_t> black;       ///< the black level
  std::optional<std::uint32_t> saturation;  ///< the saturation threshold (a raw file: its white level)
};

/// Read the camera image at `path`. A raw file (is_raw_file_name, or by its content
/// is_raw_file_content: a TIFF of CFA data under any name) is read by decode_raw_image with
/// `levels` replacing its metadata; the returned pixels have the black level subtracted, so
/// `rules.black_level` becomes 0 and `rules.saturation` raw_saturated_value. Any other file is
/// read by decode_image, and `levels` that are present replace `rules`' black level and saturation.
/// \param path the image file. \param levels the black level and saturation given for it.
/// \param rules the pixel rules whose black level and saturation are set for the image.
/// \param raw_metadata when given and the file is raw: what read_raw_image read besides the
///        pixels (pattern, levels, camera, saturated quads; its `image` is left empty).
/// \throws InputError naming the file, as read_image and read_raw_image.
RgbImage read_camera_image(const std::string& path, const ImageLevels& levels, PixelRules& rules,
                           RawImage* raw_metadata = nullptr);

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
