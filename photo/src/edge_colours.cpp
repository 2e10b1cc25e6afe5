// Edge colours for edge-based gamut mapping (Gijsenij, Gevers & van de Weijer 2010 §4).
#include <gmcc/photo/edge_colours.h>

#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/input/colour_csv.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
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
  // Kept pixels with every pixel within distance r kept: a row pass, then a column pass, of the
  // distance to the nearest dropped pixel (or the image's border, where the neighbourhood is
  // incomplete).
  std::vector<std::size_t> run(w * h, 0);  // kept pixels to the left and right within r, capped
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      bool ok = x >= r && x + r < w;
      for (std::size_t k = x >= r ? x - r : 0; ok && k <= x + r; ++k) ok = kept.kept[y * w + k];
      run[y * w + x] = ok;
    }
  ImageColours out;
  out.counts = kept.counts;
  out.counts.kept = 0;
  std::vector<std::array<double, 3>> colours;
  for (std::size_t y = r; y + r < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      bool ok = true;
      for (std::size_t k = y - r; ok && k <= y + r; ++k) ok = run[k * w + x];
      if (!ok) continue;
      ++out.counts.kept;
      const std::size_t i = y * w + x;
      colours.push_back({g.at(i, 0), g.at(i, 1), g.at(i, 2)});
    }
  std::sort(colours.begin(), colours.end());
  colours.erase(std::unique(colours.begin(), colours.end()), colours.end());
  out.counts.colours = colours.size();
  out.set = pixels.colour_set;
  if (colours.empty()) return out;
  if (pixels.colour_set == ColourSet::hull_3d) {
    for (std::size_t i : colour_hull_vertex_indices(colours))
      out.colours.push_back({Rational(colours[i][0]), Rational(colours[i][1]), Rational(colours[i][2])});
    out.counts.hull_vertices = out.colours.size();
    return out;
  }
  if (colours.size() > max_colours)
    throw std::length_error(std::to_string(colours.size()) + " distinct edge colours, more than the " +
                            std::to_string(max_colours) + " a colour set may hold: use the hull-3d colour set");
  for (const auto& c : colours) out.colours.push_back({Rational(c[0]), Rational(c[1]), Rational(c[2])});
  return out;
}

}  // namespace gmcc
