// Edge colours for edge-based gamut mapping (Gijsenij, Gevers & van de Weijer 2010 §4).
#include <gmcc/photo/edge_colours.h>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace gmcc {

namespace {

// Each order asked's edge colours (out[0] the 1st, out[1] the 2nd order), as edge_colours says.
std::array<ImageColours, 2> edge_colour_sets(const RgbImage& image, const PixelRules& pixels, const EdgeRules& edges,
                                             const std::array<bool, 3>& orders) {
  if (!pixel_colours(pixels.colour_set))
    throw std::invalid_argument("edge colours: the chromaticity hull colour set gives lifts, not colours");
  if (pixels.bin != 1 || pixels.prefilter_sigma != 0)
    throw std::invalid_argument("edge colours: no binning or pre-filter (the derivatives smooth the image)");
  if (!orders[1] && !orders[2]) throw std::invalid_argument("edge colours: the derivative order is first or second");
  if (!(edges.sigma > 0 && edges.sigma <= 64))
    throw std::invalid_argument("edge colours: sigma must be in (0, 64]");
  const KeptPixels kept = kept_pixels(image, pixels);
  const std::size_t w = image.width, h = image.height, r = edges.neighbourhood;
  PixelCounts counts = kept.counts;
  counts.kept = 0;
  std::array<ImageColours, 2> out;
  // No (2r + 1)² neighbourhood fits in the image (r compared first: 2r + 1 may overflow).
  if (r >= w || r >= h || 2 * r + 1 > w || 2 * r + 1 > h) {
    for (int o = 0; o < 2; ++o)
      if (orders[static_cast<std::size_t>(o + 1)]) out[o] = colour_set_of_doubles({}, pixels.colour_set, counts);
    return out;
  }
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
  std::vector<std::array<double, 3>> colours[2];
  for (int o = 0; o < 2; ++o)
    if (orders[static_cast<std::size_t>(o + 1)]) colours[o].reserve(edge_pixels);
  std::fill(rows_kept.begin(), rows_kept.end(), 0);
  counted = 0;
  // The derivatives row by row: no image of doubles (docs/cli.md "Resource limits").
  gaussian_derivative_rows(image, pixels.black_level, edges.sigma, orders,
                           [&](std::size_t y, const std::array<const double*, 3>& g) {
                             for (; counted < h && counted <= y + r; ++counted) count_row(counted);
                             if (y < r || y + r >= h) return;
                             for (std::size_t x = 0; x < w; ++x) {
                               if (rows_kept[x] < span) continue;
                               ++counts.kept;
                               for (int o = 0; o < 2; ++o)
                                 if (const double* v = g[static_cast<std::size_t>(o + 1)])
                                   colours[o].push_back({v[3 * x], v[3 * x + 1], v[3 * x + 2]});
                             }
                           });
  for (int o = 0; o < 2; ++o)
    if (orders[static_cast<std::size_t>(o + 1)])
      out[o] = !edges.count_colours && pixels.colour_set == ColourSet::hull_3d
                   ? hull_3d_of_doubles(std::move(colours[o]), counts)
                   : colour_set_of_doubles(std::move(colours[o]), pixels.colour_set, counts);
  return out;
}

}  // namespace

ImageColours edge_colours(const RgbImage& image, const PixelRules& pixels, const EdgeRules& edges) {
  std::array<bool, 3> orders{};  // order zero: none of 1 and 2, refused
  orders[static_cast<std::size_t>(edges.order)] = true;
  return std::move(edge_colour_sets(image, pixels, edges, orders)[edges.order == DerivativeOrder::second ? 1 : 0]);
}

std::array<ImageColours, 2> edge_colours_both_orders(const RgbImage& image, const PixelRules& pixels,
                                                      const EdgeRules& edges) {
  return edge_colour_sets(image, pixels, edges, {false, true, true});
}

}  // namespace gmcc
