// Camera raw files through LibRaw (raw_file.h). LibRaw is used for what it alone knows — the
// container formats, the decompression, the mosaic's layout and the black and white levels in
// the metadata — and nothing of its processing (dcraw_process) is called.
#include <gmcc/input/raw_file.h>

#include <gmcc/input/input_error.h>
#include <gmcc/input/text_file.h>

#include <libraw/libraw.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <memory>

namespace gmcc {
namespace {

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();  // ".DNG", or empty
  if (!e.empty()) e.erase(0, 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// LibRaw's colour index of a photosite (0 red, 1 green, 2 blue, 3 the second green) as one of
// R, G, B.
char colour_letter(int c) { return c == 0 ? 'R' : c == 2 ? 'B' : 'G'; }

}  // namespace

bool is_raw_file_name(const std::string& path) {
  static const std::array<const char*, 22> extensions = {"dng", "cr2", "cr3", "nef", "nrw", "arw", "srf", "sr2",
                                                         "raf", "orf", "rw2", "rwl", "pef", "srw", "3fr", "iiq",
                                                         "erf", "kdc", "dcr", "mos", "mrw", "x3f"};
  const std::string e = lower_extension(path);
  return std::any_of(extensions.begin(), extensions.end(), [&](const char* x) { return e == x; });
}

namespace {

// The 2×2 pattern of the mosaic as letters (row by row: "RGGB", "BGGR", …): it must repeat over
// the whole mosaic (LibRaw's `filters` describes up to 16×2; some cameras' patterns are not
// 2×2-periodic) and hold one red, two greens and one blue.
std::string bayer_pattern(LibRaw& raw, const std::string& file) {
  std::string pattern;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) pattern += colour_letter(raw.COLOR(y, x));
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      if (colour_letter(raw.COLOR(y, x)) != pattern[(y % 2) * 2 + x % 2])
        throw InputError(file, 0, "the colour filter pattern does not repeat every 2x2 photosites");
  std::string sorted = pattern;
  std::sort(sorted.begin(), sorted.end());
  if (sorted != "BGGR")
    throw InputError(file, 0, "a " + pattern + " colour filter pattern: only red, two greens and blue are read");
  return pattern;
}

// Black level of each photosite of the 2×2 pattern: LibRaw's common level, its per-colour
// levels and its repeating pattern (cblack[4] × cblack[5] values from cblack[6]), or the one
// level that replaces them.
std::array<std::uint32_t, 4> quad_black_levels(LibRaw& raw, const RawLevels& levels, const std::string& file) {
  const libraw_colordata_t& colour = raw.imgdata.color;
  const unsigned rows = colour.cblack[4], cols = colour.cblack[5];
  if (rows * cols > LIBRAW_CBLACK_SIZE - 6) throw InputError(file, 0, "a black-level pattern LibRaw cannot hold");
  auto pattern_black = [&](unsigned y, unsigned x) -> std::uint64_t {
    return rows && cols ? colour.cblack[6 + (y % rows) * cols + x % cols] : 0;
  };
  if (!levels.black)
    for (unsigned y = 0; y < 2 * rows; ++y)
      for (unsigned x = 0; x < 2 * cols; ++x)
        if (pattern_black(y, x) != pattern_black(y % 2, x % 2))
          throw InputError(file, 0, "a black-level pattern of " + std::to_string(rows) + "x" + std::to_string(cols) +
                                        " photosites that does not repeat every 2x2: give the black level");
  std::array<std::uint32_t, 4> black{};
  for (unsigned p = 0; p < 4; ++p)
    black[p] = levels.black ? *levels.black
                            : static_cast<std::uint32_t>(std::min<std::uint64_t>(
                                  std::uint64_t(colour.black) + colour.cblack[raw.COLOR(p / 2, p % 2)] +
                                      pattern_black(p / 2, p % 2),
                                  65535));
  return black;
}

// out.image from the mosaic's visible area, one pixel per 2×2 quad (raw_file.h), and
// out.saturated; out.pattern and out.white set.
void quads_to_pixels(const unsigned short* mosaic, const libraw_image_sizes_t& size,
                     const std::array<std::uint32_t, 4>& black, RawImage& out) {
  RgbImage& image = out.image;
  image.width = size.width / 2;
  image.height = size.height / 2;
  image.bits = 16;
  image.samples.resize(image.width * image.height * 3);
  const std::size_t pitch = size.raw_pitch / sizeof(unsigned short);
  std::array<int, 4> channel{};  // the quad position's output channel: 0, 1 or 2
  for (int p = 0; p < 4; ++p) channel[p] = out.pattern[p] == 'R' ? 0 : out.pattern[p] == 'G' ? 1 : 2;
  for (std::size_t qy = 0; qy < image.height; ++qy)
    for (std::size_t qx = 0; qx < image.width; ++qx) {
      std::array<std::uint32_t, 3> sum{};
      bool saturated = false;
      for (int p = 0; p < 4; ++p) {
        const std::size_t y = 2 * qy + p / 2 + size.top_margin, x = 2 * qx + p % 2 + size.left_margin;
        const std::uint32_t v = mosaic[y * pitch + x];
        if (v >= out.white) saturated = true;
        sum[channel[p]] += v > black[p] ? v - black[p] : 0;
      }
      std::uint16_t* px = &image.samples[(qy * image.width + qx) * 3];
      if (saturated) {
        px[0] = px[1] = px[2] = raw_saturated_value;
        ++out.saturated;
      } else {
        // Each photosite is below the white level (≤ 32767 after decode_raw_image's check), so
        // each sum is at most 2 · 32767 < raw_saturated_value.
        px[0] = static_cast<std::uint16_t>(2 * sum[0]);
        px[1] = static_cast<std::uint16_t>(sum[1]);
        px[2] = static_cast<std::uint16_t>(2 * sum[2]);
      }
    }
}

}  // namespace

RawImage decode_raw_image(const std::string& bytes, const std::string& file, const RawLevels& levels) {
  auto raw = std::make_unique<LibRaw>();
  auto fail = [&](const std::string& what, int code) {
    return InputError(file, 0, what + " (LibRaw: " + libraw_strerror(code) + ")");
  };
  if (const int e = raw->open_buffer(const_cast<char*>(bytes.data()), bytes.size()))
    throw fail(e == LIBRAW_FILE_UNSUPPORTED ? "not a raw file LibRaw " LIBRAW_VERSION_STR " reads" : "cannot read the raw file",
               e);
  const libraw_image_sizes_t& size = raw->imgdata.sizes;
  if (std::size_t(size.raw_width) * size.raw_height > max_image_pixels)
    throw InputError(file, 0, "more than 2^28 photosites (" + std::to_string(size.raw_width) + "x" +
                                  std::to_string(size.raw_height) + ")");
  // The header bound of images (image_file.cpp): no more photosites than the file's bytes can
  // decompress to at 4096:1, checked before unpack() decodes (and allocates) them.
  if (std::size_t(size.raw_width) * size.raw_height > 4096 * bytes.size() + 4096)
    throw InputError(file, 0, "the header declares " + std::to_string(size.raw_width) + "x" +
                                  std::to_string(size.raw_height) + " photosites, more than the file's " +
                                  std::to_string(bytes.size()) + " bytes can hold (4096:1)");
  const unsigned filters = raw->imgdata.idata.filters;
  if (filters == 0 || filters == 9 || filters < 1000)
    throw InputError(file, 0,
                     filters == 9 ? "an X-Trans mosaic: only 2x2 Bayer mosaics are read"
                                  : "not a Bayer mosaic (a linear DNG, Foveon or monochrome sensor): only 2x2 "
                                    "Bayer mosaics are read");
  if (const int e = raw->unpack()) throw fail("cannot decode the raw data", e);
  const unsigned short* mosaic = raw->imgdata.rawdata.raw_image;
  if (!mosaic) throw InputError(file, 0, "no Bayer mosaic in the file: only 2x2 Bayer mosaics are read");
  if (size.width < 2 || size.height < 2) throw InputError(file, 0, "fewer than 2x2 photosites");

  RawImage out;
  out.pattern = bayer_pattern(*raw, file);
  const std::array<std::uint32_t, 4> black = quad_black_levels(*raw, levels, file);
  out.white = levels.white ? *levels.white : raw->imgdata.color.maximum;
  out.black_min = *std::min_element(black.begin(), black.end());
  out.black_max = *std::max_element(black.begin(), black.end());
  if (out.white > 32768)
    throw InputError(file, 0, "white level " + std::to_string(out.white) +
                                  " above 32768: the sums of two photosites would reach the saturated value " +
                                  std::to_string(raw_saturated_value) + " (give the white level)");
  if (out.white <= out.black_max)
    throw InputError(file, 0, "white level " + std::to_string(out.white) + " not above the black level " +
                                  std::to_string(out.black_max));
  out.camera = std::string(raw->imgdata.idata.make) + " " + raw->imgdata.idata.model;
  quads_to_pixels(mosaic, size, black, out);
  return out;
}

RawImage read_raw_image(const std::string& path, const RawLevels& levels) {
  return decode_raw_image(read_binary_file(path, max_image_file_bytes, "raw image file"), path, levels);
}

}  // namespace gmcc
