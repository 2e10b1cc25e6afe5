#include <gmcc/photo/image_derivatives.h>

#include <gmcc/numerics/interrupt.h>

#include <algorithm>
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

// The image's rows as doubles: the linear image of an RgbImage (black level removed, clamped at
// 0: exact) or a DoubleImage's own samples.
struct LinearRows {
  const RgbImage& image;
  std::uint32_t black;
  void operator()(std::size_t y, double* out) const {
    const std::size_t n = 3 * image.width, first = y * n;
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t v = image.samples[first + i];
      out[i] = v > black ? double(v - black) : 0.0;
    }
  }
  bool same(std::size_t i, std::size_t j) const {  // linear samples i and j equal
    const auto level = [&](std::uint32_t v) { return v > black ? v - black : 0u; };
    return level(image.samples[i]) == level(image.samples[j]);
  }
};
struct DoubleRows {
  const DoubleImage& image;
  void operator()(std::size_t y, double* out) const {
    const std::size_t n = 3 * image.width;
    std::copy(image.samples.begin() + static_cast<long>(y * n), image.samples.begin() + static_cast<long>((y + 1) * n), out);
  }
  bool same(std::size_t i, std::size_t j) const { return image.samples[i] == image.samples[j]; }
};

// The separable passes along x of several kernels (all of radius r), each kept for the rows the
// passes along y need: a ring of min(h, 2r + 1) rows, row y in slot y mod slots. Rows are made
// in increasing order, each source row converted once; the edge is replicated.
template <class Source>
class XPasses {
 public:
  XPasses(const Source& source, std::size_t w, std::size_t h, std::vector<const std::vector<double>*> kernels)
      : source_(source), kernels_(std::move(kernels)), w_(static_cast<long>(w)),
        r_(static_cast<long>(kernels_.front()->size() / 2)), slots_(std::min<long>(static_cast<long>(h), 2 * r_ + 1)),
        in_(3 * w), rings_(kernels_.size(), std::vector<double>(static_cast<std::size_t>(slots_) * 3 * w)) {}
  // Rows 0 to `last` made.
  void make_to(long last) {
    for (; next_ <= last; ++next_) {
      // A row costs 3·w·(2r + 1) products per kernel, at most a few milliseconds (σ = 64 on a
      // 16,000-pixel row): Ctrl-C in the Python module is answered within that at any σ.
      check_interrupt();
      source_(static_cast<std::size_t>(next_), in_.data());
      for (std::size_t k = 0; k < kernels_.size(); ++k) along_x(*kernels_[k], rings_[k].data() + (next_ % slots_) * 3 * w_);
    }
  }
  // Kernel k's pass along x at row y (made, and within the last 2r + 1 made).
  const double* row(std::size_t k, long y) const { return rings_[k].data() + (y % slots_) * 3 * w_; }
  long radius() const { return r_; }

 private:
  // One kernel along the source row in_ into out: per value, Σ_t k(t)·in(x − t) with t from −r
  // to r in that order (the sums made term by term for every x at once), x − t clamped.
  void along_x(const std::vector<double>& kernel, double* out) const {
    std::fill(out, out + 3 * w_, 0.0);
    for (long t = -r_; t <= r_; ++t) {
      const double k = kernel[static_cast<std::size_t>(t + r_)];
      const long from = std::min(std::max(t, 0L), w_), to = std::max(std::min(w_ + t, w_), from);  // x − t in [0, w)
      for (long x = 0; x < from; ++x)
        for (long c = 0; c < 3; ++c) out[3 * x + c] += k * in_[static_cast<std::size_t>(c)];
      for (long i = 3 * from; i < 3 * to; ++i) out[i] += k * in_[static_cast<std::size_t>(i - 3 * t)];
      for (long x = to; x < w_; ++x)
        for (long c = 0; c < 3; ++c) out[3 * x + c] += k * in_[static_cast<std::size_t>(3 * (w_ - 1) + c)];
    }
  }

  const Source& source_;
  std::vector<const std::vector<double>*> kernels_;
  long w_, r_, slots_, next_ = 0;
  std::vector<double> in_;
  std::vector<std::vector<double>> rings_;
};

// The pass along y of kernel `k` over pass `along_x` of `x` at row y, into out (3·w values): per
// value, Σ_t k(t)·row(y − t) with t from −r to r in that order, y − t clamped.
template <class Source>
void y_pass(const XPasses<Source>& x, std::size_t along_x, const std::vector<double>& k, long y, long w, long h,
            double* out) {
  const long r = x.radius();
  std::fill(out, out + 3 * w, 0.0);
  for (long t = -r; t <= r; ++t) {
    const double kt = k[static_cast<std::size_t>(t + r)];
    const double* row = x.row(along_x, std::min(std::max(y - t, 0L), h - 1));
    for (long i = 0; i < 3 * w; ++i) out[i] += kt * row[i];
  }
}

// The channels constant over the whole image (their derivatives are exactly 0).
template <class Source>
std::array<bool, 3> flat_channels(const Source& source, std::size_t samples) {
  std::array<bool, 3> flat{true, true, true};
  for (std::size_t i = 3; i < samples; ++i) flat[i % 3] = flat[i % 3] && source.same(i, i % 3);
  return flat;
}

// sqrt(a² + 4c² + b²) (c = 0: the gradient's magnitude), as written; where the sum of squares
// leaves the doubles' normal range (derivatives of about 1e-154 or less, which the Gaussian's
// tails give at σ below about 0.1), from the values scaled by the largest first, so that a
// non-zero derivative never has magnitude 0 (fuzz_edge_colours' finding).
double magnitude(double a, double b, double c, double squares) {
  if (squares >= 0x1p-1000 || (a == 0 && b == 0 && c == 0)) return std::sqrt(squares);
  const double m = std::max({std::fabs(a), std::fabs(b), std::fabs(c)});
  a /= m, b /= m, c /= m;
  return m * std::sqrt(a * a + 4 * c * c + b * b);
}

// gaussian_derivative's values row by row, from `source` (a w × h image).
template <class Source>
void derivative_rows(const Source& source, std::size_t w, std::size_t h, double sigma, DerivativeOrder order,
                     const std::function<void(std::size_t, const double*)>& row) {
  if (!std::isfinite(sigma) || sigma < 0 || sigma > 64) throw std::invalid_argument("sigma must be from 0 to 64");
  if (sigma == 0 && order != DerivativeOrder::zero) throw std::invalid_argument("a derivative needs sigma > 0");
  std::vector<double> out(3 * w);
  const long W = static_cast<long>(w), H = static_cast<long>(h);
  if (sigma == 0) {
    for (std::size_t y = 0; y < h; ++y) {
      check_interrupt();
      source(y, out.data());
      row(y, out.data());
    }
    return;
  }
  const std::vector<double> g = kernel(sigma, 0);
  const std::vector<double> d1 = order == DerivativeOrder::zero ? std::vector<double>{} : kernel(sigma, 1);
  const std::vector<double> d2 = order == DerivativeOrder::second ? kernel(sigma, 2) : std::vector<double>{};
  // Order 0: g along x, then g along y. Order 1: f_x = d1 then g, f_y = g then d1. Order 2:
  // f_xx = d2 then g, f_yy = g then d2, f_xy = d1 then d1.
  std::vector<const std::vector<double>*> along_x = {&g};
  if (order == DerivativeOrder::first) along_x = {&d1, &g};
  if (order == DerivativeOrder::second) along_x = {&d2, &g, &d1};
  XPasses<Source> x(source, w, h, along_x);
  // A channel constant over the image has derivatives exactly 0 (the edge is replicated): they
  // are set so, where the convolutions would leave round-off that reads as a direction.
  const std::array<bool, 3> flat = order == DerivativeOrder::zero ? std::array<bool, 3>{} : flat_channels(source, 3 * w * h);
  std::vector<double> a(3 * w), b(3 * w), c(3 * w);
  for (long y = 0; y < H; ++y) {
    x.make_to(std::min(H - 1, y + x.radius()));
    check_interrupt();
    if (order == DerivativeOrder::zero) {
      y_pass(x, 0, g, y, W, H, out.data());
    } else if (order == DerivativeOrder::first) {
      y_pass(x, 0, g, y, W, H, a.data());  // f_x
      y_pass(x, 1, d1, y, W, H, b.data());  // f_y
      for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = flat[i % 3] ? 0.0 : magnitude(a[i], b[i], 0, a[i] * a[i] + b[i] * b[i]);
    } else {
      y_pass(x, 0, g, y, W, H, a.data());   // f_xx
      y_pass(x, 1, d2, y, W, H, b.data());  // f_yy
      y_pass(x, 2, d1, y, W, H, c.data());  // f_xy
      for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = flat[i % 3] ? 0.0 : magnitude(a[i], b[i], c[i], a[i] * a[i] + 4 * c[i] * c[i] + b[i] * b[i]);
    }
    row(static_cast<std::size_t>(y), out.data());
  }
}

}  // namespace

DoubleImage linear_image(const RgbImage& image, std::uint32_t black_level) {
  DoubleImage out{image.width, image.height, std::vector<double>(image.samples.size())};
  for (std::size_t i = 0; i < image.samples.size(); ++i)
    out.samples[i] = image.samples[i] > black_level ? double(image.samples[i] - black_level) : 0.0;
  return out;
}

DoubleImage gaussian_derivative(const DoubleImage& image, double sigma, DerivativeOrder order) {
  DoubleImage out{image.width, image.height, std::vector<double>(image.samples.size())};
  derivative_rows(DoubleRows{image}, image.width, image.height, sigma, order, [&](std::size_t y, const double* row) {
    std::copy(row, row + 3 * image.width, out.samples.begin() + static_cast<long>(3 * image.width * y));
  });
  return out;
}

void gaussian_derivative_rows(const RgbImage& image, std::uint32_t black_level, double sigma, DerivativeOrder order,
                              const std::function<void(std::size_t, const double*)>& row) {
  derivative_rows(LinearRows{image, black_level}, image.width, image.height, sigma, order, row);
}

}  // namespace gmcc
