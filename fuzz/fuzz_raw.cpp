// Fuzz target: camera raw files through LibRaw (raw_file.h), on arbitrary bytes.
//
// Every input must either decode or throw gmcc::InputError whose message is one line of bounded
// length starting with the file's name. What decodes must be one pixel per 2×2 quad of a Bayer
// pattern of red, two greens and blue, at most max_image_pixels photosites, 16 bits; the levels
// used ordered (black_min <= black_max < white <= 32768); every pixel either saturated (all three
// channels raw_saturated_value, as many as `saturated` counts) or below it in every channel, with
// red and blue even (twice a photosite's value above its black level).

#include "fuzz_support.h"

#include <gmcc/input/raw_file.h>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  gmcc::RawImage raw;
  try {
    raw = gmcc::decode_raw_image(bytes, "fuzz.dng");
  } catch (const gmcc::InputError& e) {
    const std::string message = e.what();
    FUZZ_CHECK(message.rfind("fuzz.dng", 0) == 0, "message does not start with the file: " + message);
    FUZZ_CHECK(message.find('\n') == std::string::npos, "a message of more than one line: " + message);
    FUZZ_CHECK(message.size() <= 400, "a message of " + std::to_string(message.size()) + " bytes");
    return 0;
  }
  const gmcc::RgbImage& image = raw.image;
  const std::size_t pixels = image.width * image.height;
  FUZZ_CHECK(pixels > 0 && 4 * pixels <= gmcc::max_image_pixels, "an empty or oversized mosaic");
  FUZZ_CHECK(image.bits == 16 && image.samples.size() == 3 * pixels, "samples do not match the size");
  FUZZ_CHECK(raw.pattern == "RGGB" || raw.pattern == "BGGR" || raw.pattern == "GRBG" || raw.pattern == "GBRG",
             "pattern " + raw.pattern);
  FUZZ_CHECK(raw.black_min <= raw.black_max && raw.black_max < raw.white && raw.white <= 32768,
             "levels " + std::to_string(raw.black_min) + " " + std::to_string(raw.black_max) + " " +
                 std::to_string(raw.white));
  std::size_t saturated = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::uint16_t* v = &image.samples[3 * p];
    if (v[0] == gmcc::raw_saturated_value && v[1] == gmcc::raw_saturated_value && v[2] == gmcc::raw_saturated_value) {
      ++saturated;
      continue;
    }
    for (int c = 0; c < 3; ++c) FUZZ_CHECK(v[c] < gmcc::raw_saturated_value, "an unsaturated pixel at the saturated value");
    FUZZ_CHECK(v[0] % 2 == 0 && v[2] % 2 == 0, "red or blue odd: not twice a photosite");
  }
  FUZZ_CHECK(saturated == raw.saturated, "saturated quads miscounted");
  return 0;
}
