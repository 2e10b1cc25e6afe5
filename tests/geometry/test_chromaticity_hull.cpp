#include "../test_support.h"

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/chromaticity_hull.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace gmcc;
using gmcc::test::Rng;

namespace {
// The reference: exact chromaticities (rationals), then CGAL's exact hull.
ConvexSet2 reference(const std::vector<std::array<double, 3>>& colours) {
  std::vector<Colour> exact;
  for (const auto& c : colours)
    exact.push_back({rational_from_double(c[0]), rational_from_double(c[1]), rational_from_double(c[2])});
  return convex_hull(perspective_chromaticities(exact, NonPositiveBluePolicy::drop).points);
}
}  // namespace

BOOST_AUTO_TEST_SUITE(chromaticity_hull_filtered)

BOOST_AUTO_TEST_CASE(equals_the_exact_hull_on_random_colours) {
  Rng rng(2026);
  std::uniform_real_distribution<double> channel(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<std::array<double, 3>> colours(10 + 50 * trial);
    for (auto& c : colours) c = {channel(rng), channel(rng), channel(rng) + 0.01};
    if (trial % 5 == 0) colours.push_back({0.5, 0.5, 0.0});  // no chromaticity: dropped
    const ChromaticityHull h = chromaticity_hull(colours);
    BOOST_TEST(h.hull == reference(colours));
    BOOST_TEST(h.dropped == (trial % 5 == 0 ? 1u : 0u));
  }
}

// Nearly collinear and nearly coincident chromaticities, one ulp apart: the double filter
// cannot decide these and the exact fallback must.
BOOST_AUTO_TEST_CASE(ulp_level_degeneracies_are_decided_exactly) {
  std::vector<std::array<double, 3>> colours;
  for (int k = 0; k < 200; ++k) {
    const double t = 1 + k * 0x1p-20;
    colours.push_back({t, 2 * t, 1.0});                                   // on the line y = 2x
    colours.push_back({std::nextafter(t, 2.0), 2 * t, 1.0});              // one ulp off it
    colours.push_back({3 * t, 6 * t, 3.0});                               // the same point again
  }
  BOOST_TEST(chromaticity_hull(colours).hull == reference(colours));
  // All on one line: a segment; all one chromaticity: a point.
  std::vector<std::array<double, 3>> line{{1, 2, 1}, {2, 4, 2}, {3, 6, 1}, {0.5, 1, 0.25}};
  BOOST_TEST(chromaticity_hull(line).hull == reference(line));
  BOOST_TEST(chromaticity_hull(line).hull.kind == ConvexKind::segment);
  std::vector<std::array<double, 3>> same{{1, 2, 1}, {2, 4, 2}, {0.25, 0.5, 0.25}};
  BOOST_TEST(chromaticity_hull(same).hull.kind == ConvexKind::point);
  BOOST_TEST(chromaticity_hull({}).hull.kind == ConvexKind::empty);
  BOOST_CHECK_THROW(chromaticity_hull({{1, -1, 1}}), std::invalid_argument);
  BOOST_CHECK_THROW(chromaticity_hull({{1, NAN, 1}}), std::invalid_argument);
}

// Scaling a colour by a power of 2 leaves its chromaticity and the hull unchanged, however far:
// colours near one line, each scaled by 2^e for e up to ±1000, where the double predicates'
// products leave the normal range (their bounds are relative: tests/numerics/test_filter_bounds.cpp),
// give the reference's hull.
BOOST_AUTO_TEST_CASE(extreme_scales_give_the_same_hull) {
  std::mt19937_64 gen(44);
  std::uniform_real_distribution<double> unit(0.5, 1.0);
  std::uniform_int_distribution<int> scale(-1000, 1000), nudge(-2, 2);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::array<double, 3>> colours, scaled;
    const double slope = unit(gen);
    for (int k = 0; k < 12; ++k) {
      const double x = unit(gen) * 4, b = unit(gen);
      double g = slope * x * b;  // (x·b, g, b): chromaticity near the line y = slope·x
      for (int n = nudge(gen); n != 0; n += n > 0 ? -1 : 1) g = std::nextafter(g, n > 0 ? 2.0 : 0.0);
      colours.push_back({x * b, g, b});
      const int e = trial % 2 ? scale(gen) : scale(gen) / 2;
      scaled.push_back({std::ldexp(x * b, e), std::ldexp(g, e), std::ldexp(b, e)});
    }
    BOOST_TEST_REQUIRE((chromaticity_hull(scaled).hull == reference(colours)), "trial " << trial);
  }
}

// The integer route (image pixels) against the reference: small channel ranges give many equal
// chromaticities, ties in x and collinear triples; wide ones the general case; b = 0 is dropped.
BOOST_AUTO_TEST_CASE(integer_colours_agree_with_the_reference) {
  std::mt19937_64 gen(1123);
  for (int trial = 0; trial < 400; ++trial) {
    const unsigned range = trial % 4 == 0 ? 4 : trial % 4 == 1 ? 20 : trial % 4 == 2 ? 300 : 65535;
    std::uniform_int_distribution<unsigned> channel(0, range);
    const std::size_t n = 1 + static_cast<std::size_t>(trial % 50) * 7;
    std::vector<std::array<std::uint16_t, 3>> ints;
    std::vector<std::array<double, 3>> doubles;
    std::size_t zero_blue = 0;
    for (std::size_t i = 0; i < n; ++i) {
      std::array<std::uint16_t, 3> c{std::uint16_t(channel(gen)), std::uint16_t(channel(gen)),
                                     std::uint16_t(channel(gen))};
      zero_blue += c[2] == 0;
      ints.push_back(c);
      doubles.push_back({double(c[0]), double(c[1]), double(c[2])});
    }
    const ChromaticityHull h = chromaticity_hull_of_pixels(ints);
    BOOST_TEST(h.dropped == zero_blue);
    const ConvexSet2 want = reference(doubles);
    BOOST_TEST_REQUIRE((h.hull.kind == want.kind), "trial " << trial);
    BOOST_TEST_REQUIRE((h.hull.vertices == want.vertices), "trial " << trial);
  }
  // Extremes: channels at 65535 and 1 (the largest determinants), and all on one line.
  const ChromaticityHull extreme =
      chromaticity_hull_of_pixels(std::vector<std::array<std::uint16_t, 3>>{
          {65535, 1, 1}, {1, 65535, 1}, {1, 1, 65535}, {65535, 65535, 1}});
  BOOST_TEST((extreme.hull.vertices ==
              reference({{65535, 1, 1}, {1, 65535, 1}, {1, 1, 65535}, {65535, 65535, 1}}).vertices));
  const ChromaticityHull line = chromaticity_hull_of_pixels(
      std::vector<std::array<std::uint16_t, 3>>{{1, 1, 1}, {2, 2, 1}, {3, 3, 1}, {6, 6, 2}});
  BOOST_TEST((line.hull.kind == ConvexKind::segment));
}

// Many pixels (the octagon prefilter of Akl & Toussaint drops most before the sort): clouds of
// noisy colours, as in a chart image, and points on a few lines (ties with the octagon's edges,
// its corners repeated); the same hull as the reference either way.
BOOST_AUTO_TEST_CASE(integer_colours_many_points_agree_with_the_reference) {
  std::mt19937_64 gen(20261125);
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<std::array<std::uint16_t, 3>> ints;
    std::vector<std::array<double, 3>> doubles;
    std::uniform_int_distribution<int> centre(200, 60000), noise(-150, 150), pick(0, 5);
    std::array<std::array<int, 3>, 6> cells;
    for (auto& c : cells) c = {centre(gen), centre(gen), centre(gen)};
    for (int i = 0; i < 5000; ++i) {
      std::array<std::uint16_t, 3> c;
      if (trial % 3 == 2) {  // on lines through few chromaticities: many exact ties
        const int k = 1 + pick(gen);
        const auto& base = cells[static_cast<std::size_t>(pick(gen))];
        c = {std::uint16_t(base[0] / 8 * k), std::uint16_t(base[1] / 8 * k), std::uint16_t(base[2] / 8 * k)};
      } else {
        const auto& base = cells[static_cast<std::size_t>(pick(gen))];
        for (int ch = 0; ch < 3; ++ch)
          c[static_cast<std::size_t>(ch)] = std::uint16_t(std::clamp(base[static_cast<std::size_t>(ch)] + noise(gen), 0, 65535));
      }
      ints.push_back(c);
      doubles.push_back({double(c[0]), double(c[1]), double(c[2])});
    }
    const ChromaticityHull h = chromaticity_hull_of_pixels(ints);
    const ConvexSet2 want = reference(doubles);
    BOOST_TEST_REQUIRE((h.hull.kind == want.kind), "trial " << trial);
    BOOST_TEST_REQUIRE((h.hull.vertices == want.vertices), "trial " << trial);
  }
}

BOOST_AUTO_TEST_SUITE_END()
