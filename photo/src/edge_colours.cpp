// Edge colours for edge-based gamut mapping (Gijsenij, Gevers & van de Weijer 2010 §4).
#include <gmcc/photo/edge_colours.h>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace gmcc {

ImageColours edge_colours(const RgbImage& image, const PixelRules& pixels, const EdgeRules& edges) {
  if (!pixel_colours(pixels.colour_set))
    throw std::invalid_argument("edge colours: the chromaticity hull colour set gives lifts, not colours");
  if (pixels.bin != 1 || pixels.prefilter_sigma != 0)
    throw std::invalid_argument("edge colours: no binning or pre-filter (the derivatives smooth the image)");
  if (edges.order == DerivativeOrder::zero)
    throw std::invalid_argument("edge colours: the derivative order is first or second");
  if (!(edges.sigma > 0 && edges.sigma <= 64))
    throw std::invalid_argument("edge colours: sigma must be in (0, 64]");
  const KeptPixels kept = kept_pixels(image, pixels);
  const std::size_t w = image.width, h = image.height, r = edges.neighbourhood;
  PixelCounts counts = kept.counts;
  counts.kept = 0;
  std::vector<std::array<double, 3>> colours;
  // No (2r + 1)² neighbourhood fits in the image (r compared first: 2r + 1 may overflow).
  if (r >= w || r >= h || 2 * r + 1 > w || 2 * r + 1 > h) return colour_set_of_doubles({}, pixels.colour_set, counts);
  const std::size_t span = 2 * r + 1;
  // A pixel's neighbourhood is kept when the 2r + 1 pixels of the row around it are kept in each
  // of the 2r + 1 rows around it: per column, the number of rows in a row ending here whose row
  // window is kept (the rows counted as they come, in O(pixels) whatever r).
  std::vector<std::size_t> rows_kept(w, 0);
  std::size_t counted = 0;  // rows counted so far
  const auto count_row = [&](std::size_t y) {
    std::size_t in_row = 0;  // kept pixels in a row ending at x
    for (std::size_t x = 0; x < w; ++x) {
      in_row = kept.kept[y * w + x] ? in_row + 1 : 0;
      if (x >= r) {
        const std::size_t centre = x - r;  // its row window [centre − r, x] is kept: in_row >= span
        rows_kept[centre] = centre >= r && in_row >= span ? rows_kept[centre] + 1 : 0;
      }
    }
    for (std::size_t x = w - r; x < w; ++x) rows_kept[x] = 0;  // no row window
  };
  // The edge pixels counted first, so that their colours take 24 bytes each and no more.
  std::size_t edge_pixels = 0;
  for (; counted < h; ++counted) {
    count_row(counted);
    if (counted + 1 >= span)
      for (std::size_t x = 0; x < w; ++x) edge_pixels += rows_kept[x] >= span;
  }
  colours.reserve(edge_pixels);
  std::fill(rows_kept.begin(), rows_kept.end(), 0);
  counted = 0;
  // The derivatives row by row: no image of doubles (docs/cli.md "Resource limits").
  gaussian_derivative_rows(image, pixels.black_level, edges.sigma, edges.order, [&](std::size_t y, const double* g) {
    for (; counted < h && counted <= y + r; ++counted) count_row(counted);
    if (y < r || y + r >= h) return;
    for (std::size_t x = 0; x < w; ++x) {
      if (rows_kept[x] < span) continue;
      ++counts.kept;
      colours.push_back({g[3 * x], g[3 * x + 1], g[3 * x + 2]});
    }
  });
  return colour_set_of_doubles(std::move(colours), pixels.colour_set, counts);
}

}  // namespace gmcc
