#pragma once
/// \file gehler_shi.h
/// Reading the measured chart colours of the Gehler–Shi set (data/SOURCES.md,
/// "Added for the real-camera experiment"): for each of its 568 images, the
/// mean linear camera RGB of the 24 ColorChecker patches and the ground-truth
/// illuminant of Hemrit et al. (2018), numbers read exactly. The real-data test
/// of Finlayson & Hordley (1999) §4 (their Fig. 5) uses a chart imaged under
/// several lights in the same way.

#include <gmcc/geometry/colour.h>
#include <gmcc/input/input_error.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// Patches on a ColorChecker chart, numbered 1–24 in the standard order (19
/// white … 24 black).
inline constexpr std::size_t chart_patches = 24;

/// One image: its chart's patch colours and its light.
struct ChartImage {
  std::size_t index = 0;  ///< 1-based, as in the data files
  std::string name;       ///< "8D5U5524", "IMG_0301"
  std::string camera;     ///< "Canon1D" or "Canon5D"
  Colour truth;           ///< ground-truth illuminant RGB (the recommended one: r + g + b
                          ///< = 1)
  /// Patch k + 1's mean camera RGB; empty where the data has none (NaN
  /// upstream).
  std::array<std::optional<Colour>, chart_patches> patches;
};

/// The whole set, in the order of the ground-truth file.
struct ChartDataset {
  std::vector<ChartImage> images;  ///< one per image, in the ground-truth file's order
  std::size_t missing_patches = 0;  ///< patches with no colour, over every image
};

/// Parse the two files' text. `truth_text`: header
/// `index,image,camera,shi_real_rgb_r,
/// shi_real_rgb_g,shi_real_rgb_b,rec2018_r,rec2018_g,rec2018_b`, one row per
/// image, indices 1, 2, 3, … in order, names unique, camera `Canon1D` or
/// `Canon5D`, the rec2018 channels > 0. `patches_text`: header
/// `index,image,patch,r,g,b`, one row per patch, whose index and image must
/// name an image of the truth file; patch 1–24, each at most once per image;
/// channels >= 0, or all three `NaN` (case-insensitive) for a patch with no
/// measurement, which is counted as missing like a patch with no row (the data
/// is known to lack 29 patches). \throws InputError naming the file and line: a
/// wrong header or column count, a malformed,
///         negative or (for the light) non-positive number, an index out of
///         order, an image in the patch file that the truth file lacks (or
///         under another name), a patch number out of range or repeated, a NaN
///         in some channels only.
ChartDataset parse_gehler_shi(const std::string& patches_text, const std::string& patches_file,
                              const std::string& truth_text, const std::string& truth_file);

/// Read and parse the two files (read_text_file, then parse_gehler_shi).
/// \throws InputError as parse_gehler_shi, or if a file cannot be read.
ChartDataset read_gehler_shi(const std::string& patches_path, const std::string& truth_path);

}  // namespace gmcc
