#include <gmcc/photo/grey_edge.h>

#include "internal/names.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gmcc {

std::string to_string(Baseline b) {
  switch (b) {
    case Baseline::grey_world: return "grey_world";
    case Baseline::white_patch: return "white_patch";
    case Baseline::shades_of_grey: return "shades_of_grey";
    case Baseline::grey_edge_1: return "grey_edge_1";
    case Baseline::grey_edge_2: return "grey_edge_2";
  }
  return "?";
}

Baseline baseline_from_string(const std::string& text) {
  for (Baseline b : all_baselines)
    if (internal::names_match(text, to_string(b))) return b;
  throw std::invalid_argument("\"" + text +
                              "\" is not one of grey-world, white-patch, shades-of-grey, grey-edge-1, grey-edge-2");
}

GreyEdgeParameters baseline_parameters(Baseline b) {
  switch (b) {
    case Baseline::grey_world: return {DerivativeOrder::zero, 1, 0};
    case Baseline::white_patch: return {DerivativeOrder::zero, HUGE_VAL, 0};
    case Baseline::shades_of_grey: return {DerivativeOrder::zero, 6, 0};
    case Baseline::grey_edge_1: return {DerivativeOrder::first, 1, 1};
    case Baseline::grey_edge_2: return {DerivativeOrder::second, 1, 1};
  }
  return {};
}

std::optional<std::array<double, 3>> grey_edge_estimate(const RgbImage& image, std::uint32_t black_level,
                                                        const std::vector<bool>& kept, const GreyEdgeParameters& o) {
  if (kept.size() != image.width * image.height)
    throw std::invalid_argument("the kept-pixel mask does not match the image");
  if (!(o.p >= 1)) throw std::invalid_argument("the Minkowski norm p must be >= 1");
  const std::size_t w = image.width;
  // The derivative structure row by row, twice (no image of doubles: docs/cli.md "Resource
  // limits"): its largest kept value per channel, then Σ v^p with each channel scaled by that
  // value first (no overflow for large p), each channel's sum in pixel order.
  const auto each_kept = [&](const auto& f) {
    gaussian_derivative_rows(image, black_level, o.sigma, o.order, [&](std::size_t y, const double* s) {
      for (std::size_t x = 0; x < w; ++x)
        if (kept[y * w + x])
          for (int c = 0; c < 3; ++c) f(c, std::fabs(s[3 * x + static_cast<std::size_t>(c)]));
    });
  };
  std::array<double, 3> top{0, 0, 0};
  each_kept([&](int c, double v) { top[c] = std::max(top[c], v); });
  if (top[0] == 0 || top[1] == 0 || top[2] == 0) return std::nullopt;
  // Structure reached only through the Gaussian's tails (σ below about 0.1: weights near 1e-240,
  // or subnormal) can be so small that the light top·‖v/top‖ and the squares of its length
  // underflow, to an imprecise direction or a length of 0 (fuzz_edge_colours' findings): the light
  // is a direction, so the largest values are then brought near 1 by a power of 2 (exactly) first.
  std::array<double, 3> scaled = top;
  const double largest = std::max({top[0], top[1], top[2]});
  if (largest < 0x1p-500)
    for (double& t : scaled) t = std::ldexp(t, -std::ilogb(largest));
  std::array<double, 3> e = scaled;
  if (std::isfinite(o.p)) {
    std::array<double, 3> sum{0, 0, 0};
    each_kept([&](int c, double v) { sum[c] += o.p == 1 ? v / top[c] : std::pow(v / top[c], o.p); });
    for (int c = 0; c < 3; ++c) e[c] = scaled[c] * std::pow(sum[c], 1 / o.p);
  }
  const double n = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  return std::array<double, 3>{e[0] / n, e[1] / n, e[2] / n};
}

}  // namespace gmcc
