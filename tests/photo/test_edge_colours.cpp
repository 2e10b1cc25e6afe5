// Edge-based gamut mapping (gmcc::photo, issue 26 item 3): edge colours obey the diagonal model
// exactly (a power-of-2 map on the image maps its edge colours alike, bit for bit), the
// neighbourhood rule drops the edges next to a dropped pixel, the refusals, and the joint
// estimate: one type is the single-type estimate, and a scene's true map lies in the joint F3 of
// its pixel and edge gamuts.
#include <gmcc/photo/edge_colours.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/learn_canonical.h>
#include <gmcc/input/image_derivatives.h>
#include <gmcc/numerics/interrupt.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

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

BOOST_AUTO_TEST_SUITE_END()
