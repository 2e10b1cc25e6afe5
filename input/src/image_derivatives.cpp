#include <gmcc/input/image_derivatives.h>

#include <gmcc/numerics/interrupt.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace gmcc {
namespace {

// The sampled kernel of `order` at scale σ on [−r, r], normalised as image_derivatives.h says.
std::vector<double> kernel(double sigma, int order) {
  const int r = static_cast<int>(std::ceil(3 * sigma));
  std::vector<double> g(static_cast<std::size_t>(2 * r + 1));
  double sum = 0;
  // x = 0 apart: for σ below about 1e-154, σ² is 0 and 0/0 would make the centre NaN.
  for (int x = -r; x <= r; ++x) sum += g[static_cast<std::size_t>(x + r)] = x == 0 ? 1.0 : std::exp(-0.5 * x * x / (sigma * sigma));
  for (double& v : g) v /= sum;
  if (order == 0) return g;
  std::vector<double> k(g.size());
  if (order == 1) {
    double moment = 0;
    for (int x = -r; x <= r; ++x) moment += x * (k[static_cast<std::size_t>(x + r)] = -x * g[static_cast<std::size_t>(x + r)]);
    // Below σ ≈ 0.026 the tails g(±1) underflow to 0 and so does the moment: the kernel is then
    // its limit as σ → 0, which the normalisation makes the central difference (±1/2 at ∓1).
    if (moment == 0)
      for (int x = -r; x <= r; ++x) k[static_cast<std::size_t>(x + r)] = x == -1 ? 0.5 : x == 1 ? -0.5 : 0.0;
    else
      for (double& v : k) v /= -moment;  // Σ x·k(x) = −1
    return k;
  }
  double mean = 0;
  for (int x = -r; x <= r; ++x)
    mean += k[static_cast<std::size_t>(x + r)] =
        g[static_cast<std::size_t>(x + r)] == 0 ? 0.0
        : x == 0                              ? -g[static_cast<std::size_t>(x + r)]  // 0/σ² is NaN once σ² underflows
                                              : (x * x / (sigma * sigma) - 1) * g[static_cast<std::size_t>(x + r)];
  mean /= static_cast<double>(k.size());
  double moment = 0;
  for (int x = -r; x <= r; ++x) {
    double& v = k[static_cast<std::size_t>(x + r)];
    v -= mean;
    moment += 0.5 * x * x * v;
  }
  for (double& v : k) v /= moment;  // Σ x²/2·k(x) = 1: a parabola's curvature exactly
  return k;
}

// One separable pass along x (axis 0) or y (axis 1), the edge replicated.
DoubleImage convolve(const DoubleImage& in, const std::vector<double>& k, int axis) {
  const long r = static_cast<long>(k.size() / 2);
  const long w = static_cast<long>(in.width), h = static_cast<long>(in.height);
  DoubleImage out{in.width, in.height, std::vector<double>(in.samples.size())};
  for (long y = 0; y < h; ++y) {
    // A row costs 3·w·(2r + 1) products, at most a few milliseconds (σ = 64 on a 16,000-pixel
    // row): Ctrl-C in the Python module is answered within that at any σ.
    check_interrupt();
    for (long x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (long t = -r; t <= r; ++t) {
          long xx = axis == 0 ? x - t : x, yy = axis == 1 ? y - t : y;
          xx = std::min(std::max(xx, 0L), w - 1);
          yy = std::min(std::max(yy, 0L), h - 1);
          s += k[static_cast<std::size_t>(t + r)] * in.samples[static_cast<std::size_t>(3 * (yy * w + xx) + c)];
        }
        out.samples[static_cast<std::size_t>(3 * (y * w + x) + c)] = s;
      }
  }
  return out;
}

}  // namespace

DoubleImage linear_image(const RgbImage& image, std::uint32_t black_level) {
  DoubleImage out{image.width, image.height, std::vector<double>(image.samples.size())};
  for (std::size_t i = 0; i < image.samples.size(); ++i)
    out.samples[i] = image.samples[i] > black_level ? double(image.samples[i] - black_level) : 0.0;
  return out;
}

DoubleImage gaussian_derivative(const DoubleImage& image, double sigma, DerivativeOrder order) {
  if (!std::isfinite(sigma) || sigma < 0 || sigma > 64)
    throw std::invalid_argument("sigma must be from 0 to 64");
  if (sigma == 0) {
    if (order != DerivativeOrder::zero) throw std::invalid_argument("a derivative needs sigma > 0");
    return image;
  }
  const std::vector<double> g = kernel(sigma, 0);
  if (order == DerivativeOrder::zero) return convolve(convolve(image, g, 0), g, 1);
  DoubleImage out{image.width, image.height, std::vector<double>(image.samples.size())};
  // A channel constant over the image has derivatives exactly 0 (the edge is replicated): they
  // are set so, where the convolutions would leave round-off that reads as a direction.
  std::array<bool, 3> flat{true, true, true};
  for (std::size_t i = 3; i < image.samples.size(); ++i) flat[i % 3] = flat[i % 3] && image.samples[i] == image.samples[i % 3];
  const auto zero_flat = [&](DoubleImage& d) {
    for (std::size_t i = 0; i < d.samples.size(); ++i)
      if (flat[i % 3]) d.samples[i] = 0;
  };
  if (order == DerivativeOrder::first) {
    const std::vector<double> d = kernel(sigma, 1);
    const DoubleImage fx = convolve(convolve(image, d, 0), g, 1), fy = convolve(convolve(image, g, 0), d, 1);
    for (std::size_t i = 0; i < out.samples.size(); ++i)
      out.samples[i] = std::sqrt(fx.samples[i] * fx.samples[i] + fy.samples[i] * fy.samples[i]);
    zero_flat(out);
    return out;
  }
  const std::vector<double> d1 = kernel(sigma, 1), d2 = kernel(sigma, 2);
  const DoubleImage fxx = convolve(convolve(image, d2, 0), g, 1), fyy = convolve(convolve(image, g, 0), d2, 1),
                    fxy = convolve(convolve(image, d1, 0), d1, 1);
  for (std::size_t i = 0; i < out.samples.size(); ++i)
    out.samples[i] = std::sqrt(fxx.samples[i] * fxx.samples[i] + 4 * fxy.samples[i] * fxy.samples[i] +
                               fyy.samples[i] * fyy.samples[i]);
  zero_flat(out);
  return out;
}

}  // namespace gmcc
