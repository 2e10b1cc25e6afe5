// Fuzz target: the edge-colour path (issue 42) — an image's Gaussian derivatives
// (image_derivatives.h), its edge colours (photo/edge_colours.h) and the grey-edge baselines
// (photo/grey_edge.h), as the benchmark's edge-based gamut methods and baselines take them.
//
// Ten option bytes, then the samples: byte 0 and 1 the width and height (1 to 24), byte 2 σ (from
// a table: tiny ones whose kernels underflow or whose tails are about 1e-240, ordinary ones, 64 (a kernel wider than the image),
// and refused ones: 0, negative, above 64, not finite), byte 3 the derivative order, the colour
// set and the neighbourhood (0 to 3, half the image, or values near 2^63 and 2^64 whose 2r + 1
// overflows), bytes 4 to 7 the pixel rules (black level, saturation, a keep mask, dark and bright
// fractions, binning or a pre-filter the edge colours refuse), byte 8 the grey-edge norm p (1, 2,
// 6, infinity, or a refused p < 1 or NaN), byte 9 how the samples are made (16 bits from the
// bytes, 8 bits, near 65535, or a channel constant over the image); then 2 bytes a sample, 0 past
// the end.
//
// Must hold:
// - gaussian_derivative_rows gives each row once, in order, with the values of gaussian_derivative
//   on the linear image bit for bit; both refuse exactly the σ and orders image_derivatives.h
//   refuses (std::invalid_argument). Those values are finite, orders 1 and 2 >= 0, a channel
//   constant over the image has derivatives exactly 0, and for σ >= 0.1 each value is within a
//   rounding bound of an independent evaluation of the documented kernels in long double.
// - edge_colours throws std::invalid_argument exactly for the refusals edge_colours.h lists;
//   otherwise counts.kept is the number of pixels whose (2r + 1)² neighbourhood lies in the image
//   and is kept (brute force), the other step counts are kept_pixels', the distinct colours are
//   exactly the derivative triples at those pixels (sorted, each once, counted), and hull-3d's are
//   the vertices colour_hull_vertex_indices finds among them (empty exactly when there is none).
// - grey_edge_estimate throws std::invalid_argument exactly for p < 1 (or NaN) and σ refused;
//   otherwise it is absent exactly when some channel's structure is 0 at every kept pixel, and else
//   a unit vector of channels >= 0 within 1e-9 of the norm evaluated in long double.
// No input may crash, hang or allocate beyond a few copies of its small image (libFuzzer's
// -malloc_limit_mb and -rss_limit_mb).

#include "fuzz_support.h"

#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/photo/image_derivatives.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/photo/edge_colours.h>
#include <gmcc/photo/grey_edge.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using Triple = std::array<double, 3>;
constexpr std::size_t options_size = 10;

constexpr double sigmas[16] = {1e-300, 0.02, 0.026, 0.03, 0.1, 0.5, 1, 2, 3.7, 8, 64,
                               0, -1, 64.5, std::numeric_limits<double>::quiet_NaN(), HUGE_VAL};

gmcc::DerivativeOrder order_of(int k) {
  return k == 0 ? gmcc::DerivativeOrder::zero : k == 1 ? gmcc::DerivativeOrder::first : gmcc::DerivativeOrder::second;
}

bool sigma_refused(double sigma, gmcc::DerivativeOrder order) {
  return !std::isfinite(sigma) || sigma < 0 || sigma > 64 || (sigma == 0 && order != gmcc::DerivativeOrder::zero);
}

// The image from the option bytes and the samples.
gmcc::RgbImage image_from(const std::uint8_t* o, gmcc::fuzz::ByteReader& in) {
  gmcc::RgbImage image;
  image.width = 1 + o[0] % 24;
  image.height = 1 + o[1] % 24;
  const int mode = o[9] % 4;
  image.bits = mode == 1 ? 8 : 16;
  image.samples.resize(image.width * image.height * 3);
  for (std::size_t i = 0; i < image.samples.size(); ++i) {
    const auto v = static_cast<std::uint16_t>(in.bytes(2));
    image.samples[i] = mode == 1 ? static_cast<std::uint16_t>(v & 0xff)
                       : mode == 2 ? static_cast<std::uint16_t>(65535 - (v & 0x3f))
                                   : v;
    if (mode == 3 && i % 3 == static_cast<std::size_t>(o[9] >> 2) % 3) image.samples[i] = static_cast<std::uint16_t>(o[9] * 97);
  }
  return image;
}

gmcc::PixelRules rules_from(const std::uint8_t* o, const gmcc::RgbImage& image) {
  gmcc::PixelRules rules;
  rules.black_level = image.bits == 8 ? o[4] % 64 : std::uint32_t(o[4]) * 64;
  if (o[5]) rules.saturation = image.bits == 8 ? o[5] : std::uint32_t(o[5]) << 8;
  const std::size_t pixels = image.width * image.height;
  if (o[6] % 4 == 1)
    for (std::size_t i = 0; i < pixels; ++i) rules.keep.push_back((i + i / image.width) % 2 == 0);
  else if (o[6] % 4 == 2)
    for (std::size_t i = 0; i < pixels; ++i) rules.keep.push_back(((i * 2654435761u) >> (o[6] % 7)) & 1);
  else if (o[6] % 4 == 3)
    for (std::size_t i = 0; i < pixels; ++i) rules.keep.push_back(i % 7 != static_cast<std::size_t>(o[6] >> 5));
  if (o[7] & 1) rules.dark_below_fraction = gmcc::Rational(o[7] >> 2, 255);
  if (o[7] & 2) rules.bright_above_fraction = gmcc::Rational(128 + (o[7] >> 1), 255);
  const int extra = (o[6] >> 2) % 8;  // 6: binning, 7: a pre-filter (both refused by edge colours)
  if (extra == 6) rules.bin = 2;
  if (extra == 7) rules.prefilter_sigma = 1;
  return rules;
}

// The documented kernels (image_derivatives.h), in long double, written from the definitions.
std::vector<long double> reference_kernel(double sigma, int order) {
  const long r = static_cast<long>(std::ceil(3 * sigma));
  std::vector<long double> g, k;
  long double sum = 0;
  for (long x = -r; x <= r; ++x) g.push_back(std::exp(-0.5L * x * x / ((long double)sigma * sigma)));
  for (long double v : g) sum += v;
  for (long double& v : g) v /= sum;
  if (order == 0) return g;
  long double moment = 0, mean = 0;
  for (long x = -r; x <= r; ++x) {
    const long double s2 = (long double)sigma * sigma;
    k.push_back(order == 1 ? -x * g[x + r] : (x * x / (s2 * s2) - 1 / s2) * g[x + r]);
    mean += k.back();
  }
  if (order == 2)
    for (long double& v : k) v -= mean / k.size();
  for (long x = -r; x <= r; ++x) moment += (order == 1 ? x : 0.5L * x * x) * k[x + r];
  for (long double& v : k) v /= order == 1 ? -moment : moment;
  return k;
}

// One separable pass of `k` along `axis` over a w × h image of long doubles, the edge replicated:
// the kernel folded first into each output's weights on the n samples of its line (a kernel wider
// than the image costs n, not 2r + 1, a value).
std::vector<long double> reference_pass(const std::vector<long double>& in, std::size_t w, std::size_t h,
                                        const std::vector<long double>& k, int axis) {
  const long r = static_cast<long>(k.size() / 2), W = static_cast<long>(w), H = static_cast<long>(h);
  const long n = axis == 0 ? W : H;
  std::vector<long double> weight(static_cast<std::size_t>(n * n), 0), out(in.size());
  for (long i = 0; i < n; ++i)
    for (long t = -r; t <= r; ++t) weight[i * n + std::clamp(i - t, 0L, n - 1)] += k[t + r];
  for (long y = 0; y < H; ++y)
    for (long x = 0; x < W; ++x)
      for (long c = 0; c < 3; ++c) {
        const long i = axis == 0 ? x : y;
        long double s = 0;
        for (long j = 0; j < n; ++j) s += weight[i * n + j] * in[3 * (axis == 0 ? y * W + j : j * W + x) + c];
        out[3 * (y * W + x) + c] = s;
      }
  return out;
}

// The derivative values against the reference: within a rounding bound of each.
void check_against_reference(const gmcc::DoubleImage& linear, const gmcc::DoubleImage& d, double sigma, int order) {
  const std::size_t w = linear.width, h = linear.height;
  const std::vector<long double> f(linear.samples.begin(), linear.samples.end());
  const auto g = reference_kernel(sigma, 0);
  const auto along = [&](const std::vector<long double>& kx, const std::vector<long double>& ky) {
    return reference_pass(reference_pass(f, w, h, kx, 0), w, h, ky, 1);
  };
  std::vector<long double> a, b, c;
  long double scale = 0;  // Σ|kx|·Σ|ky| for the kernels used, times the largest sample
  const auto weight = [](const std::vector<long double>& k) {
    long double s = 0;
    for (long double v : k) s += std::fabs(v);
    return s;
  };
  if (order == 0) {
    a = along(g, g);
    scale = weight(g) * weight(g);
  } else if (order == 1) {
    const auto d1 = reference_kernel(sigma, 1);
    a = along(d1, g), b = along(g, d1);
    scale = weight(d1) * weight(g);
  } else {
    const auto d1 = reference_kernel(sigma, 1), d2 = reference_kernel(sigma, 2);
    a = along(d2, g), b = along(g, d2), c = along(d1, d1);
    scale = std::max(weight(d2) * weight(g), 2 * weight(d1) * weight(d1));
  }
  long double top = 1;
  for (double v : linear.samples) top = std::max<long double>(top, v);
  const long double tolerance = 1e-9L * scale * top * (1 + 6 * sigma);
  for (std::size_t i = 0; i < d.samples.size(); ++i) {
    const long double want = order == 0   ? a[i]
                             : order == 1 ? std::sqrt(a[i] * a[i] + b[i] * b[i])
                                          : std::sqrt(a[i] * a[i] + 4 * c[i] * c[i] + b[i] * b[i]);
    FUZZ_CHECK(std::fabs(d.samples[i] - want) <= tolerance,
               "derivative " + std::to_string(d.samples[i]) + " against " + std::to_string((double)want) + " at " +
                   std::to_string(i) + ", sigma " + std::to_string(sigma) + ", order " + std::to_string(order));
  }
}

// The derivatives, whole and row by row; nullopt when refused.
std::optional<gmcc::DoubleImage> check_derivatives(const gmcc::RgbImage& image, std::uint32_t black, double sigma,
                                                   gmcc::DerivativeOrder order) {
  const gmcc::DoubleImage linear = gmcc::linear_image(image, black);
  gmcc::DoubleImage whole;
  try {
    whole = gmcc::gaussian_derivative(linear, sigma, order);
  } catch (const std::invalid_argument&) {
    FUZZ_CHECK(sigma_refused(sigma, order), "gaussian_derivative refused sigma " + std::to_string(sigma));
    bool rows_refused = false;
    try {
      gmcc::gaussian_derivative_rows(image, black, sigma, order, [](std::size_t, const double*) {});
    } catch (const std::invalid_argument&) {
      rows_refused = true;
    }
    FUZZ_CHECK(rows_refused, "gaussian_derivative_rows took what gaussian_derivative refused");
    return std::nullopt;
  }
  FUZZ_CHECK(!sigma_refused(sigma, order), "gaussian_derivative took sigma " + std::to_string(sigma));
  FUZZ_CHECK(whole.width == image.width && whole.height == image.height && whole.samples.size() == image.samples.size(),
             "derivative size");
  std::size_t next = 0;
  const std::size_t w3 = 3 * image.width;
  gmcc::gaussian_derivative_rows(image, black, sigma, order, [&](std::size_t y, const double* row) {
    FUZZ_CHECK(y == next++, "rows out of order");
    for (std::size_t i = 0; i < w3; ++i)
      FUZZ_CHECK(std::memcmp(&row[i], &whole.samples[y * w3 + i], sizeof(double)) == 0, "a row differs from the whole image");
  });
  FUZZ_CHECK(next == image.height, "rows missing");
  std::array<bool, 3> flat{true, true, true};
  for (std::size_t i = 3; i < linear.samples.size(); ++i) flat[i % 3] = flat[i % 3] && linear.samples[i] == linear.samples[i % 3];
  for (std::size_t i = 0; i < whole.samples.size(); ++i) {
    FUZZ_CHECK(std::isfinite(whole.samples[i]), "a derivative that is not finite");
    if (order != gmcc::DerivativeOrder::zero) {
      FUZZ_CHECK(whole.samples[i] >= 0, "a negative magnitude");
      FUZZ_CHECK(!flat[i % 3] || whole.samples[i] == 0, "a constant channel with a derivative");
    }
  }
  if (sigma >= 0.1) check_against_reference(linear, whole, sigma, static_cast<int>(order));
  return whole;
}

std::size_t neighbourhood_from(std::uint8_t o, const gmcc::RgbImage& image) {
  switch (o % 8) {
    case 4: return image.width / 2;
    case 5: return std::numeric_limits<std::size_t>::max();
    case 6: return std::numeric_limits<std::size_t>::max() / 2 + 1;
    case 7: return std::numeric_limits<std::size_t>::max() / 2;
    default: return o % 8;
  }
}

void check_edge_colours(const gmcc::RgbImage& image, const gmcc::PixelRules& pixels, const gmcc::EdgeRules& edges,
                        const std::optional<gmcc::DoubleImage>& d) {
  gmcc::ImageColours out;
  try {
    out = gmcc::edge_colours(image, pixels, edges);
  } catch (const std::invalid_argument& e) {
    const bool refused = pixels.colour_set == gmcc::ColourSet::hull || pixels.bin != 1 || pixels.prefilter_sigma != 0 ||
                         edges.order == gmcc::DerivativeOrder::zero || !(edges.sigma > 0 && edges.sigma <= 64);
    FUZZ_CHECK(refused, std::string("edge_colours refused: ") + e.what());
    return;
  }
  FUZZ_CHECK(d.has_value() && pixels.colour_set != gmcc::ColourSet::hull && pixels.bin == 1 &&
                 pixels.prefilter_sigma == 0 && edges.order != gmcc::DerivativeOrder::zero,
             "edge_colours took what it refuses");
  const gmcc::KeptPixels kept = gmcc::kept_pixels(image, pixels);
  const std::size_t w = image.width, h = image.height, r = edges.neighbourhood;
  std::vector<Triple> want;
  for (std::size_t y = 0; y < h; ++y)
    for (std::size_t x = 0; x < w; ++x) {
      bool ok = r < w && r < h && x >= r && y >= r && w - x > r && h - y > r;
      for (std::size_t yy = y - (ok ? r : 0); ok && yy <= y + r; ++yy)
        for (std::size_t xx = x - r; ok && xx <= x + r; ++xx) ok = kept.kept[yy * w + xx];
      if (ok) want.push_back({d->at(y * w + x, 0), d->at(y * w + x, 1), d->at(y * w + x, 2)});
    }
  const gmcc::PixelCounts& n = out.counts;
  FUZZ_CHECK(n.kept == want.size(), "edge pixels miscounted: " + std::to_string(n.kept) + " for " + std::to_string(want.size()));
  FUZZ_CHECK(n.pixels == kept.counts.pixels && n.masked == kept.counts.masked && n.saturated == kept.counts.saturated &&
                 n.dark == kept.counts.dark && n.bright == kept.counts.bright,
             "step counts differ from kept_pixels'");
  std::sort(want.begin(), want.end());
  want.erase(std::unique(want.begin(), want.end()), want.end());
  FUZZ_CHECK(n.colours == want.size(), "distinct edge colours miscounted");
  std::vector<Triple> got;
  for (const gmcc::Colour& c : out.colours) got.push_back({c.r.get_d(), c.g.get_d(), c.b.get_d()});
  for (std::size_t i = 0; i < got.size(); ++i)
    FUZZ_CHECK(gmcc::Rational(got[i][0]) == out.colours[i].r && gmcc::Rational(got[i][1]) == out.colours[i].g &&
                   gmcc::Rational(got[i][2]) == out.colours[i].b,
               "an edge colour that is not a double taken exactly");
  if (pixels.colour_set == gmcc::ColourSet::distinct) {
    FUZZ_CHECK(got == want, "distinct edge colours differ from the derivatives at the edge pixels");
    return;
  }
  std::vector<Triple> vertices;
  if (!want.empty())
    for (std::size_t i : gmcc::colour_hull_vertex_indices(want)) vertices.push_back(want[i]);
  FUZZ_CHECK(got == vertices, "hull-3d edge colours differ from the hull of the distinct ones");
  FUZZ_CHECK(n.hull_vertices == got.size(), "hull vertices miscounted");
}

void check_grey_edge(const gmcc::RgbImage& image, const gmcc::PixelRules& pixels, const gmcc::GreyEdgeParameters& p,
                     const std::optional<gmcc::DoubleImage>& d) {
  const gmcc::KeptPixels kept = gmcc::kept_pixels(image, pixels);
  std::optional<std::array<double, 3>> e;
  try {
    e = gmcc::grey_edge_estimate(image, pixels.black_level, kept.kept, p);
  } catch (const std::invalid_argument& x) {
    FUZZ_CHECK(!(p.p >= 1) || sigma_refused(p.sigma, p.order), std::string("grey_edge_estimate refused: ") + x.what());
    return;
  }
  FUZZ_CHECK(p.p >= 1 && d.has_value(), "grey_edge_estimate took what it refuses");
  std::array<long double, 3> top{0, 0, 0}, sum{0, 0, 0};
  for (std::size_t i = 0; i < kept.kept.size(); ++i)
    if (kept.kept[i])
      for (int c = 0; c < 3; ++c) top[c] = std::max<long double>(top[c], std::fabs(d->at(i, c)));
  const bool none = top[0] == 0 || top[1] == 0 || top[2] == 0;
  FUZZ_CHECK(e.has_value() == !none, "grey edge present exactly when every channel has structure");
  if (!e) return;
  std::array<long double, 3> want = top;
  if (std::isfinite(p.p)) {
    for (std::size_t i = 0; i < kept.kept.size(); ++i)
      if (kept.kept[i])
        for (int c = 0; c < 3; ++c) sum[c] += std::pow(std::fabs(d->at(i, c)) / top[c], (long double)p.p);
    for (int c = 0; c < 3; ++c) want[c] = top[c] * std::pow(sum[c], 1 / (long double)p.p);
  }
  const long double norm = std::sqrt(want[0] * want[0] + want[1] * want[1] + want[2] * want[2]);
  for (int c = 0; c < 3; ++c) {
    FUZZ_CHECK((*e)[c] >= 0 && std::isfinite((*e)[c]), "a grey-edge channel below 0 or not finite");
    FUZZ_CHECK(std::fabs((*e)[c] - want[c] / norm) <= 1e-9L, "grey edge differs from its definition");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::uint8_t o[options_size] = {};
  std::copy(data, data + std::min(size, options_size), o);
  gmcc::fuzz::ByteReader in(data + std::min(size, options_size), size - std::min(size, options_size));
  const gmcc::RgbImage image = image_from(o, in);
  const gmcc::PixelRules pixels = rules_from(o, image);
  gmcc::EdgeRules edges;
  edges.sigma = sigmas[o[2] % 16];
  edges.order = order_of(o[3] % 3);
  edges.neighbourhood = neighbourhood_from(static_cast<std::uint8_t>(o[3] / 9), image);
  gmcc::PixelRules edge_pixels = pixels;
  edge_pixels.colour_set = (o[3] / 3) % 3 == 0   ? gmcc::ColourSet::distinct
                           : (o[3] / 3) % 3 == 1 ? gmcc::ColourSet::hull_3d
                                                 : gmcc::ColourSet::hull;
  const std::optional<gmcc::DoubleImage> d = check_derivatives(image, pixels.black_level, edges.sigma, edges.order);
  check_edge_colours(image, edge_pixels, edges, d);
  // The grey-edge baselines on the plain pixel rules (binning and the pre-filter are not theirs).
  gmcc::PixelRules grey_pixels = pixels;
  grey_pixels.bin = 1;
  grey_pixels.prefilter_sigma = 0;
  constexpr double norms[6] = {1, 2, 6, HUGE_VAL, 0.5, std::numeric_limits<double>::quiet_NaN()};
  gmcc::GreyEdgeParameters p{edges.order, norms[o[8] % 6], edges.sigma};
  if (edges.order == gmcc::DerivativeOrder::zero && (o[8] & 0x80)) p.sigma = 0;  // grey world, white patch, …
  check_grey_edge(image, grey_pixels, p,
                  p.sigma == edges.sigma ? d : check_derivatives(image, pixels.black_level, p.sigma, p.order));
  return 0;
}
