// Pixel selection (image_pixels.h): the pixel rules against hand-computed counts and an
// independent point-in-polygon test, the colour sets (distinct, 2-D and 3-D hulls) against
// direct computations, floating-point images against the integer rules, the in-place key sort
// against std::sort, and the Gaussian pre-filter.
#include <gmcc/input/image_file.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/validation/mondrian.h>

#include "internal/sort_colours.h"
#include "internal/sort_keys.h"

#include "../test_support.h"

#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <functional>
#include <iterator>
#include <random>
#include <set>
#include <string>

using namespace gmcc;

namespace {

using gmcc::test::ramp;

// Independent of polygon_cover: is p inside the polygon or on its boundary?
// (exact; even–odd by a ray to +x, with points on an edge decided first)
bool inside_or_on(const std::vector<Point2>& poly, const Point2& p) {
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = poly[i];
    const Point2& b = poly[(i + 1) % n];
    const Rational cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    if (cross == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
        std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y))
      return true;
  }
  bool in = false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = poly[i];
    const Point2& b = poly[(i + 1) % n];
    if ((a.y > p.y) != (b.y > p.y)) {
      const Rational x = a.x + (b.x - a.x) * (p.y - a.y) / (b.y - a.y);
      if (p.x < x) in = !in;
    }
  }
  return in;
}

Rational quarter(int k) {
  Rational q(k, 4);
  q.canonicalize();  // gmcc's rationals are always in lowest terms
  return q;
}

std::vector<Point2> square(Rational x0, Rational y0, Rational x1, Rational y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(image_pixels)

BOOST_AUTO_TEST_CASE(polygon_work_is_bounded) {
  const RgbImage tall = ramp(2, 1024, 16);
  PixelRules rules;
  std::vector<Point2> zigzag;  // every edge spans every row: n · 1024 crossings
  const std::size_t n = max_polygon_work / 1024 + 1;
  for (std::size_t k = 0; k < n; ++k)
    zigzag.push_back({Rational(static_cast<long>(k), 4000), Rational(k % 2 ? 100000 : -3)});
  BOOST_TEST(polygon_work(zigzag, 1024) == n + (n - 1) * 1024);  // the closing edge is level at y = -3
  rules.exclude_polygons = {zigzag};
  try {
    image_colours(tall, rules);
    BOOST_FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(std::string(e.what()).find("more than 2^20 exact edge crossings") != std::string::npos, e.what());
  }
  // Two polygons that fit each but not together are refused too; a chart's four corners are not.
  rules.exclude_polygons = {std::vector<Point2>(zigzag.begin(), zigzag.begin() + n / 2 + 1),
                            std::vector<Point2>(zigzag.begin(), zigzag.begin() + n / 2 + 1)};
  BOOST_CHECK_THROW(image_colours(tall, rules), std::invalid_argument);
  rules.exclude_polygons = {square(0, 0, 1, 512)};
  BOOST_TEST(image_colours(tall, rules).counts.masked == 512u);
  // Many vertices whose edges span few rows each cost little and are accepted: 4000 vertices on a
  // circle across the 1024 rows, each pixel of every 16th row as the direct test says.
  std::vector<Point2> circle;
  for (int k = 0; k < 4000; ++k) {
    const double t = 2 * 3.141592653589793 * k / 4000;
    circle.push_back({Rational(1) + Rational(std::cos(t)), Rational(512) + Rational(500 * std::sin(t))});
  }
  BOOST_TEST(polygon_work(circle, 1024) < max_polygon_work / 100);
  rules.exclude_polygons = {circle};
  const std::vector<bool> cover = polygon_cover(circle, 2, 1024);
  for (std::size_t y = 0; y < 1024; y += 16)
    for (std::size_t x = 0; x < 2; ++x)
      BOOST_TEST(cover[y * 2 + x] == inside_or_on(circle, {Rational(2 * static_cast<long>(x) + 1, 2),
                                                           Rational(2 * static_cast<long>(y) + 1, 2)}),
                 "pixel " << x << "," << y);
  const std::size_t masked = static_cast<std::size_t>(std::count(cover.begin(), cover.end(), true));
  BOOST_TEST(masked > 1000u);
  BOOST_TEST(image_colours(tall, rules).counts.masked == masked);
}

BOOST_AUTO_TEST_CASE(polygon_cover_hand_counts) {
  // Centres (i + ½, j + ½): the square [1,3]² holds 4 of them; [½, 5/2]² has 9
  // on or inside.
  auto count = [](const std::vector<bool>& v) { return std::count(v.begin(), v.end(), true); };
  BOOST_TEST(count(polygon_cover(square(1, 1, 3, 3), 4, 4)) == 4);
  BOOST_TEST(count(polygon_cover(
                 square(Rational(1, 2), Rational(1, 2), Rational(5, 2), Rational(5, 2)), 4, 4)) ==
             9);
  // A diamond whose corners are centres: (2½,½), (4½,2½), (2½,4½), (½,2½)
  // covers 1+3+5+3+1.
  const std::vector<Point2> diamond = {{Rational(5, 2), Rational(1, 2)},
                                       {Rational(9, 2), Rational(5, 2)},
                                       {Rational(5, 2), Rational(9, 2)},
                                       {Rational(1, 2), Rational(5, 2)}};
  BOOST_TEST(count(polygon_cover(diamond, 6, 6)) == 13);
  // Partly outside the image: only the pixels inside count.
  BOOST_TEST(count(polygon_cover(square(-10, -10, 2, 1), 4, 4)) == 2);
  BOOST_CHECK_THROW(polygon_cover({{0, 0}, {1, 1}}, 4, 4), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(polygon_cover_agrees_with_a_direct_test) {
  std::mt19937_64 gen(20261123);
  std::uniform_int_distribution<int> coord(-4,
                                           28);  // in quarters: -1 to 7 pixels
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Point2> poly;
    const int n = 3 + trial % 6;  // convex or not, maybe self-intersecting: even–odd either way
    for (int k = 0; k < n; ++k) poly.push_back({quarter(coord(gen)), quarter(coord(gen))});
    const std::vector<bool> cover = polygon_cover(poly, 6, 6);
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 6; ++x) {
        const Point2 c{Rational(2 * x + 1, 2), Rational(2 * y + 1, 2)};
        BOOST_TEST_REQUIRE(cover[static_cast<std::size_t>(y * 6 + x)] == inside_or_on(poly, c),
                           "trial " << trial << " pixel " << x << "," << y);
      }
  }
}

BOOST_AUTO_TEST_CASE(pixel_rules_hand_counts) {
  // 4×2 image; pixel values chosen by hand.
  RgbImage im;
  im.width = 4;
  im.height = 2;
  im.samples = {100, 200, 300, 100, 200, 300, 1000, 5,  5,  50,  60,  70,    // row 0
                999, 999, 999, 20,  20,  20,  30,   10, 10, 100, 200, 300};  // row 1
  PixelRules rules;
  rules.black_level = 20;
  rules.saturation = 999;  // channel >= 999: pixels (2,0) and (0,1)
  ImageColours out = image_colours(im, rules);
  BOOST_TEST(out.counts.pixels == 8u);
  BOOST_TEST(out.counts.masked == 0u);
  BOOST_TEST(out.counts.saturated == 2u);
  BOOST_TEST(out.counts.kept == 6u);
  // Distinct after the black level, in increasing order: (0,0,0), (10,0,0), (30,40,50),
  // (80,180,280) (twice in the image).
  BOOST_TEST(out.counts.colours == 4u);
  BOOST_TEST((out.colours[0] == Colour{0, 0, 0}));
  BOOST_TEST((out.colours[1] == Colour{10, 0, 0}));
  BOOST_TEST((out.colours[3] == Colour{80, 180, 280}));
  // The hull's colour set: of the chromaticities (30/50, 40/50) and (80/280, 180/280) (b = 0
  // for the other two), a segment, whose two ends are returned as (x, y, 1).
  PixelRules hull_rules = rules;
  hull_rules.colour_set = ColourSet::hull;
  const ImageColours hull = image_colours(im, hull_rules);
  BOOST_TEST(hull.counts.colours == 4u);
  BOOST_TEST(hull.counts.no_chromaticity == 2u);
  BOOST_TEST(hull.counts.hull_vertices == 2u);
  BOOST_TEST_REQUIRE(hull.colours.size() == 2u);
  BOOST_TEST((hull.colours[0] == Colour{Rational(2, 7), Rational(9, 14), 1}));
  BOOST_TEST((hull.colours[1] == Colour{Rational(3, 5), Rational(4, 5), 1}));
  // Mask the first column by polygon and pixel (3,1) by the mask image.
  rules.exclude_polygons = {square(0, 0, 1, 2)};
  rules.keep.assign(8, true);
  rules.keep[7] = false;
  out = image_colours(im, rules);
  BOOST_TEST(out.counts.masked == 3u);
  BOOST_TEST(out.counts.saturated == 1u);  // (2,0); (0,1) was masked first
  BOOST_TEST(out.counts.kept == 4u);
  // 2×2 binning without masks: block 0 keeps (0,0),(1,0),(1,1) → (80+80+0,
  // 180+180+0, 280+280+0)/3; block 1 keeps (3,0),(2,1),(3,1) → ((30+10+80)/3,
  // (40+0+180)/3, (50+0+280)/3).
  rules = PixelRules{};
  rules.black_level = 20;
  rules.saturation = 999;
  rules.bin = 2;
  out = image_colours(im, rules);
  BOOST_TEST(out.counts.colours == 2u);
  BOOST_TEST((out.colours[1] == Colour{Rational(160, 3), 120, Rational(560, 3)}));
  BOOST_TEST((out.colours[0] == Colour{40, Rational(220, 3), 110}));
  rules.bin = 0;
  BOOST_CHECK_THROW(image_colours(im, rules), std::invalid_argument);
  rules.bin = 1;
  rules.keep.assign(3, true);
  BOOST_CHECK_THROW(image_colours(im, rules), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(mondrian_is_what_it_says) {
  const std::vector<Colour> colours = {{1, 2, 3}, {Rational(1, 3), 1, 1}, {6, 5, 4}, {0, 1, 1}};
  MondrianSpec spec;
  spec.width = 40;
  spec.height = 30;
  spec.columns = 4;
  spec.rows = 3;
  spec.black_level = 100;
  spec.peak = 6000;
  spec.saturated_pixels = 5;
  spec.seed = 7;
  const Mondrian m = render_mondrian(colours, spec);
  BOOST_TEST(render_mondrian(colours, spec).image.samples == m.image.samples);  // reproducible
  spec.seed = 8;
  BOOST_TEST(render_mondrian(colours, spec).surfaces != m.surfaces);
  // The brightest channel shown is black + peak; every cell's samples are black
  // + round(c·scale).
  Rational brightest = 0;
  for (std::size_t s : m.surfaces)
    brightest = std::max({brightest, colours[s].r, colours[s].g, colours[s].b});
  const Rational scale = Rational(6000) / brightest;
  std::uint64_t saturated = 0;
  for (std::size_t y = 0; y < 30; ++y)
    for (std::size_t x = 0; x < 40; ++x) {
      if (m.image.at(x, y, 0) == 65535) {
        ++saturated;
        continue;
      }
      const Colour& c = colours[m.surfaces[(y / 10) * 4 + x / 10]];
      const Rational* channel[3] = {&c.r, &c.g, &c.b};
      for (int k = 0; k < 3; ++k) {
        const Rational exact = *channel[k] * scale;
        const Rational stored = Rational(m.image.at(x, y, k)) - 100;
        BOOST_TEST_REQUIRE(abs(stored - exact) <= Rational(1, 2));
      }
    }
  BOOST_TEST(saturated >= 1u);
  BOOST_TEST(saturated <= 5u);
  // Through a PNG file and the pixel rules: the saturated pixels dropped, and
  // one colour per surface shown.
  PixelRules rules;
  rules.black_level = 100;
  rules.saturation = 65535;
  const ImageColours out = image_colours(decode_image(encode_png16(m.image), "m.png"), rules);
  BOOST_TEST(out.counts.saturated == saturated);
  const std::set<std::size_t> shown(m.surfaces.begin(), m.surfaces.end());
  BOOST_TEST(out.counts.colours == shown.size());
  BOOST_CHECK_THROW(render_mondrian({}, spec), std::invalid_argument);
  spec.peak = 65535;
  BOOST_CHECK_THROW(render_mondrian(colours, spec), std::invalid_argument);
}

// Floating-point images (the Python module's float arrays): on integer-valued samples the same
// hull colours and counts as the 16-bit route, whose rules are tested above; black level and
// saturation as doubles; bad samples and inexact subtractions refused, naming the pixel.
BOOST_AUTO_TEST_CASE(float_images_follow_the_integer_rules) {
  std::mt19937_64 gen(17);
  for (int trial = 0; trial < 60; ++trial) {
    const unsigned range = trial % 3 == 0 ? 6 : trial % 3 == 1 ? 200 : 65535;
    std::uniform_int_distribution<unsigned> channel(0, range);
    RgbImage im;
    im.width = 7 + static_cast<std::size_t>(trial % 5);
    im.height = 5;
    FloatRgbImage fim;
    fim.width = im.width;
    fim.height = im.height;
    for (std::size_t i = 0; i < im.width * im.height * 3; ++i) {
      const unsigned v = channel(gen);
      im.samples.push_back(static_cast<std::uint16_t>(v));
      fim.samples.push_back(v);
    }
    PixelRules rules;
    rules.colour_set = ColourSet::hull;
    rules.black_level = static_cast<std::uint32_t>(trial % 4);
    if (trial % 2) rules.saturation = range / 2 + 1;
    std::bernoulli_distribution keep(0.8);
    if (trial % 3 == 1)
      for (std::size_t i = 0; i < im.width * im.height; ++i) rules.keep.push_back(keep(gen));
    FloatPixelRules frules;
    frules.black_level = rules.black_level;
    if (rules.saturation) frules.saturation = *rules.saturation;
    frules.keep = rules.keep;
    const ImageColours a = image_colours(im, rules), b = image_colours(fim, frules);
    BOOST_TEST_REQUIRE((a.colours == b.colours), "trial " << trial);
    BOOST_TEST(a.counts.masked == b.counts.masked);
    BOOST_TEST(a.counts.saturated == b.counts.saturated);
    BOOST_TEST(a.counts.kept == b.counts.kept);
    BOOST_TEST(a.counts.colours == b.counts.colours);
    BOOST_TEST(a.counts.hull_vertices == b.counts.hull_vertices);
    BOOST_TEST(a.counts.no_chromaticity == b.counts.no_chromaticity);
  }
  FloatRgbImage bad;
  bad.width = 2;
  bad.height = 1;
  bad.samples = {1, 1, 1, 1, NAN, 1};
  try {
    image_colours(bad, {});
    BOOST_FAIL("NaN accepted");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(std::string(e.what()).find("pixel (row 0, column 1) channel g: NaN") == 0);
  }
  bad.samples = {1, 1, 1, 1, -1, 1};
  BOOST_CHECK_THROW(image_colours(bad, {}), std::invalid_argument);
  bad.samples = {1e17, 1, 1, 1, 1, 1};  // 1e17 − 1 is not a double
  FloatPixelRules one;
  one.black_level = 1;
  BOOST_CHECK_THROW(image_colours(bad, one), std::invalid_argument);
  one.black_level = 0.5;  // 1e17 − 0.5 neither; but 3 − 0.5 is
  bad.samples = {3, 3, 3, 2, 2, 2};
  BOOST_TEST(image_colours(bad, one).counts.kept == 2u);
  one.black_level = -1;
  BOOST_CHECK_THROW(image_colours(bad, one), std::invalid_argument);
}

// Which files go to LibRaw: by extension (LibRaw's formats, any case), and by content a TIFF of
// raw sensor data under any name. The TIFFs are written here byte by byte (TIFF 6.0 §2), in both
// byte orders: IFD 0 an RGB thumbnail whose SubIFD (tag 330) holds the CFA data, as DNGs do.
BOOST_AUTO_TEST_SUITE_END()


// Step 4 (image_pixels.h): dark and too-bright pixels, absolute and relative to the image's
// largest value M, by hand on a small image, then Gijsenij's preset against its own wording
// (rescaled to a maximum of 255, a channel below 5 or above 245 dropped) on random images.
BOOST_AUTO_TEST_CASE(dark_and_bright_pixels) {
  RgbImage im;
  im.width = 3;
  im.height = 2;
  // After black level 10: (0,90,90) (1,1,1) (1000,490,490) / (50,50,50) (980,980,980)
  // (890,891,40); M = 1000.
  im.samples = {10, 100, 100,   11, 11, 11,   1010, 500, 500,    // row 0
                60, 60, 60,     990, 990, 990, 900, 901, 50};    // row 1
  PixelRules rules;
  rules.black_level = 10;
  rules.dark_below = 2;  // (0,0): r = 0 < 2; (1,0): 1 < 2
  KeptPixels k = kept_pixels(im, rules);
  BOOST_TEST(k.counts.dark == 2u);
  BOOST_TEST(k.counts.kept == 4u);
  BOOST_TEST(!k.kept[0]);
  BOOST_TEST(k.kept[2]);
  rules.dark_below.reset();
  rules.dark_below_fraction = Rational(1, 20);    // below 50: (0,0), (1,0), (2,1) with b = 40
  rules.bright_above_fraction = Rational(9, 10);  // above 900: (2,0) r = 1000, (1,1) 980
  k = kept_pixels(im, rules);
  BOOST_TEST(k.counts.dark == 3u);
  BOOST_TEST(k.counts.bright == 2u);
  BOOST_TEST(k.counts.kept == 1u);  // (0,1): 50 is not below 50
  BOOST_TEST(k.kept[3]);
  // M is taken over the pixels the mask keeps: masking (2,0) makes M = 980.
  rules.keep.assign(6, true);
  rules.keep[2] = false;
  k = kept_pixels(im, rules);
  BOOST_TEST(k.counts.masked == 1u);
  BOOST_TEST(k.counts.dark == 3u);    // below ceil(980/20) = 49: (0,0), (1,0), (2,1)
  BOOST_TEST(k.counts.bright == 1u);  // above floor(9/10 · 980) = 882: (1,1) only
  rules.keep.clear();
  rules.bright_above_fraction = Rational(11, 10);
  BOOST_CHECK_THROW(kept_pixels(im, rules), std::invalid_argument);

  std::mt19937 rng(26);
  for (int trial = 0; trial < 20; ++trial) {
    RgbImage r = ramp(17, 9, 16);
    std::uniform_int_distribution<int> v(0, trial % 2 ? 65535 : 3000);
    for (auto& s : r.samples) s = static_cast<std::uint16_t>(v(rng));
    PixelRules preset = gijsenij_pixel_rules();
    preset.black_level = static_cast<std::uint32_t>(trial * 97 % 700);  // the rules hold after it
    const KeptPixels g = kept_pixels(r, preset);
    const auto level = [&](std::uint64_t s) -> std::uint64_t { return s > preset.black_level ? s - preset.black_level : 0; };
    std::uint64_t M = 0;
    for (auto s : r.samples) M = std::max<std::uint64_t>(M, level(s));
    std::uint64_t kept = 0;
    for (std::size_t p = 0; p < 17 * 9; ++p) {
      bool keep = true;
      for (int c = 0; c < 3; ++c) {
        const std::uint64_t x = level(r.samples[3 * p + c]);
        keep = keep && !(255 * x < 5 * M) && !(255 * x > 245 * M);
      }
      BOOST_TEST(g.kept[p] == keep);
      kept += keep;
    }
    BOOST_TEST(g.counts.kept == kept);
    BOOST_TEST(g.counts.dark + g.counts.bright + g.counts.kept == g.counts.pixels);
  }
}

// ColourSet::hull_3d: the pixel colours on the exact 3-D hull: a subset of the distinct colours
// containing every extreme one (each colour largest along some direction is kept), and ImageColours
// says which set it holds.
BOOST_AUTO_TEST_CASE(hull_3d_colour_set) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> v(0, 400);
  RgbImage im = ramp(20, 20, 16);
  for (auto& s : im.samples) s = static_cast<std::uint16_t>(v(rng));
  PixelRules rules;
  rules.colour_set = ColourSet::distinct;
  const ImageColours all = image_colours(im, rules);
  rules.colour_set = ColourSet::hull_3d;
  const ImageColours hull = image_colours(im, rules);
  BOOST_TEST((all.set == ColourSet::distinct));
  BOOST_TEST((hull.set == ColourSet::hull_3d));
  BOOST_TEST(pixel_colours(hull.set));
  BOOST_TEST(hull.counts.hull_vertices == hull.colours.size());
  BOOST_TEST(hull.colours.size() < all.colours.size());
  for (const Colour& c : hull.colours)
    BOOST_TEST((std::find(all.colours.begin(), all.colours.end(), c) != all.colours.end()));
  const int dirs[4][3] = {{1, 0, 0}, {0, 1, 0}, {1, -1, 1}, {-1, -1, -1}};
  for (const auto& d : dirs) {
    Rational best = -1000000;
    for (const Colour& c : all.colours) best = std::max(best, Rational(d[0] * c.r + d[1] * c.g + d[2] * c.b));
    bool found = false;
    for (const Colour& c : hull.colours) found = found || Rational(d[0] * c.r + d[1] * c.g + d[2] * c.b) == best;
    BOOST_TEST(found);
  }
  rules.colour_set = ColourSet::hull;
  BOOST_TEST(!pixel_colours(image_colours(im, rules).set));
}

// Several colour sets from one sort (image_colour_sets, what the benchmark calls) are each what
// image_colours gives for that set alone, with the counts of its steps: with and without a mask
// and dark rule, with binning (where each set takes its own route) and in any order of the sets.
BOOST_AUTO_TEST_CASE(colour_sets_from_one_sort) {
  std::mt19937 rng(44);
  std::uniform_int_distribution<int> v(0, 3000);
  RgbImage im = ramp(37, 23, 16);
  for (auto& s : im.samples) s = static_cast<std::uint16_t>(v(rng));
  for (int variant = 0; variant < 3; ++variant) {
    PixelRules rules;
    if (variant >= 1) {
      rules.black_level = 100;
      rules.dark_below = 50;
      rules.exclude_polygons = {square(0, 0, 9, 9)};
    }
    if (variant == 2) rules.bin = 3;
    const std::vector<ColourSet> sets = variant == 2 ? std::vector<ColourSet>{ColourSet::hull_3d, ColourSet::distinct}
                                                     : std::vector<ColourSet>{ColourSet::hull, ColourSet::distinct,
                                                                              ColourSet::hull_3d, ColourSet::hull};
    const KeptPixels kept = kept_pixels(im, rules);
    const std::vector<ImageColours> together = image_colour_sets(im, rules, kept, sets);
    BOOST_REQUIRE(together.size() == sets.size());
    for (std::size_t k = 0; k < sets.size(); ++k) {
      PixelRules alone = rules;
      alone.colour_set = sets[k];
      const ImageColours one = image_colours(im, alone);
      BOOST_TEST((together[k].set == one.set));
      BOOST_TEST((together[k].colours == one.colours));
      BOOST_TEST(together[k].counts.kept == one.counts.kept);
      BOOST_TEST(together[k].counts.colours == one.counts.colours);
      BOOST_TEST(together[k].counts.hull_vertices == one.counts.hull_vertices);
      BOOST_TEST(together[k].counts.no_chromaticity == one.counts.no_chromaticity);
    }
  }
  BOOST_CHECK_THROW(image_colour_sets(im, PixelRules{}, KeptPixels{}, {ColourSet::hull}), std::invalid_argument);
}

// More distinct colours than image_colours takes a hull of at once (2^20): the hulls are taken
// chunk by chunk and then of the chunks' vertices (image_pixels.cpp). The same chromaticity hull,
// 3-D hull and counts as the floating-point route, which takes each hull of every colour at once.
BOOST_AUTO_TEST_CASE(hulls_of_more_colours_than_a_chunk) {
  std::mt19937_64 rng(29);
  std::uniform_int_distribution<unsigned> channel(0, 65535);
  RgbImage im;
  im.width = 1100;
  im.height = 1000;
  FloatRgbImage fim;
  fim.width = im.width;
  fim.height = im.height;
  for (std::size_t i = 0; i < im.width * im.height * 3; ++i) {
    // every 50,000th pixel has b = 0 (no chromaticity), spread over the chunks
    const unsigned v = (i % 3 == 2 && (i / 3) % 50000 == 7) ? 0 : channel(rng);
    im.samples.push_back(static_cast<std::uint16_t>(v));
    fim.samples.push_back(v);
  }
  for (ColourSet set : {ColourSet::hull, ColourSet::hull_3d}) {
    PixelRules rules;
    rules.colour_set = set;
    FloatPixelRules frules;
    frules.colour_set = set;
    const ImageColours a = image_colours(im, rules), b = image_colours(fim, frules);
    BOOST_TEST(a.counts.colours > (std::uint64_t(1) << 20));
    BOOST_TEST(a.counts.colours == b.counts.colours);
    BOOST_TEST(a.counts.hull_vertices == b.counts.hull_vertices);
    BOOST_TEST(a.counts.no_chromaticity == b.counts.no_chromaticity);
    BOOST_TEST((a.colours == b.colours), to_string(set));
  }
}

// The in-place sort image_colours takes beyond 2^24 colours: std::sort's order on random keys,
// keys sharing high bytes (one r channel, one r and g), many repeats, and already sorted or
// reversed input, at sizes about the small-bucket threshold and above.
BOOST_AUTO_TEST_CASE(in_place_key_sort) {
  std::mt19937_64 rng(31);
  const std::uint64_t below48 = (std::uint64_t(1) << 48) - 1;
  // Issue 42: up to 2^20 keys a bucket goes through a buffer, beyond it the in-place pass again.
  for (std::size_t n : {0, 1, 63, 64, 65, 1000, 300000, 2200000}) {
    for (int kind = 0; kind < 5; ++kind) {
      std::vector<std::uint64_t> keys(n);
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t r = rng() & below48;
        keys[i] = kind == 0   ? r
                  : kind == 1 ? (std::uint64_t(4321) << 32) | (r & 0xffffffff)
                  : kind == 2 ? (std::uint64_t(0x1234abcd) << 16) | (r & 0xffff)
                  : kind == 3 ? r % 7
                              : i * 977;
      }
      if (kind == 4 && n % 2) std::reverse(keys.begin(), keys.end());
      std::vector<std::uint64_t> want = keys;
      std::sort(want.begin(), want.end());
      internal::sort_keys_in_place(keys);
      BOOST_TEST((keys == want), "n " << n << " kind " << kind);
    }
  }
}

// The colours of doubles sorted by buckets of their first channel (internal/sort_colours.h)
// against std::sort: edge-like magnitudes (most near 0, a long tail), repeats, zeros, one value,
// wide exponents (2^-1000 to 2^1000), subnormals, sizes around the route's bounds, and first
// channels that send it to std::sort (a −0, a negative); compared bit for bit.
BOOST_AUTO_TEST_CASE(double_colours_sorted_as_std_sort) {
  std::mt19937_64 rng(4649);
  std::exponential_distribution<double> tail(0.01);
  std::uniform_int_distribution<int> exponent(-1000, 1000), small(0, 3);
  const auto bits = [](const std::vector<std::array<double, 3>>& v) {
    std::vector<std::array<std::uint64_t, 3>> out(v.size());
    if (!v.empty()) std::memcpy(out.data(), v.data(), v.size() * sizeof v[0]);  // no null pointers to memcpy
    return out;
  };
  for (const std::size_t n : {0, 1, 255, 256, 257, 1000, 16384, (1 << 20) + 1})
    for (int kind = 0; kind < 7; ++kind) {
      std::vector<std::array<double, 3>> c(n);
      for (std::size_t i = 0; i < n; ++i)
        for (double& x : c[i]) {
          x = kind == 0 ? tail(rng) : kind == 1 ? double(small(rng)) : kind == 2 ? std::ldexp(1.0 + tail(rng), exponent(rng))
              : kind == 3 ? 0x1p-1060 * small(rng) : 5.0;
        }
      if (kind == 5 && n > 0) c[n / 2][0] = -0.0;
      if (kind == 6 && n > 0) c[n / 2][0] = -1.0;
      std::vector<std::array<double, 3>> want = c;
      std::sort(want.begin(), want.end());
      internal::sort_double_colours(c);
      BOOST_TEST((bits(c) == bits(want)), "n " << n << " kind " << kind);
    }
}

// The Gaussian pre-filter (image_pixels.h): a constant image stays one colour exactly; a smoothed
// colour is a convex combination of the image's (every channel within the image's range, and in
// 2-D its chromaticity within theirs); kept pixels are decided on the raw values; not with binning.
BOOST_AUTO_TEST_CASE(gaussian_prefilter) {
  RgbImage flat = ramp(9, 7, 16);
  for (std::size_t p = 0; p < 63; ++p) flat.samples[3 * p] = 300, flat.samples[3 * p + 1] = 200, flat.samples[3 * p + 2] = 100;
  PixelRules rules;
  rules.prefilter_sigma = 1.5;
  rules.colour_set = ColourSet::distinct;
  const ImageColours one = image_colours(flat, rules);
  BOOST_TEST_REQUIRE(one.colours.size() == 1u);
  BOOST_TEST((one.colours[0] == Colour{300, 200, 100}));
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> v(10, 5000);
  RgbImage im = ramp(16, 12, 16);
  for (auto& s : im.samples) s = static_cast<std::uint16_t>(v(rng));
  int lo[3] = {65535, 65535, 65535}, hi[3] = {0, 0, 0};
  for (std::size_t p = 0; p < 16 * 12; ++p)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min<int>(lo[c], im.samples[3 * p + c]);
      hi[c] = std::max<int>(hi[c], im.samples[3 * p + c]);
    }
  rules.prefilter_sigma = 1;
  rules.colour_set = ColourSet::distinct;
  const ImageColours smooth = image_colours(im, rules);
  BOOST_TEST(smooth.counts.kept == 16u * 12u);
  for (const Colour& c : smooth.colours)
    for (int k = 0; k < 3; ++k) {
      const Rational& x = k == 0 ? c.r : k == 1 ? c.g : c.b;
      BOOST_TEST((x >= lo[k] && x <= hi[k]));
    }
  rules.colour_set = ColourSet::hull_3d;
  const ImageColours hull = image_colours(im, rules);
  BOOST_TEST(hull.colours.size() <= smooth.colours.size());
  for (const Colour& c : hull.colours)
    BOOST_TEST((std::find(smooth.colours.begin(), smooth.colours.end(), c) != smooth.colours.end()));
  rules.colour_set = ColourSet::hull;
  BOOST_TEST((image_colours(im, rules).set == ColourSet::hull));
  rules.bin = 2;
  BOOST_CHECK_THROW(image_colours(im, rules), std::invalid_argument);
  rules.bin = 1;
  rules.prefilter_sigma = 65;
  BOOST_CHECK_THROW(image_colours(im, rules), std::invalid_argument);
}
