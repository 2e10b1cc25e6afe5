// Fuzz target: image files and the pixel rules (image_file.h, image_pixels.h).
//
// The first 9 bytes are options, the rest is a file's content. Option byte 0 chooses the reader:
// decode_image (a PNG or TIFF as a camera image) or decode_mask_image (any PNG or TIFF as a mask).
// Every input must either decode or throw gmcc::InputError whose message is one line of bounded
// length starting with the file's name. What decodes must be a non-empty image of at most
// max_image_pixels pixels, 8 or 16 bits, every sample below 2^bits, whose samples take no more
// bytes than the file's can decompress to (deflate's 1032:1 bound, which covers PNG; libtiff's
// other compressions are held to 4096:1 by image_file.cpp; a mask's pixel may be a single bit of
// that, so 48 times as much for masks), and encode_png16 must give it back sample for sample.
//
// A decoded image of at most 2^16 pixels then goes through image_colours with rules from the
// option bytes (black level, saturation, absolute and relative dark and bright thresholds, a keep
// mask, an exclusion triangle, binning, a pre-filter, each colour set). It may throw only
// std::invalid_argument (rules image_pixels.h refuses); otherwise: the steps' counts add up to
// the pixels and equal kept_pixels'; the colours are as their set says (distinct: strictly
// increasing, one per counted colour, none negative; hull: lifts (x, y, 1) with x, y >= 0, at
// most one per distinct colour; hull-3d: a non-empty subset of the distinct colours whenever
// there is a colour).

#include "fuzz_support.h"

#include <gmcc/input/image_file.h>
#include <gmcc/photo/image_pixels.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <tuple>
#include <string>
#include <vector>

namespace {

constexpr std::size_t options_size = 9;

void check_message(const std::string& message) {
  FUZZ_CHECK(message.rfind("fuzz.img", 0) == 0, "message does not start with the file: " + message);
  FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line: " + message);
  FUZZ_CHECK(message.size() <= 400, "a message of " + std::to_string(message.size()) + " bytes");
}

gmcc::PixelRules rules_from(const std::uint8_t* o, const gmcc::RgbImage& image) {
  gmcc::PixelRules rules;
  rules.colour_set = o[1] % 3 == 0   ? gmcc::ColourSet::distinct
                     : o[1] % 3 == 1 ? gmcc::ColourSet::hull
                                     : gmcc::ColourSet::hull_3d;
  const int extra = (o[1] / 3) % 4;  // 0 none, 1 bin 2, 2 bin 3, 3 pre-filter
  if (extra == 1 || extra == 2) rules.bin = static_cast<std::uint32_t>(extra + 1);
  if (extra == 3) rules.prefilter_sigma = 0.5 + (o[1] >> 6);
  rules.black_level = image.bits == 8 ? o[2] % 64 : std::uint32_t(o[2]) * 64;
  if (o[3]) rules.saturation = image.bits == 8 ? o[3] : std::uint32_t(o[3]) << 8;
  if (o[4] & 1) rules.dark_below = std::uint32_t(o[4] >> 1) * (image.bits == 8 ? 1 : 64);
  if (o[5] & 1) rules.dark_below_fraction = gmcc::Rational(o[5] >> 1, 255);
  if (o[6] & 1) rules.bright_above_fraction = gmcc::Rational(128 + (o[6] >> 1), 255);
  const std::size_t pixels = image.width * image.height;
  if (o[7] % 3 == 1) {
    for (std::size_t i = 0; i < pixels; ++i) rules.keep.push_back((i + i / image.width) % 2 == 0);
  } else if (o[7] % 3 == 2) {
    for (std::size_t i = 0; i < pixels; ++i) rules.keep.push_back(((i * 2654435761u) >> (o[7] % 7)) & 1);
  }
  if (o[8]) {  // a triangle over part of the image, vertices from the byte
    const long w = static_cast<long>(image.width), h = static_cast<long>(image.height);
    rules.exclude_polygons.push_back({{gmcc::Rational(o[8] % (w + 1)), gmcc::Rational(0)},
                                      {gmcc::Rational(w), gmcc::Rational(o[8] % (h + 1))},
                                      {gmcc::Rational(0, 1), gmcc::Rational(h, 2)}});
  }
  return rules;
}

void check_colours(const gmcc::RgbImage& image, const gmcc::PixelRules& rules) {
  gmcc::ImageColours out;
  try {
    out = gmcc::image_colours(image, rules);
  } catch (const std::invalid_argument& e) {
    // binning with a pre-filter is the only combination the recipe can make that is refused
    FUZZ_CHECK(rules.bin > 1 && rules.prefilter_sigma > 0, std::string("refused: ") + e.what());
    return;
  }
  const gmcc::PixelCounts& n = out.counts;
  FUZZ_CHECK(n.pixels == image.width * image.height, "pixels miscounted");
  FUZZ_CHECK(n.masked + n.saturated + n.dark + n.bright + n.kept == n.pixels, "counts do not add up");
  const gmcc::KeptPixels kept = gmcc::kept_pixels(image, rules);
  FUZZ_CHECK(kept.counts.kept == n.kept && kept.counts.masked == n.masked &&
                 kept.counts.saturated == n.saturated && kept.counts.dark == n.dark &&
                 kept.counts.bright == n.bright,
             "kept_pixels counts differ from image_colours'");
  FUZZ_CHECK(static_cast<std::uint64_t>(std::count(kept.kept.begin(), kept.kept.end(), true)) == n.kept,
             "kept flags do not match the count");
  FUZZ_CHECK(n.colours <= n.kept, "more colours than kept pixels");
  for (const gmcc::Colour& c : out.colours)
    FUZZ_CHECK(sgn(c.r) >= 0 && sgn(c.g) >= 0 && sgn(c.b) >= 0, "a negative channel");
  const bool binned = rules.bin > 1;
  if (out.set == gmcc::ColourSet::hull) {
    FUZZ_CHECK(!binned, "binned colours returned as lifts");
    FUZZ_CHECK(n.hull_vertices == out.colours.size() && out.colours.size() <= n.colours,
               "hull vertex count");
    for (const gmcc::Colour& c : out.colours) FUZZ_CHECK(c.b == 1, "a lift with b != 1");
    return;
  }
  gmcc::PixelRules distinct_rules = rules;
  distinct_rules.colour_set = gmcc::ColourSet::distinct;
  const gmcc::ImageColours all = gmcc::image_colours(image, distinct_rules);
  FUZZ_CHECK(all.colours.size() == all.counts.colours, "distinct colours miscounted");
  for (std::size_t i = 1; i < all.colours.size(); ++i) {
    const gmcc::Colour &a = all.colours[i - 1], &b = all.colours[i];
    FUZZ_CHECK(std::tie(a.r, a.g, a.b) < std::tie(b.r, b.g, b.b), "distinct colours not increasing");
  }
  if (out.set == gmcc::ColourSet::hull_3d) {
    FUZZ_CHECK(out.colours.empty() == all.colours.empty(), "hull-3d empty exactly when no colour");
    for (const gmcc::Colour& c : out.colours)
      FUZZ_CHECK(std::find(all.colours.begin(), all.colours.end(), c) != all.colours.end(),
                 "a hull-3d colour that is not a kept colour");
  } else {
    FUZZ_CHECK(out.colours == all.colours, "distinct colours differ between two calls");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::uint8_t options[options_size] = {};
  std::copy(data, data + std::min(size, options_size), options);
  const std::string bytes(reinterpret_cast<const char*>(data) + std::min(size, options_size),
                          size - std::min(size, options_size));
  const bool mask = options[0] & 1;
  gmcc::RgbImage image;
  try {
    image = mask ? gmcc::decode_mask_image(bytes, "fuzz.img") : gmcc::decode_image(bytes, "fuzz.img");
  } catch (const gmcc::InputError& e) {
    check_message(e.what());
    return 0;
  }
  const std::size_t pixels = image.width * image.height;
  FUZZ_CHECK(pixels > 0 && pixels <= gmcc::max_image_pixels, "an empty or oversized image");
  FUZZ_CHECK(image.bits == 8 || image.bits == 16, "bits " + std::to_string(image.bits));
  FUZZ_CHECK(image.samples.size() == pixels * 3, "samples do not match the size");
  // A camera image's samples (8 or 16 bits) come from at least a byte each of decompressed data;
  // a mask's pixel may be one bit of it, widened to three 16-bit samples (48 times as large).
  const std::size_t widening = mask ? 48 : 2;
  FUZZ_CHECK(image.samples.size() * 2 <= widening * 4096 * bytes.size() + 65536,
             "more samples than the file's bytes can decompress to");
  for (std::uint16_t v : image.samples) FUZZ_CHECK(v < (1u << image.bits), "a sample beyond its bits");
  if (pixels <= 65536) {
    const gmcc::RgbImage back = gmcc::decode_image(gmcc::encode_png16(image), "again.png");
    FUZZ_CHECK(back.samples == image.samples && back.width == image.width, "PNG round trip");
    check_colours(image, rules_from(options, image));
  }
  return 0;
}
