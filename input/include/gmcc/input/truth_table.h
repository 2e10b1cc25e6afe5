#pragma once
/// \file truth_table.h
/// A dataset's truth table (docs/photographs.md §6, `gmcc benchmark --truths`): one line per
/// image, in the dataset's order, with its measured light and, optionally, its own pixel rules.
///
///   image,r,g,b[,black_level][,saturation][,mask][,chart]
///
/// `image` is the file's path relative to the image folder; r, g, b the light (read exactly,
/// > 0); the optional columns, named in the header in any order after b: `black_level` and
/// `saturation` (integers 0 to 65535, empty for the run's), `mask` (a mask image's path relative
/// to the image folder, 0 excluded) and `chart` (a polygon to exclude, "x1 y1 x2 y2 x3 y3 …" in
/// pixel coordinates, read exactly). Blank lines and `#` lines are skipped; a UTF-8 byte-order
/// mark and CRLF line ends are accepted.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>
#include <gmcc/input/input_error.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// One image's line.
struct TruthRow {
  std::string image;  ///< the image's path relative to the image folder
  Colour light;       ///< its measured light, every channel > 0
  /// its own black level and saturation, when given
  ///@{
  std::optional<std::uint32_t> black_level, saturation;
  ///@}
  std::string mask;            ///< a mask image (relative path), empty for none
  std::vector<Point2> chart;   ///< a polygon to exclude, empty for none
  std::size_t line = 0;        ///< the 1-based line it came from
};

/// Read a truth table. \throws InputError naming the file and line: a header without image,r,g,b
/// first or with an unknown or repeated column, a wrong number of fields, a bad number, a light
/// channel <= 0, an image listed twice, a chart of fewer than 3 points, no image at all.
std::vector<TruthRow> read_truth_table(const std::string& path);

/// The rows by image name (the `image` column).
std::map<std::string, TruthRow> truth_rows_by_image(std::vector<TruthRow> rows);

/// The row of the image at `image_path`: the line naming it as given, else by its file name.
/// \throws InputError naming the truth file and the image when there is none.
const TruthRow& truth_of_image(const std::map<std::string, TruthRow>& rows, const std::string& image_path,
                               const std::string& truths_path);

/// A benchmark's table: refuses an `image` or `mask` path that is absolute or has a `..`
/// component, since the benchmark reads every image under its `--images` folder only.
/// \throws InputError naming the table and the line.
void require_paths_under_folder(const std::vector<TruthRow>& rows, const std::string& table_path);

/// Read a folds file `image,fold` (fold an integer >= 0) as a map from image to fold.
/// \throws InputError naming the file and line.
std::map<std::string, int> read_folds_file(const std::string& path);

}  // namespace gmcc
