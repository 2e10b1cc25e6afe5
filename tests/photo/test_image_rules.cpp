// The rules that hold for one image (image_rules.h) and the corrected image (corrected_image.h):
// which of the run's, the image's own and the file's levels wins, told case by case; the mask;
// and the corrected image against its definition computed per pixel in rationals.
#include <gmcc/geometry/rational.h>
#include <gmcc/input/input_error.h>
#include <gmcc/photo/corrected_image.h>
#include <gmcc/photo/image_rules.h>

#include <boost/test/unit_test.hpp>
#include <random>

using namespace gmcc;

namespace {

CameraImage png_read(std::size_t w, std::size_t h, int bits, std::uint32_t black,
                     std::optional<std::uint32_t> saturation) {
  CameraImage read;
  read.image.width = w;
  read.image.height = h;
  read.image.bits = bits;
  read.image.samples.assign(w * h * 3, 7);
  read.black_level = black;
  read.saturation = saturation;
  return read;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(image_rules)

// The image's own levels replace the run's; the run's black level is passed to a raw file only
// when given; its default is what a PNG's reading records.
BOOST_AUTO_TEST_CASE(levels_the_image_is_read_with) {
  RunPixelRules run;
  run.rules.black_level = 64;
  ImagePixelRules own;
  ImageLevels l = levels_to_read(run, own);
  BOOST_TEST(!l.black.has_value());
  BOOST_TEST(l.run_black == 64u);
  BOOST_TEST(!l.saturation.has_value());
  run.black_level_given = true;
  run.rules.saturation = 4000;
  l = levels_to_read(run, own);
  BOOST_TEST(*l.black == 64u);
  BOOST_TEST(*l.saturation == 4000u);
  own.black_level = 128;
  own.saturation = 3000;
  l = levels_to_read(run, own);
  BOOST_TEST(*l.black == 128u);
  BOOST_TEST(*l.saturation == 3000u);
}

// saturation max gives 2^bits − 1 only when neither the run nor the image gave a level; the
// reading's levels are the rules'; the image's polygons are added to the run's.
BOOST_AUTO_TEST_CASE(rules_for_an_image) {
  RunPixelRules run;
  run.saturation_max = true;
  run.rules.exclude_polygons = {{{0, 0}, {1, 0}, {1, 1}}};
  ImagePixelRules own;
  own.exclude_polygons = {{{2, 2}, {3, 2}, {3, 3}}};
  PixelRules r = rules_for_image(run, own, png_read(2, 2, 12, 5, std::nullopt), "a.png");
  BOOST_TEST(*r.saturation == 4095u);
  BOOST_TEST(r.black_level == 5u);
  BOOST_TEST(r.exclude_polygons.size() == 2u);
  own.saturation = 1000;
  r = rules_for_image(run, own, png_read(2, 2, 12, 5, 1000), "a.png");
  BOOST_TEST(*r.saturation == 1000u);
  run.saturation_max = false;
  own.saturation.reset();
  r = rules_for_image(run, own, png_read(2, 2, 12, 5, std::nullopt), "a.png");
  BOOST_TEST(!r.saturation.has_value());
}

BOOST_AUTO_TEST_CASE(mask_keeps_nonzero_pixels_and_must_fit) {
  RunPixelRules run;
  RgbImage mask;
  mask.width = 2;
  mask.height = 1;
  mask.bits = 8;
  mask.samples = {0, 0, 0, 0, 1, 0};
  const PixelRules r = rules_for_image(run, {}, png_read(2, 1, 8, 0, std::nullopt), "a.png", &mask, "m.png");
  BOOST_TEST((r.keep == std::vector<bool>{false, true}));
  mask.width = 1;
  mask.samples.resize(3);
  try {
    rules_for_image(run, {}, png_read(2, 1, 8, 0, std::nullopt), "a.png", &mask, "m.png");
    BOOST_FAIL("a mask of the wrong size was accepted");
  } catch (const InputError& e) {
    const std::string what = e.what();
    BOOST_TEST(what.find("a.png") != std::string::npos);
    BOOST_TEST(what.find("m.png") != std::string::npos);
    BOOST_TEST(what.find("1x1") != std::string::npos);
  }
}

// Each output code against the definition in rationals: (v − black)⁺ · m_k / max m · (257 for
// 8 bits), rounded half up, at most 65535; a pixel with a channel >= saturation is white.
BOOST_AUTO_TEST_CASE(corrected_image_is_its_definition) {
  std::mt19937_64 gen(20261129);
  for (int bits : {8, 16}) {
    RgbImage im;
    im.width = 31;
    im.height = 7;
    im.bits = bits;
    std::uniform_int_distribution<int> code(0, bits == 8 ? 255 : 65535);
    for (std::size_t i = 0; i < im.width * im.height * 3; ++i) im.samples.push_back(static_cast<std::uint16_t>(code(gen)));
    const std::uint32_t black = bits == 8 ? 16 : 2048, saturation = bits == 8 ? 250 : 60000;
    const std::array<double, 3> m = {0.75, 2.5, 1.25};  // dyadic: m / max is exact
    const RgbImage out = corrected_image(im, black, saturation, m);
    BOOST_TEST(out.bits == 16);
    for (std::size_t p = 0; p < im.width * im.height; ++p) {
      const std::uint16_t* in = &im.samples[3 * p];
      const bool clipped = in[0] >= saturation || in[1] >= saturation || in[2] >= saturation;
      for (int c = 0; c < 3; ++c) {
        std::uint32_t expect = 65535;
        if (!clipped) {
          Rational v(static_cast<long>(m[c] * 4), 10);  // m[c] / 2.5 = 4 m[c] / 10
          v.canonicalize();
          v *= Rational((in[c] > black ? in[c] - black : 0) * (bits == 8 ? 257 : 1));
          v += Rational(1, 2);
          mpz_class rounded;
          mpz_fdiv_q(rounded.get_mpz_t(), v.get_num_mpz_t(), v.get_den_mpz_t());
          expect = rounded > 65535 ? 65535u : static_cast<std::uint32_t>(rounded.get_ui());
        }
        BOOST_TEST(out.samples[3 * p + c] == expect);
      }
    }
  }
  RgbImage one;
  one.width = one.height = 1;
  one.samples = {1, 2, 3};
  BOOST_CHECK_THROW(corrected_image(one, 0, 65536, {0, 0, 0}), std::invalid_argument);
  BOOST_CHECK_THROW(corrected_image(one, 0, 65536, {1, -1, 1}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
