// Edge-based gamut mapping (gmcc::photo, issue 26 item 3): edge colours obey the diagonal model
// exactly (a power-of-2 map on the image maps its edge colours alike, bit for bit), the
// neighbourhood rule drops the edges next to a dropped pixel, the refusals, and the joint
// estimate: one type is the single-type estimate, and a scene's true map lies in the joint F3 of
// its pixel and edge gamuts.
#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/photo/edge_colours.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/grey_edge.h>
#include <gmcc/photo/learn_canonical.h>
#include <gmcc/photo/image_derivatives.h>
#include <gmcc/numerics/interrupt.h>

#include <boost/test/unit_test.hpp>

#include "internal/clamped_convolution.h"  // photo/src: the FFT route and the kernels

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <limits>
#include <random>
#include <thread>

using namespace gmcc;

namespace {

// A w × h image of random rectangles of random colours (a Mondrian), channels in [lo, hi].
RgbImage mondrian(std::mt19937& rng, std::size_t w, std::size_t h, unsigned lo, unsigned hi) {
  RgbImage im;
  im.width = w, im.height = h;
  im.samples.assign(w * h * 3, 0);
  std::uniform_int_distribution<unsigned> v(lo, hi);
  std::uniform_int_distribution<std::size_t> x(0, w - 1), y(0, h - 1);
  for (int k = 0; k < 40; ++k) {
    const std::size_t x0 = x(rng), y0 = y(rng), x1 = std::min(w, x0 + 1 + x(rng) / 2), y1 = std::min(h, y0 + 1 + y(rng) / 2);
    const unsigned c[3] = {v(rng), v(rng), v(rng)};
    for (std::size_t yy = y0; yy < y1; ++yy)
      for (std::size_t xx = x0; xx < x1; ++xx)
        for (int ch = 0; ch < 3; ++ch) im.samples[3 * (yy * w + xx) + ch] = static_cast<std::uint16_t>(c[ch]);
  }
  return im;
}

// Σ_t k(t)·in(clamp(x − t)) in long double (2^-64 per operation): the reference for the FFT route.
std::vector<long double> clamped_reference(const std::vector<long double>& in, const std::vector<double>& k) {
  const long r = static_cast<long>(k.size() / 2), n = static_cast<long>(in.size());
  std::vector<long double> out(in.size(), 0.0L);
  for (long x = 0; x < n; ++x)
    for (long t = -r; t <= r; ++t)
      out[static_cast<std::size_t>(x)] += static_cast<long double>(k[static_cast<std::size_t>(t + r)]) *
                                          in[static_cast<std::size_t>(std::clamp(x - t, 0L, n - 1))];
  return out;
}

double l1(const std::vector<double>& k) {
  double s = 0;
  for (double v : k) s += std::fabs(v);
  return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(edge_colours_suite)

BOOST_AUTO_TEST_CASE(edge_colours_follow_the_diagonal_model_exactly) {
  std::mt19937 rng(26);
  for (DerivativeOrder order : {DerivativeOrder::first, DerivativeOrder::second}) {
    const RgbImage im = mondrian(rng, 40, 30, 100, 8000);
    RgbImage mapped = im;  // d = (2, 4, 1): powers of 2, so every double operation scales exactly
    for (std::size_t i = 0; i < mapped.samples.size(); i += 3) mapped.samples[i] *= 2, mapped.samples[i + 1] *= 4;
    EdgeRules e;
    e.order = order;
    for (ColourSet set : {ColourSet::distinct, ColourSet::hull_3d}) {
      PixelRules rules;
      rules.colour_set = set;
      const ImageColours a = edge_colours(im, rules, e), b = edge_colours(mapped, rules, e);
      BOOST_TEST_REQUIRE(a.colours.size() > 3u);
      BOOST_TEST_REQUIRE(a.colours.size() == b.colours.size());
      for (std::size_t i = 0; i < a.colours.size(); ++i) {
        BOOST_TEST((b.colours[i].r == 2 * a.colours[i].r));
        BOOST_TEST((b.colours[i].g == 4 * a.colours[i].g));
        BOOST_TEST((b.colours[i].b == a.colours[i].b));
        BOOST_TEST(sgn(a.colours[i].r) >= 0);  // magnitudes
      }
      BOOST_TEST(a.counts.kept == (40u - 4) * (30u - 4));  // the border's 2 pixels have no full neighbourhood
    }
  }
}

BOOST_AUTO_TEST_CASE(edges_next_to_a_dropped_pixel_are_not_taken) {
  std::mt19937 rng(27);
  const RgbImage im = mondrian(rng, 20, 20, 100, 8000);
  PixelRules rules;
  rules.keep.assign(400, true);
  rules.keep[10 * 20 + 10] = false;  // one dropped pixel: its 5 × 5 neighbourhood loses its edges
  EdgeRules e;
  BOOST_TEST(edge_colours(im, rules, e).counts.kept == 16u * 16 - 25);
  e.neighbourhood = 0;  // only the pixel itself (and every pixel up to the border)
  BOOST_TEST(edge_colours(im, rules, e).counts.kept == 400u - 1);
  BOOST_CHECK_THROW(edge_colours(im, PixelRules{}, EdgeRules{DerivativeOrder::zero, 1, 2}), std::invalid_argument);
  BOOST_CHECK_THROW(edge_colours(im, PixelRules{}, EdgeRules{DerivativeOrder::first, 0, 2}), std::invalid_argument);
  PixelRules lifts;
  lifts.colour_set = ColourSet::hull;
  BOOST_CHECK_THROW(edge_colours(im, lifts), std::invalid_argument);
  PixelRules binned;
  binned.bin = 2;
  BOOST_CHECK_THROW(edge_colours(im, binned), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(both_orders_from_one_sweep_are_each_order_alone) {
  // Issue 46 (the 2-jet): the 1st- and 2nd-order edge colours from one sweep are those of each
  // order alone, colour for colour and count for count: both colour sets, the direct and the FFT
  // routes (σ = 16), a dropped pixel and a black level, a neighbourhood too wide for the image.
  std::mt19937 rng(46);
  for (const auto& [w, h] : {std::pair<std::size_t, std::size_t>{23, 17}, {9, 40}}) {
    const RgbImage im = mondrian(rng, w, h, 100, 20000);
    PixelRules rules;
    rules.black_level = 150;
    rules.keep.assign(w * h, true);
    rules.keep[(h / 2) * w + w / 3] = false;
    for (ColourSet set : {ColourSet::distinct, ColourSet::hull_3d})
      for (double sigma : {1.0, 4.0, 16.0})
        for (std::size_t r : {std::size_t(0), std::size_t(2), std::size_t(20)}) {
          rules.colour_set = set;
          EdgeRules e{DerivativeOrder::second, sigma, r};  // the order is not read
          const std::array<ImageColours, 2> both = edge_colours_both_orders(im, rules, e);
          for (int o = 0; o < 2; ++o) {
            e.order = o == 0 ? DerivativeOrder::first : DerivativeOrder::second;
            const ImageColours alone = edge_colours(im, rules, e);
            const ImageColours& b = both[static_cast<std::size_t>(o)];
            BOOST_TEST((b.colours == alone.colours), "order " << o + 1 << " sigma " << sigma << " r " << r);
            BOOST_TEST(b.counts.kept == alone.counts.kept);
            BOOST_TEST(b.counts.colours == alone.counts.colours);
            BOOST_TEST(b.counts.hull_vertices == alone.counts.hull_vertices);
            BOOST_TEST(b.counts.dark == alone.counts.dark);
            BOOST_TEST((b.set == alone.set));
          }
          BOOST_TEST((r == 20 || !both[0].colours.empty()));
          BOOST_TEST((both[0].colours != both[1].colours || both[0].colours.empty()));
        }
  }
  const RgbImage im = mondrian(rng, 8, 8, 100, 900);
  PixelRules lifts;
  lifts.colour_set = ColourSet::hull;
  BOOST_CHECK_THROW(edge_colours_both_orders(im, lifts, EdgeRules{}), std::invalid_argument);
  BOOST_CHECK_THROW(edge_colours_both_orders(im, PixelRules{}, EdgeRules{DerivativeOrder::first, 0, 2}),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(hull_without_the_distinct_colours_is_the_same_hull) {
  // Issue 46: the benchmark's edge colours skip finding the distinct colours (hull_3d_of_doubles):
  // the same vertices in the same order as colour_set_of_doubles's hull of the sorted distinct
  // colours, from shuffled colours with repeats and from flat ones, and edge_colours with
  // count_colours false the same colours and counts but the distinct count.
  std::mt19937_64 rng(46);
  std::uniform_int_distribution<int> small(0, 40);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<std::array<double, 3>> colours;
    for (int i = 0; i < 300 + 400 * trial; ++i) {
      std::array<double, 3> c{small(rng) / 8.0, small(rng) * 0.3, small(rng) * 1e-3};
      if (trial % 3 == 2) c[2] = c[0];  // flat: the plane b = r
      colours.push_back(c);
      if (i % 5 == 0) colours.push_back(c);  // repeats
    }
    std::shuffle(colours.begin(), colours.end(), rng);
    // The reference: the hull of the sorted distinct colours by index (colour_hull_3.h).
    std::vector<std::array<double, 3>> sorted = colours;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    std::vector<Colour> want;
    for (std::size_t i : colour_hull_vertex_indices(sorted))
      want.push_back({Rational(sorted[i][0]), Rational(sorted[i][1]), Rational(sorted[i][2])});
    const ImageColours got = hull_3d_of_doubles(colours, PixelCounts{});
    const ImageColours set = colour_set_of_doubles(colours, ColourSet::hull_3d, PixelCounts{});
    BOOST_TEST_REQUIRE(want.size() >= 3u);
    BOOST_TEST((got.colours == want), "trial " << trial);
    BOOST_TEST((set.colours == want), "trial " << trial);
    BOOST_TEST(got.counts.hull_vertices == want.size());
    BOOST_TEST(got.counts.colours == 0u);
    BOOST_TEST(set.counts.colours == sorted.size());
  }
  BOOST_TEST(hull_3d_of_doubles({}, PixelCounts{}).colours.empty());
  std::mt19937 rng32(47);
  const RgbImage im = mondrian(rng32, 30, 26, 100, 20000);
  PixelRules rules;
  rules.colour_set = ColourSet::hull_3d;
  for (double sigma : {1.0, 16.0}) {
    EdgeRules e{DerivativeOrder::first, sigma, 2};
    const ImageColours counted = edge_colours(im, rules, e);
    e.count_colours = false;
    const ImageColours hull = edge_colours(im, rules, e);
    BOOST_TEST((hull.colours == counted.colours));
    BOOST_TEST(hull.counts.kept == counted.counts.kept);
    BOOST_TEST(hull.counts.hull_vertices == counted.counts.hull_vertices);
    BOOST_TEST(hull.counts.colours == 0u);
    BOOST_TEST(counted.counts.colours > 0u);
  }
}

// A scene seen under a light e: canonical pixel and edge gamuts learned from the same scene under
// white light, the true map 1/e in the joint F3; with one type the joint estimate is the single one.
BOOST_AUTO_TEST_CASE(joint_estimate_of_pixel_and_edge_gamuts) {
  std::mt19937 rng(28);
  const RgbImage white = mondrian(rng, 48, 48, 200, 4000);
  RgbImage lit = white;  // e = (2, 1, 4) exactly
  for (std::size_t i = 0; i < lit.samples.size(); i += 3) lit.samples[i] *= 2, lit.samples[i + 2] *= 4;
  PixelRules rules;
  rules.colour_set = ColourSet::hull_3d;
  CanonicalLearner3 pixels(CanonicalIntensity::none), edges(CanonicalIntensity::none);
  pixels.add(image_colours(white, rules).colours, {1, 1, 1});
  edges.add(edge_colours(white, rules).colours, {1, 1, 1});
  const CanonicalConstraints3 cp(pixels.gamut()), ce(edges.gamut());
  const ImageColours p = image_colours(lit, rules), e = edge_colours(lit, rules);
  const ImageEstimate3 joint = estimate_3d(std::vector<GamutConstraint3>{{&cp, &p.colours}, {&ce, &e.colours}});
  BOOST_TEST_REQUIRE((joint.feasible.kind != ConvexKind3::empty));
  BOOST_TEST(contains(joint.feasible, Point3{Rational(1, 2), 1, Rational(1, 4)}));
  // The true map is the largest in F3 in every direction that keeps its proportions: every
  // rule's light is the true one.
  BOOST_TEST_REQUIRE(joint[Rule3::max_trace]->light.has_value());
  BOOST_TEST(recovery_angular_error_deg(*joint[Rule3::max_trace]->light, {2, 1, 4}) < 1e-9);
  const ImageEstimate3 alone = estimate_3d(cp, p), as_joint = estimate_3d(std::vector<GamutConstraint3>{{&cp, &p.colours}});
  BOOST_TEST((alone.feasible == as_joint.feasible));
  BOOST_TEST((alone[Rule3::max_trace]->selection.estimate.exact == as_joint[Rule3::max_trace]->selection.estimate.exact));
  BOOST_TEST((alone[Rule3::max_volume]->selection.estimate.exact == as_joint[Rule3::max_volume]->selection.estimate.exact));
  BOOST_CHECK_THROW(estimate_3d(std::vector<GamutConstraint3>{}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(tiny_sigmas_give_central_differences) {
  // Issue 42: below σ ≈ 0.026 the sampled Gaussian's tails underflow (the first-order kernel's
  // moment was 0, 0/0 made it NaN), and below about 1e-154 σ² itself (the centre was NaN). The
  // derivatives are now their limit, central differences: on a ramp of slope 3 in x, the first
  // derivative's magnitude is 3 inside, the second 0, and the smoothing is the identity.
  DoubleImage ramp{8, 6, std::vector<double>(8 * 6 * 3)};
  for (std::size_t y = 0; y < 6; ++y)
    for (std::size_t x = 0; x < 8; ++x)
      for (std::size_t c = 0; c < 3; ++c) ramp.samples[3 * (y * 8 + x) + c] = 3.0 * static_cast<double>(x) + static_cast<double>(c);
  for (double sigma : {0.02, 1e-100, 1e-300}) {
    const DoubleImage d1 = gaussian_derivative(ramp, sigma, DerivativeOrder::first);
    const DoubleImage d2 = gaussian_derivative(ramp, sigma, DerivativeOrder::second);
    const DoubleImage d0 = gaussian_derivative(ramp, sigma, DerivativeOrder::zero);
    for (std::size_t y = 0; y < 6; ++y)
      for (std::size_t x = 1; x + 1 < 8; ++x)
        for (std::size_t c = 0; c < 3; ++c) {
          BOOST_TEST(d1.samples[3 * (y * 8 + x) + c] == 3.0);
          BOOST_TEST(std::abs(d2.samples[3 * (y * 8 + x) + c]) < 1e-9);  // [1, -2, 1] up to rounding
        }
    BOOST_TEST((d0.samples == ramp.samples));
  }
}

BOOST_AUTO_TEST_CASE(derivatives_stop_at_an_interrupt) {
  // Issue 42 item 4: the convolutions check for an interrupt row by row, so a Ctrl-C in the
  // Python module is answered within a row at any σ, not after the image.
  DoubleImage im{64, 64, std::vector<double>(64 * 64 * 3, 1.0)};
  interrupt_requested.store(true);
  bool stopped = false;
  try {
    gaussian_derivative(im, 64, DerivativeOrder::second);
  } catch (const Interrupted&) {
    stopped = true;
  }
  interrupt_requested.store(false);
  BOOST_TEST(stopped);
}

BOOST_AUTO_TEST_CASE(derivative_rows_are_the_whole_images_rows) {
  // Issue 42 (memory): the benchmark takes the derivatives row by row, from the 16-bit samples,
  // with rings of the passes along x; the values are the whole image's bit for bit, for images
  // shorter and taller than a kernel, at every order, with a black level.
  std::mt19937 rng(42);
  for (std::size_t h : {1u, 5u, 40u}) {
    const RgbImage im = mondrian(rng, 23, h, 0, 60000);
    for (double sigma : {0.0, 0.02, 1.0, 2.5, 64.0})
      for (DerivativeOrder order : {DerivativeOrder::zero, DerivativeOrder::first, DerivativeOrder::second}) {
        if (sigma == 0 && order != DerivativeOrder::zero) continue;
        const DoubleImage whole = gaussian_derivative(linear_image(im, 700), sigma, order);
        std::size_t next = 0;
        bool same = true;
        gaussian_derivative_rows(im, 700, sigma, order, [&](std::size_t y, const double* row) {
          same = same && y == next++ && std::memcmp(row, &whole.samples[3 * 23 * y], 3 * 23 * sizeof(double)) == 0;
        });
        BOOST_TEST((same && next == h), "sigma " << sigma << " order " << static_cast<int>(order) << " height " << h);
      }
  }
  BOOST_CHECK_THROW(gaussian_derivative_rows(RgbImage{}, 0, 0, DerivativeOrder::first, [](std::size_t, const double*) {}),
                    std::invalid_argument);
  // An image of no columns (or no rows): h empty rows at every σ, on the FFT route's σ too (it
  // read the sample before a row's first, a review's finding).
  for (const auto& [w, h] : {std::pair<std::size_t, std::size_t>{0, 5}, {5, 0}, {0, 0}})
    for (double sigma : {1.0, 16.0, 64.0}) {
      const DoubleImage d = gaussian_derivative(DoubleImage{w, h, {}}, sigma, DerivativeOrder::second);
      BOOST_TEST((d.width == w && d.height == h && d.samples.empty()));
      std::size_t rows = 0;
      gaussian_derivative_rows(RgbImage{w, h, 16, {}}, 0, sigma, {true, true, true},
                               [&](std::size_t, const std::array<const double*, 3>&) { ++rows; });
      BOOST_TEST(rows == h, "width " << w << " height " << h << " sigma " << sigma);
    }
}

BOOST_AUTO_TEST_CASE(one_sweep_of_several_orders_is_each_order_alone) {
  // Issue 46 (the baselines at full size): the orders asked together share their passes; each
  // order's rows are those of a sweep of that order alone, bit for bit, on the direct and the FFT
  // routes, for every set of orders, and null for an order not asked.
  std::mt19937 rng(46);
  for (std::size_t h : {1u, 7u, 45u}) {
    const RgbImage im = mondrian(rng, 19, h, 0, 60000);
    for (double sigma : {0.02, 1.0, 4.0, 11.5})
      for (int mask = 1; mask < 8; ++mask) {
        const std::array<bool, 3> asked{(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
        std::vector<double> alone[3];
        for (int o = 0; o < 3; ++o)
          if (asked[static_cast<std::size_t>(o)])
            gaussian_derivative_rows(im, 300, sigma, static_cast<DerivativeOrder>(o), [&](std::size_t, const double* row) {
              alone[o].insert(alone[o].end(), row, row + 3 * 19);
            });
        bool same = true;
        std::size_t rows = 0;
        gaussian_derivative_rows(im, 300, sigma, asked, [&](std::size_t y, const std::array<const double*, 3>& v) {
          ++rows;
          for (std::size_t o = 0; o < 3; ++o)
            same = same && (asked[o] ? v[o] && std::memcmp(v[o], &alone[o][3 * 19 * y], 3 * 19 * sizeof(double)) == 0
                                     : v[o] == nullptr);
        });
        BOOST_TEST((same && rows == h), "sigma " << sigma << " orders " << mask << " height " << h);
      }
  }
  BOOST_CHECK_THROW(gaussian_derivative_rows(mondrian(rng, 4, 4, 0, 9), 0, 0, std::array<bool, 3>{true, true, false},
                                             [](std::size_t, const std::array<const double*, 3>&) {}),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(fft_convolution_within_its_stated_bound) {
  // Issue 46: above radius kFftMinRadius the derivatives' 1-D passes are FFT convolutions; each
  // is within 2^-40·Σ|k|·max|in| of the exact truncated, edge-replicated sum (clamped_convolution.h),
  // checked against long double sums on random sequences, short and long, for every kernel.
  std::mt19937 rng(46);
  std::uniform_real_distribution<double> v(0, 65535);
  double worst = 0;  // the largest error seen, over its bound's scale Σ|k|·max|in|
  for (std::size_t n : {1u, 2u, 7u, 100u, 1500u})
    for (double sigma : {5.5, 16.0, 64.0})
      for (int order : {0, 1, 2}) {
        const std::vector<double> k = internal::derivative_kernel(sigma, order);
        std::vector<double> in(n);
        double top = 0;
        for (double& x : in) top = std::max(top, x = std::floor(v(rng)));
        const std::vector<double> fft = internal::clamped_convolution_fft(in, k);
        const std::vector<long double> ref = clamped_reference(std::vector<long double>(in.begin(), in.end()), k);
        double err = 0;
        for (std::size_t i = 0; i < n; ++i) err = std::max(err, static_cast<double>(std::fabs(fft[i] - ref[i])));
        const double scale = l1(k) * std::max(top, 1.0);
        worst = std::max(worst, err / scale);
        BOOST_TEST(err <= 0x1p-40 * scale, "n " << n << " sigma " << sigma << " order " << order << ": " << err);
      }
  BOOST_TEST_MESSAGE("FFT convolution: largest error " << worst << " of sum|k| max|in|");
  BOOST_TEST(worst > 0);  // the comparison compared something
}

BOOST_AUTO_TEST_CASE(fft_without_reordering_is_the_dft_in_bit_reversed_order) {
  // The FFT route's transforms (clamped_convolution.h: decimation in frequency forward, leaving the
  // spectrum in bit-reversed order; decimation in time back, reading it so): forward against a
  // long double DFT at rev(k) (its n twiddles made once per n), inverse(forward(a)) against n·a,
  // for every length from 2 to 2^12 on random complex data; each within 2^-50·n·max|a| (the
  // round-off is O(u log n): about 5.6e-14 at n = 2^12, against the bound's 3.6e-12).
  std::mt19937 rng(4647);
  std::uniform_real_distribution<double> v(-1, 1);
  const long double pi = 3.141592653589793238462643383279502884L;
  for (std::size_t n = 2; n <= 4096; n *= 2) {
    const internal::Fft fft(n);
    std::vector<std::complex<double>> a(n);
    for (auto& z : a) z = {v(rng), v(rng)};
    std::vector<std::complex<double>> t = a;
    fft.forward(t.data());
    double err = 0, back = 0;
    std::vector<long double> c(n), s(n);  // cos and sin of −2π·m/n
    for (std::size_t m = 0; m < n; ++m) {
      const long double x = -2 * pi * static_cast<long double>(m) / static_cast<long double>(n);
      c[m] = std::cos(x), s[m] = std::sin(x);
    }
    for (std::size_t k = 0; k < n; ++k) {
      long double re = 0, im = 0;
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t m = (j * k) % n;
        re += a[j].real() * c[m] - a[j].imag() * s[m];
        im += a[j].real() * s[m] + a[j].imag() * c[m];
      }
      const std::complex<double>& got = t[fft.bit_reversed(k)];
      err = std::max(err, static_cast<double>(std::max(std::fabs(got.real() - re), std::fabs(got.imag() - im))));
    }
    fft.inverse(t.data());
    for (std::size_t j = 0; j < n; ++j)
      back = std::max(back, std::max(std::fabs(t[j].real() - static_cast<double>(n) * a[j].real()),
                                     std::fabs(t[j].imag() - static_cast<double>(n) * a[j].imag())));
    BOOST_TEST(err <= 0x1p-50 * static_cast<double>(n), "n " << n << ": forward " << err);
    BOOST_TEST(back <= 0x1p-50 * static_cast<double>(n), "n " << n << ": round trip " << back);
  }
}

BOOST_AUTO_TEST_CASE(fft_route_buffers_kept_between_calls_change_nothing) {
  // The FFT route's rings and results are kept by the thread between calls (image_derivatives.cpp,
  // KeptBuffers; every value written before it is read): each image's rows are the same bytes as
  // those made in a fresh thread, after images of other sizes and orders in this thread, and after
  // one too large to keep (its own buffers).
  std::mt19937 rng(4648);
  const std::vector<RgbImage> images = {mondrian(rng, 70, 50, 0, 60000), mondrian(rng, 13, 300, 0, 60000),
                                        mondrian(rng, 150, 3, 0, 60000), mondrian(rng, 600, 400, 0, 60000)};
  const std::array<bool, 3> orders[2] = {{false, true, false}, {true, true, true}};
  const auto rows_of = [&](const RgbImage& im, const std::array<bool, 3>& asked) {
    std::vector<double> out;
    gaussian_derivative_rows(im, 0, 16.0, asked, [&](std::size_t, const std::array<const double*, 3>& v) {
      for (std::size_t o = 0; o < 3; ++o)
        if (v[o]) out.insert(out.end(), v[o], v[o] + 3 * im.width);
    });
    return out;
  };
  std::vector<std::vector<double>> fresh;
  for (const RgbImage& im : images)
    for (const std::array<bool, 3>& asked : orders) {
      std::thread t([&] { fresh.push_back(rows_of(im, asked)); });
      t.join();
    }
  for (int round = 0; round < 2; ++round)
    for (std::size_t i = 0; i < images.size(); ++i)
      for (std::size_t k = 0; k < 2; ++k) {
        const std::vector<double> again = rows_of(images[i], orders[k]);
        const std::vector<double>& f = fresh[2 * i + k];
        BOOST_TEST((again.size() == f.size() && std::memcmp(again.data(), f.data(), f.size() * sizeof(double)) == 0),
                   "round " << round << " image " << i << " orders " << k);
      }
}

BOOST_AUTO_TEST_CASE(fft_derivatives_within_their_stated_bound) {
  // The whole derivatives at σ above 11 (the FFT route along x and along y, in blocks) against
  // separable long double sums of the same kernels: f_σ within 2^-39·(Σ|g|)²·max|in| and the
  // magnitudes within 2^-37·max_pass(Σ|k_x|·Σ|k_y|)·max|in| (two passes of 2^-40 each, the
  // magnitude 1-Lipschitz with the weight 2 on f_xy;
  // docs/photographs.md "Gaussian derivatives by FFT"). Sizes that are not powers
  // of 2, blocks that end inside the image, and an image shorter than one block.
  std::mt19937 rng(4646);
  for (const auto& [w, h] : {std::pair<std::size_t, std::size_t>{37, 29}, {13, 300}, {70, 1}})
    for (double sigma : {11.5, 20.0}) {
      const RgbImage im = mondrian(rng, w, h, 0, 60000);
      const DoubleImage lin = linear_image(im, 0);
      for (DerivativeOrder order : {DerivativeOrder::zero, DerivativeOrder::first, DerivativeOrder::second}) {
        const std::vector<double> g = internal::derivative_kernel(sigma, 0), d1 = internal::derivative_kernel(sigma, 1),
                                  d2 = internal::derivative_kernel(sigma, 2);
        // (x kernel, y kernel) per component: f_σ; f_x, f_y; f_xx, f_yy, f_xy (weight 4 on its square).
        std::vector<std::pair<const std::vector<double>*, const std::vector<double>*>> parts = {{&g, &g}};
        if (order == DerivativeOrder::first) parts = {{&d1, &g}, {&g, &d1}};
        if (order == DerivativeOrder::second) parts = {{&d2, &g}, {&g, &d2}, {&d1, &d1}};
        std::vector<std::vector<long double>> comp;
        double scale = 0;
        for (const auto& [kx, ky] : parts) {
          scale = std::max(scale, l1(*kx) * l1(*ky) * 60000);
          std::vector<long double> c(3 * w * h);
          for (int ch = 0; ch < 3; ++ch) {
            std::vector<long double> tmp(w * h);
            for (std::size_t y = 0; y < h; ++y) {
              std::vector<long double> row(w);
              for (std::size_t x = 0; x < w; ++x) row[x] = lin.at(y * w + x, ch);
              const std::vector<long double> o = clamped_reference(row, *kx);
              for (std::size_t x = 0; x < w; ++x) tmp[y * w + x] = o[x];
            }
            for (std::size_t x = 0; x < w; ++x) {
              std::vector<long double> col(h);
              for (std::size_t y = 0; y < h; ++y) col[y] = tmp[y * w + x];
              const std::vector<long double> o = clamped_reference(col, *ky);
              for (std::size_t y = 0; y < h; ++y) c[3 * (y * w + x) + ch] = o[y];
            }
          }
          comp.push_back(std::move(c));
        }
        const DoubleImage d = gaussian_derivative(lin, sigma, order);
        double err = 0;
        for (std::size_t i = 0; i < 3 * w * h; ++i) {
          long double m = comp[0][i];
          if (order == DerivativeOrder::first) m = std::sqrt(comp[0][i] * comp[0][i] + comp[1][i] * comp[1][i]);
          if (order == DerivativeOrder::second)
            m = std::sqrt(comp[0][i] * comp[0][i] + comp[1][i] * comp[1][i] + 4 * comp[2][i] * comp[2][i]);
          err = std::max(err, static_cast<double>(std::fabs(d.samples[i] - m)));
        }
        const double bound = (order == DerivativeOrder::zero ? 0x1p-39 : 0x1p-37) * scale;
        BOOST_TEST(err <= bound, w << "x" << h << " sigma " << sigma << " order " << static_cast<int>(order) << ": "
                                   << err << " > " << bound);
      }
    }
}

BOOST_AUTO_TEST_CASE(neighbourhoods_beyond_the_image_take_no_edge) {
  // A neighbourhood as wide as the image or wider takes no edge colour, also where 2r + 1
  // overflows; the widest that fits takes the centre.
  std::mt19937 rng(7);
  const RgbImage im = mondrian(rng, 9, 7, 100, 8000);
  PixelRules rules;
  for (std::size_t r : {std::size_t(4), std::size_t(7), std::numeric_limits<std::size_t>::max(),
                        std::numeric_limits<std::size_t>::max() / 2, std::numeric_limits<std::size_t>::max() / 2 + 1}) {
    const ImageColours e = edge_colours(im, rules, EdgeRules{DerivativeOrder::first, 1, r});
    BOOST_TEST(e.counts.kept == 0u);
    BOOST_TEST(e.colours.empty());
  }
  BOOST_TEST(edge_colours(im, rules, EdgeRules{DerivativeOrder::first, 1, 3}).counts.kept == 3u);  // x 3..5, y 3
}

BOOST_AUTO_TEST_CASE(hull_3d_of_many_doubles_taken_in_chunks) {
  // Issue 42 (memory): more than 2^20 colours of doubles (edge colours, a pre-filtered image) have
  // their 3-D hull taken chunk by chunk; the vertices are those of the whole set's hull.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(1, 2);
  std::vector<std::array<double, 3>> colours((std::size_t(1) << 20) + 5000);
  for (auto& c : colours) c = {u(rng), u(rng), u(rng)};
  colours.push_back({0.5, 1.5, 1.5});  // a few colours beyond the cube, to be vertices
  colours.push_back({2.5, 1.5, 1.5});
  colours.push_back({1.5, 1.5, 3});
  std::vector<std::array<double, 3>> sorted = colours;
  std::sort(sorted.begin(), sorted.end());
  std::vector<Colour> want;
  for (std::size_t i : colour_hull_vertex_indices(sorted)) want.push_back({Rational(sorted[i][0]), Rational(sorted[i][1]), Rational(sorted[i][2])});
  const ImageColours got = colour_set_of_doubles(colours, ColourSet::hull_3d, PixelCounts{});
  BOOST_TEST(got.counts.colours == colours.size());
  BOOST_TEST_REQUIRE(got.colours.size() == want.size());
  for (std::size_t i = 0; i < want.size(); ++i) BOOST_TEST((got.colours[i] == want[i]));
  BOOST_TEST(got.counts.hull_vertices == want.size());
}

BOOST_AUTO_TEST_CASE(grey_edge_from_the_samples) {
  // The baselines from the 16-bit samples row by row (no image of doubles): each light is the
  // Minkowski norm of the derivative structure over the kept pixels, as written out here.
  std::mt19937 rng(11);
  const RgbImage im = mondrian(rng, 30, 20, 50, 9000);
  PixelRules rules;
  rules.black_level = 40;
  rules.dark_below = 200;
  const KeptPixels kept = kept_pixels(im, rules);
  for (Baseline b : all_baselines) {
    const GreyEdgeParameters p = baseline_parameters(b);
    const DoubleImage s = gaussian_derivative(linear_image(im, 40), p.sigma, p.order);
    std::array<double, 3> top{0, 0, 0}, e{0, 0, 0};
    for (std::size_t i = 0; i < kept.kept.size(); ++i)
      for (int c = 0; c < 3 && kept.kept[i]; ++c) top[c] = std::max(top[c], s.at(i, c));
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (std::size_t i = 0; i < kept.kept.size(); ++i)
        if (kept.kept[i]) sum += std::isfinite(p.p) ? std::pow(s.at(i, c) / top[c], p.p) : 0;
      e[c] = std::isfinite(p.p) ? top[c] * std::pow(sum, 1 / p.p) : top[c];
    }
    const double n = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    const auto got = grey_edge_estimate(im, 40, kept.kept, p);
    BOOST_TEST_REQUIRE(got.has_value());
    for (int c = 0; c < 3; ++c) BOOST_TEST(std::abs((*got)[c] - e[c] / n) < 1e-14);
  }
  BOOST_CHECK_THROW(grey_edge_estimate(im, 0, std::vector<bool>(3), GreyEdgeParameters{}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(baselines_at_sigma_0_are_the_sums_in_pixel_order_bit_for_bit) {
  // At σ = 0 the values are the linear samples, integers: the largest values and Σ v are taken in
  // integers and the terms (v/largest)^p from tables (photo/src/grey_edge.cpp). Each light must be
  // the bytes of the sums written out here in doubles, in pixel order, over the full 16-bit range,
  // a black level and a random mask.
  std::mt19937 rng(29);
  RgbImage im;
  im.width = 97, im.height = 61;
  std::uniform_int_distribution<int> sample(0, 65535), coin(0, 3);
  for (std::size_t i = 0; i < 3 * im.width * im.height; ++i) im.samples.push_back(static_cast<std::uint16_t>(sample(rng)));
  std::vector<bool> kept(im.width * im.height);
  for (std::size_t i = 0; i < kept.size(); ++i) kept[i] = coin(rng) != 0;
  const std::uint32_t black = 2048;
  for (double p : {1.0, HUGE_VAL, 6.0, 3.0, 1.5}) {
    std::array<double, 3> top{0, 0, 0}, plain{0, 0, 0}, sum{0, 0, 0}, e{};
    for (std::size_t i = 0; i < kept.size(); ++i)
      for (std::size_t c = 0; c < 3 && kept[i]; ++c) {
        const double v = im.samples[3 * i + c] > black ? double(im.samples[3 * i + c] - black) : 0.0;
        top[c] = std::max(top[c], v), plain[c] += v;
      }
    for (std::size_t i = 0; i < kept.size(); ++i)
      for (std::size_t c = 0; c < 3 && kept[i]; ++c)
        sum[c] += std::pow((im.samples[3 * i + c] > black ? double(im.samples[3 * i + c] - black) : 0.0) / top[c], p);
    for (std::size_t c = 0; c < 3; ++c) e[c] = p == 1 ? plain[c] : std::isfinite(p) ? top[c] * std::pow(sum[c], 1 / p) : top[c];
    const double length = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    const auto got = grey_edge_estimate(im, black, kept, GreyEdgeParameters{DerivativeOrder::zero, p, 0});
    BOOST_TEST_REQUIRE(got.has_value());
    for (std::size_t c = 0; c < 3; ++c) BOOST_TEST((*got)[c] == e[c] / length, "p " << p << " channel " << c);
  }
}

BOOST_AUTO_TEST_CASE(baselines_together_are_each_alone) {
  // The benchmark asks for its baselines together (one sweep per σ for the largest values, one
  // for the sums): each light is bit for bit the one asked alone, in the order asked, whatever
  // the mix of σ, orders and norms, the tiny σ of the Gaussian's tails included.
  std::mt19937 rng(12);
  const RgbImage im = mondrian(rng, 33, 21, 50, 60000);
  PixelRules rules;
  rules.black_level = 40;
  const KeptPixels kept = kept_pixels(im, rules);
  std::vector<GreyEdgeParameters> all;
  for (Baseline b : all_baselines) all.push_back(baseline_parameters(b));
  all.push_back({DerivativeOrder::second, 6, 2});
  all.push_back({DerivativeOrder::first, HUGE_VAL, 2});
  all.push_back({DerivativeOrder::zero, 2, 2});
  all.push_back({DerivativeOrder::first, 1, 0.03});
  all.push_back({DerivativeOrder::second, 1, 12});
  const auto together = grey_edge_estimates(im, 40, kept.kept, all);
  BOOST_TEST_REQUIRE(together.size() == all.size());
  for (std::size_t k = 0; k < all.size(); ++k) {
    const auto alone = grey_edge_estimate(im, 40, kept.kept, all[k]);
    BOOST_TEST_REQUIRE(together[k].has_value() == alone.has_value());
    if (alone) BOOST_TEST(std::memcmp(together[k]->data(), alone->data(), sizeof(*alone)) == 0, "baseline " << k);
  }
  // Refused as one at a time: p < 1 before any work, a NaN σ or a derivative at σ = 0.
  BOOST_CHECK_THROW(grey_edge_estimates(im, 40, kept.kept, {all[0], {DerivativeOrder::zero, 0.5, 0}}),
                    std::invalid_argument);
  BOOST_CHECK_THROW(grey_edge_estimates(im, 40, kept.kept, {all[0], {DerivativeOrder::first, 1, std::nan("")}}),
                    std::invalid_argument);
  BOOST_CHECK_THROW(grey_edge_estimates(im, 40, kept.kept, {all[0], {DerivativeOrder::first, 1, 0}}),
                    std::invalid_argument);
  BOOST_TEST(grey_edge_estimates(im, 40, kept.kept, {}).empty());
}

BOOST_AUTO_TEST_CASE(grey_edge_of_structure_in_the_tails) {
  // fuzz_edge_colours' findings (corpus/edge_colours/finding_grey_edge_subnormal_structure): at
  // σ = 0.026 the Gaussian's tails are subnormal weights; the one kept pixel (black, below a
  // saturated one) has a smoothed colour of about 1e-318, whose squares underflowed, so the
  // light's length was 0 and the light infinite or NaN. Now it is the saturated pixel's direction.
  RgbImage im;
  im.width = 1, im.height = 2;
  im.samples = {16321, 248, 92, 0, 0, 0};
  PixelRules rules;
  rules.saturation = 11776;
  const KeptPixels kept = kept_pixels(im, rules);
  BOOST_TEST_REQUIRE(kept.counts.kept == 1u);
  const auto e = grey_edge_estimate(im, 0, kept.kept, GreyEdgeParameters{DerivativeOrder::zero, 1, 0.026});
  BOOST_TEST_REQUIRE(e.has_value());
  const double n = std::sqrt(16321.0 * 16321 + 248 * 248 + 92 * 92);
  BOOST_TEST(std::abs((*e)[0] - 16321 / n) < 1e-12);
  BOOST_TEST(std::abs((*e)[1] - 248 / n) < 1e-12);
  BOOST_TEST(std::abs((*e)[2] - 92 / n) < 1e-12);
  // The second finding (corpus/edge_colours/finding_grey_edge_subnormal_light_imprecise): with
  // several such pixels and p = 2 the light top·‖v/top‖ itself was subnormal, so rounded to about
  // 1e-7 of its size. Two saturated pixels, each above a black kept one: the light is the
  // Euclidean norm of their colours channel by channel, to the last bits.
  RgbImage two = im;
  two.height = 4;
  two.samples = {16321, 248, 92, 0, 0, 0, 0, 0, 0, 300, 12000, 4000};
  const KeptPixels kept_two = kept_pixels(two, rules);
  BOOST_TEST_REQUIRE(kept_two.counts.kept == 2u);
  const auto e2 = grey_edge_estimate(two, 0, kept_two.kept, GreyEdgeParameters{DerivativeOrder::zero, 2, 0.026});
  BOOST_TEST_REQUIRE(e2.has_value());
  const std::array<double, 3> norm{std::hypot(16321.0, 300.0), std::hypot(248.0, 12000.0), std::hypot(92.0, 4000.0)};
  const double n2 = std::sqrt(norm[0] * norm[0] + norm[1] * norm[1] + norm[2] * norm[2]);
  for (int c = 0; c < 3; ++c) BOOST_TEST(std::abs((*e2)[c] - norm[c] / n2) < 1e-12);
  // The same in the 1st order at σ = 0.03 (tails about 1e-241, normal numbers whose squares
  // underflow): the centre of a 3 × 3 image whose middle row is flat and whose outer rows rise by
  // (400, 300, 100) from left to right has f_x of about 1e-238 times that, and f_y = 0.
  RgbImage rows;
  rows.width = 3, rows.height = 3;
  for (std::size_t y = 0; y < 3; ++y)
    for (std::size_t x = 0; x < 3; ++x)
      for (int c = 0; c < 3; ++c)
        rows.samples.push_back(static_cast<std::uint16_t>(y == 1 ? 1000 : 1000 + x * (c == 0 ? 200 : c == 1 ? 150 : 50)));
  std::vector<bool> centre(9, false);
  centre[4] = true;
  const auto g = grey_edge_estimate(rows, 0, centre, GreyEdgeParameters{DerivativeOrder::first, 1, 0.03});
  BOOST_TEST_REQUIRE(g.has_value());
  const double m = std::sqrt(400.0 * 400 + 300 * 300 + 100 * 100);
  BOOST_TEST(std::abs((*g)[0] - 400 / m) < 1e-12);
  BOOST_TEST(std::abs((*g)[1] - 300 / m) < 1e-12);
  BOOST_TEST(std::abs((*g)[2] - 100 / m) < 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
