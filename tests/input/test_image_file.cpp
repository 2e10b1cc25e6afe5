// Image files (image_file.h, raw_file.h): round trips through the project's own encoders and
// libpng's, samples read as stored (no gamma), a clear message for each kind of bad file, masks,
// and raw files told by name and by content. The pixel rules: tests/photo/test_image_pixels.cpp.
#include <gmcc/input/image_file.h>
#include <gmcc/input/raw_file.h>

#include <png.h>
#include <tiffio.h>

#include "../test_support.h"

#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <set>
#include <string>

using namespace gmcc;

namespace {

using gmcc::test::ramp;

std::string error_of(const std::string& bytes) {
  try {
    decode_image(bytes, "i.png");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// libpng's simplified writer (8-bit; it writes an sRGB chunk, which gmcc must
// ignore).
std::string png8(png_uint_32 format, const std::vector<png_byte>& pixels, png_uint_32 w,
                 png_uint_32 h) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = w;
  image.height = h;
  image.format = format;
  png_alloc_size_t size = 0;
  BOOST_REQUIRE(png_image_write_to_memory(&image, nullptr, &size, 0, pixels.data(), 0, nullptr));
  std::string out(size, '\0');
  BOOST_REQUIRE(png_image_write_to_memory(&image, out.data(), &size, 0, pixels.data(), 0, nullptr));
  out.resize(size);
  return out;
}

// A TIFF that libtiff writes to a temporary file (`write` sets its fields and data); removed
// when this goes out of scope.
struct LibtiffFile {
  char path[32] = "/tmp/gmcc_test_tiff_XXXXXX";
  explicit LibtiffFile(const std::function<void(TIFF*)>& write) {
    const int fd = mkstemp(path);
    BOOST_REQUIRE(fd >= 0);
    close(fd);
    TIFF* t = TIFFOpen(path, "w");
    BOOST_REQUIRE(t);
    write(t);
    TIFFClose(t);
  }
  ~LibtiffFile() { std::remove(path); }
  std::string bytes() const {
    std::FILE* f = std::fopen(path, "rb");
    std::string out;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) out.append(buf, n);
    std::fclose(f);
    return out;
  }
};

// A one-channel TIFF, written by libtiff.
std::string grey_tiff() {
  return LibtiffFile([](TIFF* t) {
           TIFFSetField(t, TIFFTAG_IMAGEWIDTH, 2u);
           TIFFSetField(t, TIFFTAG_IMAGELENGTH, 1u);
           TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
           TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 16);
           TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
           std::uint16_t row[2] = {1, 2};
           TIFFWriteScanline(t, row, 0, 0);
         })
      .bytes();
}

// CRC-32 of PNG chunks (ISO 3309), bit by bit: for rewriting a header in a test.
std::uint32_t crc32_of(const std::string& bytes) {
  std::uint32_t c = 0xffffffffu;
  for (unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return c ^ 0xffffffffu;
}

void put_be32(std::string& s, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) s[at + k] = static_cast<char>((v >> (24 - 8 * k)) & 0xff);
}

// A PNG whose IHDR declares w × h (the CRC rewritten, so libpng reads the header).
std::string png_declaring(std::string png, std::uint32_t w, std::uint32_t h) {
  put_be32(png, 16, w);
  put_be32(png, 20, h);
  put_be32(png, 29, crc32_of(png.substr(12, 17)));
  return png;
}

// A little-endian TIFF with tag `tag`'s value replaced by v (a SHORT or LONG entry of count 1).
std::string tiff_with(std::string tiff, std::uint16_t tag, std::uint32_t v) {
  auto u16 = [&](std::size_t at) { return std::uint32_t(std::uint8_t(tiff[at])) | std::uint32_t(std::uint8_t(tiff[at + 1])) << 8; };
  auto u32 = [&](std::size_t at) { return u16(at) | u16(at + 2) << 16; };
  BOOST_REQUIRE(tiff.compare(0, 4, "II*\0", 4) == 0);
  const std::size_t ifd = u32(4);
  for (std::size_t i = 0, n = u16(ifd); i < n; ++i) {
    const std::size_t e = ifd + 2 + 12 * i;
    if (u16(e) != tag) continue;
    const std::uint32_t type = u16(e + 2);
    BOOST_REQUIRE((type == 3 || type == 4));
    if (type == 3) BOOST_REQUIRE(v < 65536u);
    for (int k = 0; k < (type == 3 ? 2 : 4); ++k) tiff[e + 8 + k] = static_cast<char>((v >> (8 * k)) & 0xff);
    return tiff;
  }
  BOOST_FAIL("tag not in the TIFF");
  return tiff;
}

// A 16×16 RGB 16-bit TIFF in one 16×16 tile, written by libtiff (compression none or deflate).
std::string tiled_tiff(std::uint16_t compression) {
  return LibtiffFile([compression](TIFF* t) {
           TIFFSetField(t, TIFFTAG_IMAGEWIDTH, 16u);
           TIFFSetField(t, TIFFTAG_IMAGELENGTH, 16u);
           TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 3);
           TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 16);
           TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
           TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
           TIFFSetField(t, TIFFTAG_COMPRESSION, compression);
           TIFFSetField(t, TIFFTAG_TILEWIDTH, 16u);
           TIFFSetField(t, TIFFTAG_TILELENGTH, 16u);
           std::vector<std::uint16_t> tile(16 * 16 * 3, 1000);
           BOOST_REQUIRE(TIFFWriteTile(t, tile.data(), 0, 0, 0, 0) > 0);
         })
      .bytes();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(image_file)

BOOST_AUTO_TEST_CASE(png_and_tiff_round_trips) {
  const RgbImage im = ramp(7, 5, 16);
  for (const std::string& bytes : {encode_png16(im), encode_tiff16(im)}) {
    const RgbImage back = decode_image(bytes, "x");
    BOOST_TEST(back.width == 7u);
    BOOST_TEST(back.height == 5u);
    BOOST_TEST(back.bits == 16);
    BOOST_TEST(back.samples == im.samples);
  }
}

BOOST_AUTO_TEST_CASE(eight_bit_png_read_as_stored) {
  // RGBA 8-bit with an sRGB chunk: the alpha is dropped, the values are not
  // linearised.
  const std::vector<png_byte> px = {10, 20, 30, 255, 200, 100, 0, 128};
  const RgbImage im = decode_image(png8(PNG_FORMAT_RGBA, px, 2, 1), "x");
  BOOST_TEST(im.bits == 8);
  BOOST_TEST((im.samples == std::vector<std::uint16_t>{10, 20, 30, 200, 100, 0}));
}

// 8-bit samples are decoded into the samples' own storage and widened in place (image_file.cpp):
// every sample of a multi-row RGB and RGBA image where libpng's simplified writer put it.
BOOST_AUTO_TEST_CASE(eight_bit_png_widened_in_place) {
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> byte(0, 255);
  for (png_uint_32 format : {png_uint_32(PNG_FORMAT_RGB), png_uint_32(PNG_FORMAT_RGBA)}) {
    const std::size_t w = 37, h = 23, channels = format == PNG_FORMAT_RGB ? 3 : 4;
    std::vector<png_byte> px(w * h * channels);
    for (png_byte& b : px) b = static_cast<png_byte>(byte(rng));
    const RgbImage im = decode_image(png8(format, px, w, h), "x");
    BOOST_REQUIRE(im.samples.size() == w * h * 3);
    for (std::size_t p = 0; p < w * h; ++p)
      for (std::size_t c = 0; c < 3; ++c) BOOST_TEST(im.samples[3 * p + c] == px[channels * p + c]);
  }
}

BOOST_AUTO_TEST_CASE(bad_files_get_clear_messages) {
  BOOST_TEST(error_of("hello, world") ==
             "i.png: not a PNG or TIFF image (its first bytes are neither signature)");
  BOOST_TEST(error_of("") ==
             "i.png: not a PNG or TIFF image (its first bytes are neither signature)");
  const std::string png = encode_png16(ramp(40, 40, 16));
  BOOST_TEST(error_of(png.substr(0, png.size() / 2)).find("i.png: PNG: ") == 0u);
  BOOST_TEST(error_of(png8(PNG_FORMAT_GRAY, {1, 2}, 2, 1)) ==
             "i.png: PNG: a grey image: expected three channels r, g, b");
  BOOST_TEST(error_of(grey_tiff()).find("i.png: photometric interpretation 1: expected RGB (2)") ==
             0u);
  const std::string tiff = encode_tiff16(ramp(40, 40, 16));
  BOOST_TEST(error_of(tiff.substr(0, 200)) != "");
  BOOST_CHECK_THROW(encode_png16(RgbImage{}), std::invalid_argument);
  // fuzz_image's finding: libtiff's text for a bad InkNames tag holds a newline; the message is
  // still one line (the finding's file bytes, after the target's nine option bytes).
  std::ifstream finding(std::string(GMCC_DATA_DIR) + "/../fuzz/corpus/image/finding_multiline_libtiff_message",
                        std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(finding)), std::istreambuf_iterator<char>());
  BOOST_REQUIRE(bytes.size() > 9);
  const std::string message = error_of(bytes.substr(9));
  BOOST_TEST(message.find("i.png: ") == 0u);
  BOOST_TEST(message.find("InkNames") != std::string::npos);
  BOOST_TEST(message.find('\n') == std::string::npos);
}

// Memory follows the data, not the header (issue 30): a header claiming more pixels than the
// file's bytes can decompress to is refused before any allocation, and real files of any
// compressibility are not (the bound is deflate's, 1032:1, not a guess).
BOOST_AUTO_TEST_CASE(headers_cannot_claim_more_than_the_data_holds) {
  const std::string small = encode_png16(ramp(4, 4, 16));
  BOOST_TEST(error_of(png_declaring(small, 4, 4)).empty());  // the rewriting itself is sound
  const std::string bomb = error_of(png_declaring(small, 16384, 16384));
  BOOST_TEST(bomb.find("i.png: PNG: the header declares more pixels than the file's bytes can hold") == 0u, bomb);
  // A constant 2000×2000 image compresses as well as deflate can: still read.
  RgbImage flat;
  flat.width = flat.height = 2000;
  flat.samples.assign(2000 * 2000 * 3, 4242);
  const RgbImage back = decode_image(encode_png16(flat), "flat.png");
  BOOST_TEST((back.width == 2000 && back.samples == flat.samples));

  const std::string tiff = encode_tiff16(ramp(4, 4, 16));
  BOOST_TEST(error_of(tiff_with(tiff, 256, 4)).empty());
  const std::string wide = error_of(tiff_with(tiff_with(tiff, 256, 10000), 257, 10000));
  BOOST_TEST(wide.find("the header declares more pixels than the file's bytes can hold") != std::string::npos, wide);
  for (std::uint16_t compression : {std::uint16_t(COMPRESSION_NONE), std::uint16_t(COMPRESSION_ADOBE_DEFLATE)}) {
    const std::string tiled = tiled_tiff(compression);
    BOOST_TEST(decode_image(tiled, "t.tif").samples == std::vector<std::uint16_t>(16 * 16 * 3, 1000));
    const std::string huge = error_of(tiff_with(tiff_with(tiled, 322, 32768), 323, 32768));
    BOOST_TEST(huge.find("a 32768x32768 tile larger than the file's bytes can hold") != std::string::npos, huge);
  }
}

// Masks in TIFF of the usual kinds (issue 30): 8-bit grey, 1-bit min-is-black and min-is-white,
// read as they display; a black pixel excluded, any other kept.
BOOST_AUTO_TEST_CASE(grey_and_bilevel_tiff_masks) {
  struct Case {
    std::uint16_t bits, photometric;
    std::vector<unsigned char> row;  // one row of 8 pixels as stored
    std::vector<bool> kept;
  };
  const std::vector<Case> cases = {
      {8, PHOTOMETRIC_MINISBLACK, {0, 1, 255, 0, 7, 0, 0, 9}, {0, 1, 1, 0, 1, 0, 0, 1}},
      {1, PHOTOMETRIC_MINISBLACK, {0xb2}, {1, 0, 1, 1, 0, 0, 1, 0}},   // 1011 0010
      {1, PHOTOMETRIC_MINISWHITE, {0xb2}, {0, 1, 0, 0, 1, 1, 0, 1}}};  // 1 displays black
  for (const Case& c : cases) {
    const LibtiffFile file([&c](TIFF* t) {
      TIFFSetField(t, TIFFTAG_IMAGEWIDTH, 8u);
      TIFFSetField(t, TIFFTAG_IMAGELENGTH, 1u);
      TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 1);
      TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, c.bits);
      TIFFSetField(t, TIFFTAG_PHOTOMETRIC, c.photometric);
      std::vector<unsigned char> row = c.row;
      BOOST_REQUIRE(TIFFWriteScanline(t, row.data(), 0, 0) >= 0);
    });
    const RgbImage mask = read_mask_image(file.path);
    BOOST_TEST((mask.width == 8u && mask.height == 1u));
    for (std::size_t x = 0; x < 8; ++x) {
      const bool kept = mask.samples[3 * x] || mask.samples[3 * x + 1] || mask.samples[3 * x + 2];
      BOOST_TEST(kept == c.kept[x], "bits " << c.bits << " photometric " << c.photometric << " pixel " << x);
    }
  }
}

// Exclusion polygons are bounded in work, Σ (vertices + rows each edge spans) ≤ max_polygon_work,
// checked before any work (issue 30: a 9,000-vertex polygon on a tall image took hours; issue 42:
// the bound counted edge tests, not the crossings that cost, and 3.2·10^7 crossings of long
// fractions took 142 s under the cap).
namespace {
std::string tiff_with_subifd(bool little, std::uint16_t sub_photometric, bool dng_version) {
  std::string b;
  auto put16 = [&](std::uint32_t v) {
    if (little) b += {char(v & 255), char(v >> 8 & 255)};
    else b += {char(v >> 8 & 255), char(v & 255)};
  };
  auto put32 = [&](std::uint32_t v) {
    if (little) { put16(v & 0xffff); put16(v >> 16); }
    else { put16(v >> 16); put16(v & 0xffff); }
  };
  auto entry = [&](std::uint16_t tag, std::uint16_t type, std::uint32_t value) {
    put16(tag); put16(type); put32(1);
    if (type == 3) { put16(value); put16(0); } else put32(value);
  };
  b += little ? "II" : "MM";
  put16(42);
  put32(8);                      // IFD 0 at 8
  const std::uint16_t n0 = dng_version ? 3 : 2;
  put16(n0);
  entry(262, 3, 2);              // RGB
  entry(330, 4, 8 + 2 + 12 * n0 + 4);  // the SubIFD right after IFD 0
  if (dng_version) entry(50706, 1, 0x01040000);
  put32(0);
  put16(1);
  entry(262, 3, sub_photometric);
  put32(0);
  return b;
}
}  // namespace

BOOST_AUTO_TEST_CASE(raw_files_by_extension_and_by_content) {
  for (const char* name : {"a.dng", "b.CRW", "c.gpr", "d.Mef", "e.raw", "f.cap", "g.fff", "h.rwz", "dir.x/i.nef"})
    BOOST_TEST(is_raw_file_name(name), name);
  for (const char* name : {"a.png", "b.tif", "c.tiff", "d", "e.dng.png", "raw", ".crw/x.jpg"})
    BOOST_TEST(!is_raw_file_name(name), name);
  for (bool little : {true, false}) {
    BOOST_TEST(is_raw_file_content(tiff_with_subifd(little, 32803, false)));   // CFA in a SubIFD
    BOOST_TEST(is_raw_file_content(tiff_with_subifd(little, 34892, false)));   // LinearRaw
    BOOST_TEST(is_raw_file_content(tiff_with_subifd(little, 2, true)));        // DNGVersion in IFD 0
    BOOST_TEST(!is_raw_file_content(tiff_with_subifd(little, 2, false)));      // RGB only
    std::string cut = tiff_with_subifd(little, 32803, false);
    cut.resize(cut.size() - 10);  // the SubIFD cut off: not read past the end
    BOOST_TEST(!is_raw_file_content(cut));
  }
  RgbImage rgb;
  rgb.width = 2;
  rgb.height = 1;
  rgb.bits = 16;
  rgb.samples = {1, 2, 3, 4, 5, 6};
  BOOST_TEST(!is_raw_file_content(encode_tiff16(rgb)));
  BOOST_TEST(!is_raw_file_content(encode_png16(rgb)));
  BOOST_TEST(!is_raw_file_content(""));
}

BOOST_AUTO_TEST_SUITE_END()
