#include <gmcc/photo/grey_edge.h>

#include "internal/names.h"

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

std::optional<std::array<double, 3>> grey_edge_estimate(const DoubleImage& image, const std::vector<bool>& kept,
                                                        const GreyEdgeParameters& o) {
  if (kept.size() != image.width * image.height)
    throw std::invalid_argument("the kept-pixel mask does not match the image");
  if (!(o.p >= 1)) throw std::invalid_argument("the Minkowski norm p must be >= 1");
  const DoubleImage s = gaussian_derivative(image, o.sigma, o.order);
  // Σ v^p with each channel scaled by its largest kept value first (no overflow for large p).
  std::array<double, 3> top{0, 0, 0};
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (kept[i])
      for (int c = 0; c < 3; ++c) top[c] = std::max(top[c], std::fabs(s.at(i, c)));
  if (top[0] == 0 || top[1] == 0 || top[2] == 0) return std::nullopt;
  std::array<double, 3> e = top;
  if (std::isfinite(o.p)) {
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (std::size_t i = 0; i < kept.size(); ++i)
        if (kept[i]) sum += o.p == 1 ? std::fabs(s.at(i, c)) / top[c] : std::pow(std::fabs(s.at(i, c)) / top[c], o.p);
      e[c] = top[c] * std::pow(sum, 1 / o.p);
    }
  }
  const double n = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  return std::array<double, 3>{e[0] / n, e[1] / n, e[2] / n};
}

}  // namespace gmcc
