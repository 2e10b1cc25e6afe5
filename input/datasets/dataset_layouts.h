#pragma once
// Colour-constancy datasets read as they ship, into the rows of a truth table
// (gmcc/input/truth_table.h; docs/photographs.md §6 "The benchmark"): each image's path relative
// to the dataset's folder, its measured light, its black level and saturation level, and the
// calibration chart to exclude. Used by `gmcc benchmark --layout` and the Python module; built as
// a library of its own (gmcc_datasets) because the NUS ground truth is MATLAB files, read with
// libmatio, which the installed libraries do not need.

#include <gmcc/input/truth_table.h>

#include <map>
#include <string>
#include <vector>

namespace gmcc {

/// One camera of the NUS 8-camera dataset (Cheng, Prasad & Brown, JOSA A 2014): the folder holds
/// `<camera>_gt.mat` — `all_image_names` (cell array of names), `groundtruth_illuminants` (N × 3),
/// `darkness_level` and `saturation_level` (scalars, raw codes) and `CC_coords` (N × 4: the chart's
/// box as rows y1, y2 and columns x1, x2) — and the images `<name>.PNG` (in the folder or its
/// `PNG/` subfolder). Each row: the image found, its light, black level = darkness_level,
/// saturation = saturation_level (pixels at or above it dropped), and the chart box as a polygon
/// widened by one pixel on every side (the box read either 0- or 1-based is inside it).
/// \throws InputError naming the file: no or several `*_gt.mat`, a variable missing or of the
/// wrong shape or type, a name without its image, a light channel <= 0.
std::vector<TruthRow> read_nus_camera(const std::string& dir);

/// Cube+ (Banić & Lončarić 2017): the folder holds `cube+_gt.txt` (one light "r g b" per line,
/// image k on line k) and the images `<k>.PNG` (in the folder or its `PNG/` subfolder). Each row:
/// the image, its light, black level 2048, saturation none (give `--saturation` or
/// `--bright-fraction`), and the SpyderCube's corner excluded: rows from 1050 and columns from
/// 2050 (0-based), to the image's edge.
/// \throws InputError naming the file and line.
std::vector<TruthRow> read_cube_plus(const std::string& dir);

/// Shi & Funt's re-processed Gehler–Shi set (568 linear PNGs of the Canon 5D and 1D): the folder
/// holds the images (`png/` or `images/`, taken in sorted name order), the lights
/// `real_illum_568.mat` (variable `real_rgb`, one row per image in that order; the name
/// `real_illum_568..mat` it is sometimes shipped under is accepted), the chart coordinates
/// `coordinates/<name>_macbeth.txt` (a line "width height" of the frame the coordinates are in,
/// whole numbers, then the chart's four corners "x y", in the order 1, 2, 4, 3 around it, read
/// exactly and scaled here to the image's size) and, optionally, the standard split
/// `threefoldCVsplit.mat` (`te_split`: three lists of 1-based image indices). Each PNG must be
/// its frame scaled by one factor to within a pixel on each axis (109 of the 568 frames are
/// portrait, and so are their PNGs). Black level as Shi's `description.txt` (shipped with the
/// lights) computes the ground truth: 129 for the Canon 5D images (names beginning `IMG`, images
/// 87-568), 0 for the Canon 1D's (`8D5U*`, images 1-86); no saturation level is assumed.
/// \returns the rows, and in `folds` each image's fold (0, 1, 2) from the split, empty without it.
/// \throws InputError naming the file: a coordinate file without its frame line (its first line
///         fractional: a corner, as in 22 files of the download, all for images outside the 568)
///         or with fewer than five lines, a PNG whose shape is not its frame's (rotated or
///         cropped), a MATLAB variable of the wrong shape, a light channel <= 0.
std::vector<TruthRow> read_gehler_shi(const std::string& dir, std::map<std::string, int>& folds);

/// The layouts read_dataset reads, as the command line names them: `nus`, `cube+`, `gehler-shi`.
std::vector<std::string> dataset_layout_names();

/// The dataset in `dir` as it ships in `layout` (one of dataset_layout_names): read_nus_camera,
/// read_cube_plus or read_gehler_shi, the split it ships (Gehler–Shi's) in `folds`.
/// \throws std::invalid_argument for another layout; InputError as the readers.
std::vector<TruthRow> read_dataset(const std::string& layout, const std::string& dir, std::map<std::string, int>& folds);

}  // namespace gmcc
