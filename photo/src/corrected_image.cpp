#include <gmcc/photo/corrected_image.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gmcc {

RgbImage corrected_image(const RgbImage& image, std::uint32_t black_level, std::uint32_t saturation,
                         const std::array<double, 3>& m) {
  for (double v : m)
    if (!std::isfinite(v) || v < 0) throw std::invalid_argument("corrected_image: a map component is negative or not finite");
  const double big = std::max({m[0], m[1], m[2]});
  if (!(big > 0)) throw std::invalid_argument("corrected_image: the map is zero");
  const double d[3] = {m[0] / big, m[1] / big, m[2] / big};
  RgbImage out = image;
  out.bits = 16;
  const double scale = image.bits == 8 ? 257.0 : 1.0;  // 8-bit codes to 16-bit
  for (std::size_t p = 0; p < image.width * image.height; ++p) {
    const std::uint16_t* in = &image.samples[3 * p];
    const bool clipped = in[0] >= saturation || in[1] >= saturation || in[2] >= saturation;
    for (int c = 0; c < 3; ++c) {
      if (clipped) {
        out.samples[3 * p + c] = 65535;
        continue;
      }
      const double x = (in[c] > black_level ? in[c] - black_level : 0) * d[c] * scale;
      out.samples[3 * p + c] = static_cast<std::uint16_t>(std::min(65535.0, std::floor(x + 0.5)));
    }
  }
  return out;
}

}  // namespace gmcc
