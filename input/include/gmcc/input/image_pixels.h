#pragma once
/// \file image_pixels.h
/// From a linear camera image to the colours gmcc's geometry takes
/// (docs/conventions.md §8), each step explicit and exact, in this order for every pixel:
///   1. a mask excludes pixels (a polygon such as a calibration chart's corners, and/or a
///      mask image);
///   2. saturation: a pixel with any channel at or above the threshold (raw value, before the
///      black level) is dropped, since its true colour is unknown;
///   3. black level: subtracted from every channel, negative results clamped to 0;
///   4. binning (optional): the kept pixels of each b×b block are averaged, exactly, into one
///      colour;
///   5. the distinct colours are returned (their convex hull is what the gamut method uses, so
///      repeated colours add nothing) or, with ColourSet::hull, only those whose perspective
///      chromaticities are vertices of the exact chromaticity hull (chromaticity_hull.h), which
///      is all the 2-D feasible set depends on: a 10-megapixel image then costs the geometry a
///      few dozen colours.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>
#include <gmcc/input/image_file.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace gmcc {

/// How pixels become colours.
/// What step 5 returns.
enum class ColourSet {
  distinct,  ///< every distinct colour, in increasing (r, g, b) order
  hull,      ///< without binning: one colour (x, y, 1) per vertex of the hull of the
             ///< chromaticities (x, y) = (r/b, g/b), counter-clockwise (b = 0 has none)
};

/// Which pixels become colours, and how (docs/conventions.md §8; `gmcc estimate`'s options).
struct PixelRules {
  std::uint32_t black_level = 0;            ///< subtracted from every channel
  std::optional<std::uint32_t> saturation;  ///< drop pixels with a raw channel >= this
  /// Polygons to exclude, in pixel coordinates: x to the right, y down, pixel
  /// (i, j) the unit square [i, i+1) × [j, j+1) with its centre at (i + ½, j +
  /// ½). A pixel whose centre lies inside a polygon or on its boundary
  /// (even–odd rule; exact arithmetic) is excluded.
  std::vector<std::vector<Point2>> exclude_polygons;
  /// Per pixel (row-major, width · height), false to exclude; empty for none.
  std::vector<bool> keep;
  std::uint32_t bin = 1;  ///< block size b for binning; 1: every kept pixel is a colour
  /// With bin > 1 the binned colours are always returned as ColourSet::distinct.
  ColourSet colour_set = ColourSet::distinct;
};

/// What happened to the pixels, each counted once, in the order of the steps.
struct PixelCounts {
  std::uint64_t pixels = 0;     ///< width · height
  std::uint64_t masked = 0;     ///< excluded by a polygon or the mask image
  std::uint64_t saturated = 0;  ///< of the rest, dropped for a channel >= saturation
  std::uint64_t kept = 0;       ///< the rest
  std::uint64_t colours = 0;    ///< distinct colours (after binning)
  std::uint64_t hull_vertices = 0;    ///< ColourSet::hull: vertices returned
  std::uint64_t no_chromaticity = 0;  ///< ColourSet::hull: distinct colours with b = 0
};

/// What image_colours returns: the colours for the geometry and how each pixel was accounted for.
struct ImageColours {
  std::vector<Colour> colours;  ///< distinct, in order of first appearance (row-major)
  PixelCounts counts;  ///< what happened to the pixels
};

/// Apply the rules to `image`.
/// \throws std::length_error for ColourSet::distinct with more than max_colours (colour_csv.h)
///         distinct colours; std::invalid_argument if bin is 0, `keep` is neither empty nor width
/// · height long, or
///         a polygon has fewer than 3 vertices.
ImageColours image_colours(const RgbImage& image, const PixelRules& rules);

/// A linear camera image of floating-point samples (as a Python or MATLAB reader returns it):
/// width · height pixels, row-major, three channels each. Every double is an exact rational.
struct FloatRgbImage {
  std::size_t width = 0;   ///< pixels per row
  std::size_t height = 0;  ///< rows
  std::vector<double> samples;  ///< width · height · 3
};

/// The pixel rules of a floating-point image: `keep` (steps 1), saturation (2) and black level
/// (3) as for integer images; no binning, and always ColourSet::hull (the colours are
/// (x, y, 1) for the hull's vertices, counter-clockwise).
struct FloatPixelRules {
  double black_level = 0;            ///< subtracted from every channel (>= 0, finite)
  std::optional<double> saturation;  ///< drop pixels with a raw channel >= this
  std::vector<bool> keep;            ///< per pixel (row-major), false to exclude; empty for none
};

/// Apply the rules to a floating-point image, exactly: each v − black_level must be exact in
/// double (it is for float32 data and whenever v <= 2·black_level; Sterbenz), checked by an
/// error-free transformation (Knuth's TwoSum), so the hull is that of the exact differences;
/// a channel at or below the black level becomes 0. The hull is chromaticity_hull's (exact).
/// counts.colours is the number of distinct kept colours.
/// \throws std::invalid_argument naming the pixel (row, column) and channel for a NaN, an
///         infinity or a negative sample, a subtraction that is not exact, a black level or
///         saturation that is negative or not finite, or a `keep` of the wrong size.
ImageColours image_colours(const FloatRgbImage& image, const FloatPixelRules& rules);

/// The pixels a polygon excludes, row-major (true: centre inside or on the
/// boundary). Exposed for tests and reports.
std::vector<bool> polygon_cover(const std::vector<Point2>& polygon, std::size_t width,
                                std::size_t height);

}  // namespace gmcc
