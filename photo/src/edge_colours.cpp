// Edge colours for edge-based gamut mapping (Gijsenij, Gevers & van de Weijer 2010 §4).
#include <gmcc/photo/edge_colours.h>

#include <array>
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
  const DoubleImage g = gaussian_derivative(linear_image(image, pixels.black_level), edges.sigma, edges.order);
  const std::size_t w = image.width, h = image.height, r = edges.neighbourhood;
  // Pixels whose (2r + 1)² neighbourhood lies in the image and is kept, by a row pass (every
  // pixel within r in the row kept) and then a column pass over its result.
  std::vector<char> run(w * h, 0);
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      bool ok = x >= r && x + r < w;
      for (std::size_t k = x >= r ? x - r : 0; ok && k <= x + r; ++k) ok = kept.kept[y * w + k];
      run[y * w + x] = ok;
    }
  PixelCounts counts = kept.counts;
  counts.kept = 0;
  std::vector<std::array<double, 3>> colours;
  for (std::size_t y = r; y + r < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      bool ok = true;
      for (std::size_t k = y - r; ok && k <= y + r; ++k) ok = run[k * w + x];
      if (!ok) continue;
      ++counts.kept;
      const std::size_t i = y * w + x;
      colours.push_back({g.at(i, 0), g.at(i, 1), g.at(i, 2)});
    }
  return colour_set_of_doubles(std::move(colours), pixels.colour_set, counts);
}

}  // namespace gmcc
