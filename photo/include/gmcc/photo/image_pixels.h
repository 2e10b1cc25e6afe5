#pragma once
/// \file image_pixels.h
/// From a linear camera image to the colours gmcc's geometry takes
/// (docs/conventions.md §8), each step explicit and exact, in this order for every pixel:
///   1. a mask excludes pixels (a polygon such as a calibration chart's corners, and/or a
///      mask image);
///   2. saturation: a pixel with any channel at or above the threshold (raw value, before the
///      black level) is dropped, since its true colour is unknown;
///   3. black level: subtracted from every channel, negative results clamped to 0;
///   4. dark pixels: a pixel with a channel below an absolute threshold, or below a fraction of
///      the image's largest value M, is dropped (noise dominates its ratios); too bright: a
///      pixel with a channel above a fraction of M is dropped (a margin below clipping). M is
///      the largest channel, after the black level, of the pixels step 1 keeps. Gijsenij,
///      Gevers & van de Weijer (2010)'s rule is the preset gijsenij_pixel_rules(): the image
///      rescaled to a maximum of 255, a channel below 5 or above 245 dropped;
///   5. binning (optional): the kept pixels of each b×b block are averaged, exactly, into one
///      colour;
///   6. the colours passed on (ColourSet): every distinct colour, in increasing (r, g, b) order
///      (their convex hull is what a gamut method uses, so repeated colours add nothing); or only
///      the vertices of their exact 3-D hull, in the same order (colour_hull_3.h: all the 3-D
///      feasible set depends on); or, for the 2-D perspective route and without binning, the
///      chromaticity lifts (x, y, 1) of the vertices of the exact chromaticity hull
///      (chromaticity_hull.h), counter-clockwise from the lexicographically smallest, which is
///      all the 2-D feasible set depends on: a 10-megapixel image then costs the geometry a few
///      dozen colours. Lifts are not pixel colours: ImageColours::set says which the colours
///      are, and every 3-D entry point refuses lifts (docs/conventions.md §8).

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>
#include <gmcc/input/image_file.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// What step 6 returns.
enum class ColourSet {
  distinct,  ///< every distinct colour, in increasing (r, g, b) order: pixel colours
  hull,      ///< without binning: one chromaticity lift (x, y, 1) per vertex of the hull of
             ///< the chromaticities (x, y) = (r/b, g/b), counter-clockwise (b = 0 has none):
             ///< not pixel colours, for the 2-D perspective route only
  hull_3d,   ///< the distinct colours (binned or not) that are vertices of their exact 3-D
             ///< convex hull, sorted (colour_hull_vertices): pixel colours
};

/// `distinct`, `hull` or `hull-3d` (the command line's names).
std::string to_string(ColourSet set);
/// The inverse of to_string, also from the key `hull_3d` (Python's spelling).
/// \throws std::invalid_argument (quoting the text) for any other.
ColourSet colour_set_from_string(const std::string& text);
/// Every name to_string gives, in declaration order: the choices a front end offers.
std::vector<std::string> colour_set_names();

/// True when the set's colours are pixel colours (distinct or hull_3d), false for the
/// chromaticity lifts of ColourSet::hull.
inline bool pixel_colours(ColourSet set) { return set != ColourSet::hull; }

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
  /// Step 4: drop a pixel with a channel (after the black level) below this; absent: none.
  std::optional<std::uint32_t> dark_below;
  /// Step 4: drop a pixel with a channel below this fraction of M (0 to 1); absent: none.
  std::optional<Rational> dark_below_fraction;
  /// Step 4: drop a pixel with a channel above this fraction of M (0 to 1); absent: none.
  std::optional<Rational> bright_above_fraction;
  /// A Gaussian pre-filter of scale σ (Gijsenij et al. 2010's pixel gamut mapping parameter):
  /// 0 for none; else the image (black level removed) is smoothed channel by channel
  /// (image_derivatives.h, in double with a fixed order) and each kept pixel's colour is its
  /// smoothed value, taken exactly; which pixels are kept is decided on the raw values (steps
  /// 1–4). Not with binning.
  double prefilter_sigma = 0;
  std::uint32_t bin = 1;  ///< block size b for binning; 1: every kept pixel is a colour
  /// Step 6. With bin > 1, `hull` is not applied: the block means come back as
  /// ColourSet::distinct; `hull_3d` still keeps only their 3-D hull's vertices.
  ColourSet colour_set = ColourSet::distinct;
};

/// What happened to the pixels, each counted once, in the order of the steps.
struct PixelCounts {
  std::uint64_t pixels = 0;     ///< width · height
  std::uint64_t masked = 0;     ///< excluded by a polygon or the mask image
  std::uint64_t saturated = 0;  ///< of the rest, dropped for a channel >= saturation
  std::uint64_t dark = 0;       ///< of the rest, dropped as dark (step 4)
  std::uint64_t bright = 0;     ///< of the rest, dropped as too bright (step 4)
  std::uint64_t kept = 0;       ///< the rest
  std::uint64_t colours = 0;    ///< distinct colours (after binning)
  std::uint64_t hull_vertices = 0;    ///< ColourSet::hull or hull_3d: vertices returned
  std::uint64_t no_chromaticity = 0;  ///< ColourSet::hull: distinct colours with b = 0
};

/// What image_colours returns: the colours for the geometry and how each pixel was accounted for.
struct ImageColours {
  /// Pixel colours, or for ColourSet::hull chromaticity lifts (x, y, 1), which are not colours;
  /// in the order ColourSet describes.
  std::vector<Colour> colours;
  ColourSet set = ColourSet::distinct;  ///< what `colours` are: pixel colours or chromaticity lifts
  PixelCounts counts;  ///< what happened to the pixels
};

/// Gijsenij, Gevers & van de Weijer (2010)'s pixel rule as step 4's fractions: with the image
/// rescaled so that its largest value is 255, a pixel with a channel below 5 or above 245 is
/// dropped (dark_below_fraction 5/255, bright_above_fraction 245/255); the other fields as in
/// `base`.
PixelRules gijsenij_pixel_rules(PixelRules base = {});

/// The pixels steps 1 to 4 keep, and the counts of those steps.
struct KeptPixels {
  std::vector<bool> kept;  ///< per pixel, row-major: true if steps 1 to 4 keep it
  PixelCounts counts;      ///< pixels, masked, saturated, dark, bright and kept filled
};

/// Which pixels the rules keep (steps 1 to 4), row-major, with the counts of those steps: the
/// pixels every method of an image sees, the gamut methods and the statistics alike.
/// \throws std::invalid_argument as image_colours.
KeptPixels kept_pixels(const RgbImage& image, const PixelRules& rules);

/// Colours given as doubles (smoothed or derivative values), taken exactly, as `colour_set`
/// says: distinct (sorted), the 3-D hull's vertices, or the chromaticity hull's lifts; `counts`
/// as the caller's steps left them, with colours, hull_vertices and no_chromaticity set here.
/// The last step of the pre-filter route of image_colours and of edge colours (edge_colours.h).
/// \throws std::length_error for ColourSet::distinct with more than max_colours colours.
ImageColours colour_set_of_doubles(std::vector<std::array<double, 3>> colours, ColourSet colour_set,
                                   const PixelCounts& counts);

/// colour_set_of_doubles(colours, ColourSet::hull_3d, counts) without finding the distinct colours
/// (none are sorted but the hull's candidates): the same vertices in the same order, (r, g, b)
/// increasing, with `counts.colours` left 0 (docs/photographs.md §5, the edge colours of the
/// benchmark, which needs only the hull). \throws std::invalid_argument for a negative or not
/// finite channel (colour_hull_vertex_indices).
ImageColours hull_3d_of_doubles(std::vector<std::array<double, 3>> colours, const PixelCounts& counts);

/// Apply the rules to `image`.
/// \throws std::length_error for ColourSet::distinct with more than max_colours (colour_csv.h)
///         distinct colours; std::invalid_argument if bin is 0, `keep` is neither empty nor width
///         · height long, a polygon has fewer than 3 vertices, a fraction of step 4 is
///         outside [0, 1], or a pre-filter σ outside [0, 64] or given with binning.
ImageColours image_colours(const RgbImage& image, const PixelRules& rules);

/// What image_colours returns for each of `sets`, from the kept pixels `kept` that
/// kept_pixels(image, rules) gave: the image's distinct colours are found and sorted once for
/// every set (with binning or a pre-filter, image_colours is called per set). For a caller that
/// needs several sets and the kept pixels too (the benchmark: the 3-D hull's colours, the 2-D
/// lifts and the baselines' pixels).
/// \throws as image_colours; std::invalid_argument if `kept` is not of the image's size.
std::vector<ImageColours> image_colour_sets(const RgbImage& image, const PixelRules& rules, const KeptPixels& kept,
                                            const std::vector<ColourSet>& sets);

/// A linear camera image of floating-point samples (as a Python or MATLAB reader returns it):
/// width · height pixels, row-major, three channels each. Every double is an exact rational.
struct FloatRgbImage {
  std::size_t width = 0;   ///< pixels per row
  std::size_t height = 0;  ///< rows
  std::vector<double> samples;  ///< width · height · 3
};

/// The pixel rules of a floating-point image: `keep` (step 1), saturation (2), black level (3)
/// and dark and bright pixels (4) as for integer images, compared exactly; no binning.
struct FloatPixelRules {
  double black_level = 0;            ///< subtracted from every channel (>= 0, finite)
  std::optional<double> saturation;  ///< drop pixels with a raw channel >= this
  std::vector<bool> keep;            ///< per pixel (row-major), false to exclude; empty for none
  std::optional<double> dark_below;  ///< step 4: drop a pixel with a channel below this
  std::optional<Rational> dark_below_fraction;    ///< step 4, as PixelRules
  std::optional<Rational> bright_above_fraction;  ///< step 4, as PixelRules
  ColourSet colour_set = ColourSet::hull;  ///< step 6 (the default: chromaticity lifts)
};

/// Apply the rules to a floating-point image, exactly: each v − black_level must be exact in
/// double (it is for float32 data and whenever v <= 2·black_level; Sterbenz), checked by an
/// error-free transformation (Knuth's TwoSum), so the hull is that of the exact differences;
/// a channel at or below the black level becomes 0. Step 4 compares each channel with f·M in ℚ.
/// The chromaticity hull is chromaticity_hull's, the 3-D hull colour_hull_vertices' (exact).
/// counts.colours is the number of distinct kept colours.
/// \throws std::invalid_argument naming the pixel (row, column) and channel for a NaN, an
///         infinity or a negative sample, a subtraction that is not exact, a black level or
///         saturation that is negative or not finite, or a `keep` of the wrong size.
ImageColours image_colours(const FloatRgbImage& image, const FloatPixelRules& rules);

/// Most exact work the exclusion polygons of one image may take, Σ over polygons of polygon_work:
/// 2^20 (more is refused with std::invalid_argument before any work).
inline constexpr std::uint64_t max_polygon_work = std::uint64_t(1) << 20;

/// The exact work of `polygon`'s cover on an image of `height` rows: its vertices plus, per
/// edge, the rows whose centre line meets the edge's y-span (one rational crossing each).
std::uint64_t polygon_work(const std::vector<Point2>& polygon, std::size_t height);

/// The pixels a polygon excludes, row-major (true: centre inside or on the
/// boundary). Exposed for tests and reports.
std::vector<bool> polygon_cover(const std::vector<Point2>& polygon, std::size_t width,
                                std::size_t height);

}  // namespace gmcc
