// The hull colour sets by the sieve (image_hull_sets.h, colour_hull_sieve.h): the sieve's
// "strictly inside" against an independent exact test (every supporting plane through three
// corners, in 64-bit integers), the extreme colours against a brute-force search, and the hull
// sets against image_colour_sets (the sort of every distinct colour) on noisy, tied, flat and
// masked images, with and without a blue channel of 0.
#include <gmcc/geometry/colour_hull_sieve.h>
#include <gmcc/photo/image_hull_sets.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/validation/mondrian.h>

#include <boost/test/unit_test.hpp>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

using namespace gmcc;

namespace {

using Int3 = std::array<std::int64_t, 3>;

// The planes n·x <= d through three corners with every corner on their side (the supporting
// planes of conv(corners)); none when the corners are flat.
std::vector<std::pair<Int3, std::int64_t>> supporting_planes(const std::vector<Int3>& c) {
  std::vector<std::pair<Int3, std::int64_t>> out;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j)
      for (std::size_t k = j + 1; k < c.size(); ++k) {
        const Int3 u{c[j][0] - c[i][0], c[j][1] - c[i][1], c[j][2] - c[i][2]};
        const Int3 v{c[k][0] - c[i][0], c[k][1] - c[i][1], c[k][2] - c[i][2]};
        Int3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
        const auto dot = [&](const Int3& p) { return n[0] * p[0] + n[1] * p[1] + n[2] * p[2]; };
        const std::int64_t d = dot(c[i]);
        bool below = true, above = true, strict = false;
        for (const Int3& p : c) {
          below = below && dot(p) <= d, above = above && dot(p) >= d;
          strict = strict || dot(p) != d;
        }
        if (!strict) continue;  // every corner on the plane: flat
        if (above) n = {-n[0], -n[1], -n[2]};
        if (below || above) out.push_back({n, below ? d : -d});
      }
  return out;
}

bool strictly_inside(const std::vector<std::pair<Int3, std::int64_t>>& planes, const Int3& p) {
  if (planes.empty()) return false;
  for (const auto& [n, d] : planes)
    if (!(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] < d)) return false;
  return true;
}

std::array<double, 3> as_doubles(const Int3& p) { return {double(p[0]), double(p[1]), double(p[2])}; }

RgbImage noisy(std::mt19937& rng, std::size_t w, std::size_t h, unsigned lo, unsigned hi) {
  RgbImage im;
  im.width = w, im.height = h, im.bits = 16;
  std::uniform_int_distribution<unsigned> v(lo, hi);
  for (std::size_t i = 0; i < 3 * w * h; ++i) im.samples.push_back(static_cast<std::uint16_t>(v(rng)));
  return im;
}

// image_hull_sets against image_colour_sets: the same colours in the same order, the same hull
// vertex and kept counts.
void check_same(const RgbImage& im, const PixelRules& rules, const std::vector<ColourSet>& sets, const char* what) {
  const KeptPixels kept = kept_pixels(im, rules);
  const std::vector<ImageColours> sieved = image_hull_sets(im, rules, kept, sets);
  const std::vector<ImageColours> sorted = image_colour_sets(im, rules, kept, sets);
  BOOST_TEST_REQUIRE(sieved.size() == sorted.size(), what);
  for (std::size_t k = 0; k < sets.size(); ++k) {
    BOOST_TEST((sieved[k].set == sorted[k].set), what);
    BOOST_TEST((sieved[k].colours == sorted[k].colours), what << " set " << to_string(sets[k]));
    BOOST_TEST(sieved[k].counts.hull_vertices == sorted[k].counts.hull_vertices, what);
    BOOST_TEST(sieved[k].counts.kept == sorted[k].counts.kept, what);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(image_hull_sets_suite)

BOOST_AUTO_TEST_CASE(sieve_is_strict_interior_exactly) {
  // Random corners (few, many, at the top of the 16-bit range, flat), and points everywhere in
  // their box and just beyond: random ones, the corners themselves, edge midpoints, the
  // centroid, and the sieve's grid points (where a cell's corners are tested).
  std::mt19937 rng(46);
  for (int round = 0; round < 60; ++round) {
    const unsigned top = round % 3 == 0 ? 65535 : round % 3 == 1 ? 40 : 3000;
    std::uniform_int_distribution<unsigned> v(round % 5 == 0 ? top - 30 : 0, top);
    std::vector<Int3> c(4 + round % 23);
    for (Int3& p : c) p = {v(rng), v(rng), v(rng)};
    if (round % 7 == 3)
      for (Int3& p : c) p[2] = std::min<std::int64_t>(top, p[0] / 2 + p[1] / 3);  // not flat: rounding
    if (round % 7 == 5)
      for (Int3& p : c) p[2] = p[0];  // flat: the plane b = r
    std::vector<std::array<double, 3>> corners;
    for (const Int3& p : c) corners.push_back(as_doubles(p));
    const ColourHullSieve sieve(corners);
    const auto planes = supporting_planes(c);
    std::vector<Int3> probes = c;
    for (std::size_t i = 0; i + 1 < c.size(); ++i)
      probes.push_back({(c[i][0] + c[i + 1][0]) / 2, (c[i][1] + c[i + 1][1]) / 2, (c[i][2] + c[i + 1][2]) / 2});
    std::uniform_int_distribution<unsigned> any(0, std::min(65535u, top + 2));
    for (int k = 0; k < 3000; ++k) probes.push_back({any(rng), any(rng), any(rng)});
    Int3 sum{0, 0, 0};
    for (const Int3& p : c)
      for (int k = 0; k < 3; ++k) sum[k] += p[k];
    probes.push_back({sum[0] / std::int64_t(c.size()), sum[1] / std::int64_t(c.size()), sum[2] / std::int64_t(c.size())});
    int wrong = 0, inside = 0;
    for (const Int3& p : probes) {
      const bool expected = strictly_inside(planes, p);
      inside += expected;
      wrong += sieve.strictly_inside(as_doubles(p)) != expected;
    }
    BOOST_TEST(wrong == 0, "round " << round << ": " << wrong << " of " << probes.size() << " wrong");
    if (round % 7 == 5) BOOST_TEST((inside == 0 && sieve.facets() == 0));
  }
  BOOST_CHECK_THROW(ColourHullSieve({{0, 0, 0.5}}), std::invalid_argument);
  BOOST_CHECK_THROW(ColourHullSieve({{65536, 0, 0}}), std::invalid_argument);
  BOOST_CHECK_THROW(ColourHullSieve({{-1, 0, 0}}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(extreme_colours_by_brute_force) {
  // The first colour of largest and of smallest v·c for each of the 13 directions, by a search
  // over every colour and direction written out here.
  std::mt19937 rng(7);
  std::uniform_int_distribution<unsigned> v(0, 9);  // many ties
  std::vector<std::array<double, 3>> colours(500);
  for (auto& c : colours) c = {double(v(rng)), double(v(rng)), double(v(rng))};
  ExtremeColours extremes;
  BOOST_TEST(extremes.indices().empty());
  for (std::size_t i = 0; i < colours.size(); ++i) extremes.add(i, colours[i]);
  std::vector<std::size_t> expected;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        if (x == 0 && y == 0 && z == 0) continue;
        std::size_t best = 0;
        for (std::size_t i = 1; i < colours.size(); ++i)
          if (x * colours[i][0] + y * colours[i][1] + z * colours[i][2] >
              x * colours[best][0] + y * colours[best][1] + z * colours[best][2])
            best = i;
        expected.push_back(best);
      }
  std::sort(expected.begin(), expected.end());
  expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
  BOOST_TEST(extremes.indices() == expected, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(hull_sets_are_the_sorted_colour_sets) {
  std::mt19937 rng(45);
  const std::vector<std::vector<ColourSet>> orders = {
      {ColourSet::hull_3d, ColourSet::hull}, {ColourSet::hull}, {ColourSet::hull_3d}, {ColourSet::hull, ColourSet::hull_3d}};
  PixelRules plain, dark;
  dark.black_level = 200;
  dark.dark_below = 300;
  for (const auto& sets : orders) {
    check_same(noisy(rng, 300, 200, 1, 65535), plain, sets, "noise over the whole range");
    check_same(noisy(rng, 97, 61, 1000, 1040), dark, sets, "noise in a small cube, many ties");
    check_same(noisy(rng, 1, 1, 5, 9), plain, sets, "one pixel");
    MondrianSpec spec;
    spec.width = 257, spec.height = 131, spec.noise = 300;
    const std::vector<Colour> chips = {{Rational(1), Rational(2), Rational(3)}, {Rational(3), Rational(1), Rational(1)},
                                       {Rational(2), Rational(2), Rational(1)}, {Rational(1), Rational(3), Rational(2)}};
    check_same(render_mondrian(chips, spec).image, dark, sets, "noisy Mondrian");
    // Each special case at two sizes: at most 2^15 kept pixels the exact hull takes every kept
    // colour, above it the sieves of slabs of red choose (image_hull_sets.cpp, candidate_keys).
    for (const std::size_t scale : {1, 4}) {
      const std::size_t w = 64 * scale, h = 60 * scale;
      RgbImage flat = noisy(rng, w, h, 1, 50000);
      for (std::size_t i = 0; i < flat.samples.size(); i += 3) flat.samples[i + 2] = flat.samples[i];  // b = r
      check_same(flat, plain, sets, "flat colours (b = r)");
      RgbImage line = noisy(rng, w, h, 1, 60000);
      for (std::size_t i = 0; i < line.samples.size(); i += 3) line.samples[i + 1] = line.samples[i + 2] = line.samples[i];
      check_same(line, plain, sets, "grey colours (a segment)");
      RgbImage blue_zero = noisy(rng, w, h, 0, 65535);
      blue_zero.samples[2] = 0;  // a colour without chromaticity
      check_same(blue_zero, plain, sets, "a blue channel of 0");
      // Colours with b = 0 that hide a vertex of conv(S+) inside the image's hull: P = (1000, 500,
      // 1000) has the largest r/b of the colours with a chromaticity, but lies inside the hull of
      // the others with (3000, g, 0) and black (masked pixels kept): the lifts must still have it.
      RgbImage hidden = noisy(rng, w, h, 0, 0);
      std::uniform_int_distribution<unsigned> r(0, 999), g(0, 1000), b(1001, 2000);
      for (std::size_t i = 0; i < w * h; ++i) {
        const std::array<unsigned, 3> c = i % 7 == 0   ? std::array<unsigned, 3>{3000, unsigned(i % 3) * 500, 0}
                                          : i % 11 == 0 ? std::array<unsigned, 3>{0, 0, 0}
                                          : i == 5      ? std::array<unsigned, 3>{1000, 500, 1000}
                                                        : std::array<unsigned, 3>{r(rng), g(rng), b(rng)};
        for (int k = 0; k < 3; ++k) hidden.samples[3 * i + k] = static_cast<std::uint16_t>(c[k]);
      }
      check_same(hidden, plain, sets, "a vertex of the chromatic colours' hull hidden by colours with b = 0");
      PixelRules masked = plain;
      masked.keep.assign(w * h, false);
      for (std::size_t i = 0; i < masked.keep.size(); ++i) masked.keep[i] = i % 3 != 0;  // two in three
      check_same(blue_zero, masked, sets, "a mask");
    }
  }
  // Other sets and binning: image_colour_sets itself, counts and all.
  RgbImage im = noisy(rng, 40, 30, 1, 4000);
  PixelRules binned;
  binned.bin = 2;
  const KeptPixels kept = kept_pixels(im, binned);
  const auto a = image_hull_sets(im, binned, kept, {ColourSet::hull_3d});
  const auto b = image_colour_sets(im, binned, kept, {ColourSet::hull_3d});
  BOOST_TEST((a.front().colours == b.front().colours && a.front().counts.colours == b.front().counts.colours));
  const auto d = image_hull_sets(im, PixelRules{}, kept_pixels(im, PixelRules{}), {ColourSet::distinct});
  BOOST_TEST(d.front().counts.colours == d.front().colours.size());
}

BOOST_AUTO_TEST_SUITE_END()
