#pragma once
// Colour-constancy datasets read as they ship, into the rows of a truth table
// (gmcc/input/truth_table.h; docs/photographs.md §6 "The benchmark"): each image's path relative
// to the dataset's folder, its measured light, its black level and saturation level, and the
// calibration chart to exclude. Used by `gmcc benchmark --layout` and the Python module; built as
// a library of its own (gmcc_datasets) because the NUS ground truth is MATLAB files, read with
// libmatio, which the installed libraries do not need.

#include <gmcc/input/truth_table.h>

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

}  // namespace gmcc
