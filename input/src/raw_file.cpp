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
#include <vector>

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

// The extensions of the raw formats LibRaw reads (its list of supported cameras and formats,
// https://www.libraw.org/supported-cameras, and dcraw's, whose decoders it carries): Adobe DNG
// and GoPro's GPR (a DNG), and the makers' own containers.
bool is_raw_file_name(const std::string& path) {
  static const std::array extensions = {
      "3fr", "ari", "arw", "bay", "bmq", "cap", "cine", "cr2", "cr3", "crw", "cs1", "dc2",
      "dcr", "dng", "drf", "dsc", "erf", "fff", "gpr", "ia",  "iiq", "k25", "kc2", "kdc",
      "mdc", "mef", "mos", "mrw", "nef", "nrw", "orf", "ori", "pef", "pxn", "qtk", "raf",
      "raw", "rdc", "rw2", "rwl", "rwz", "sr2", "srf", "srw", "sti", "x3f"};
  const std::string e = lower_extension(path);
  return std::any_of(extensions.begin(), extensions.end(), [&](const char* x) { return e == x; });
}

namespace {

// What a walk over a TIFF's directories finds (TIFF 6.0 §2 "Image File Directory"; DNG 1.6 for
// the tags): IFD 0, the chain after it and the SubIFDs (tag 330) below any of them, at most 64
// directories, every offset checked against the file's size.
struct TiffScan {
  bool cfa = false;   // PhotometricInterpretation 32803 (CFA) or 34892 (LinearRaw), or DNGVersion
  bool vc5 = false;   // Compression 9: the VC-5 wavelet codec of GoPro's GPR (DNG 1.6 adds no code 9)
};

TiffScan scan_tiff(const std::string& b) {
  TiffScan scan;
  if (b.size() < 8) return scan;
  const bool little = b.compare(0, 4, "II*\0", 4) == 0;
  if (!little && b.compare(0, 4, "MM\0*", 4) != 0) return scan;
  auto u16 = [&](std::size_t at) -> std::uint32_t {
    const auto x = [&](std::size_t k) { return std::uint32_t(static_cast<unsigned char>(b[at + k])); };
    return little ? x(0) | x(1) << 8 : x(0) << 8 | x(1);
  };
  auto u32 = [&](std::size_t at) -> std::uint32_t {
    return little ? u16(at) | u16(at + 2) << 16 : u16(at) << 16 | u16(at + 2);
  };
  std::vector<std::uint32_t> todo = {u32(4)};
  for (int seen = 0; !todo.empty() && seen < 64; ++seen) {
    const std::size_t ifd = todo.back();
    todo.pop_back();
    if (ifd < 8 || ifd + 2 > b.size()) continue;
    const std::size_t n = u16(ifd);
    if (ifd + 2 + 12 * n + 4 > b.size()) continue;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t e = ifd + 2 + 12 * k;
      const std::uint32_t tag = u16(e), type = u16(e + 2), count = u32(e + 4);
      const std::uint32_t value = type == 3 ? u16(e + 8) : u32(e + 8);  // SHORT or LONG, the first
      if (tag == 262 && (value == 32803 || value == 34892)) scan.cfa = true;
      if (tag == 50706) scan.cfa = true;
      if (tag == 259 && value == 9) scan.vc5 = true;
      if (tag == 330 && (type == 4 || type == 13)) {
        if (count == 1) {
          todo.push_back(value);
        } else if (count < 64 && std::size_t(value) + 4 * count <= b.size()) {
          for (std::uint32_t i = 0; i < count; ++i) todo.push_back(u32(value + 4 * i));
        }
      }
    }
    todo.push_back(u32(ifd + 2 + 12 * n));  // the next directory (0: none)
  }
  return scan;
}

}  // namespace

bool is_raw_file_content(const std::string& bytes) { return scan_tiff(bytes).cfa; }

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

namespace {

// What LibRaw reports through its callbacks, kept for gmcc's message instead of printed: its
// default handlers write to stderr (libraw_datastream.cpp, default_data_callback and
// default_memory_callback).
struct LibRawReports {
  std::string data;    // the first data error: "data corrupted at N" or "unexpected end of file"
  std::string memory;  // the first memory error
};

void capture_data_error(void* to, const char*, const int offset) {
  std::string& d = static_cast<LibRawReports*>(to)->data;
  if (d.empty()) d = offset < 0 ? "unexpected end of file" : "data corrupted at byte " + std::to_string(offset);
}

void capture_memory_error(void* to, const char*, const char* where) {
  std::string& m = static_cast<LibRawReports*>(to)->memory;
  if (m.empty()) m = std::string("out of memory in ") + (where ? where : "LibRaw");
}

}  // namespace

RawImage decode_raw_image(const std::string& bytes, const std::string& file, const RawLevels& levels) {
  auto raw = std::make_unique<LibRaw>();
  LibRawReports reports;
  raw->set_dataerror_handler(capture_data_error, &reports);
  raw->set_memerror_handler(capture_memory_error, &reports);
  auto fail = [&](const std::string& what, int code) {
    std::string why = libraw_strerror(code);
    if (!reports.data.empty()) why = reports.data;
    if (!reports.memory.empty()) why = reports.memory;
    return InputError(file, 0, what + " (LibRaw " LIBRAW_VERSION_STR ": " + why + ")");
  };
  if (const int e = raw->open_buffer(const_cast<char*>(bytes.data()), bytes.size())) {
    if (e == LIBRAW_FILE_UNSUPPORTED && scan_tiff(bytes).vc5)
      throw InputError(file, 0,
                       "VC-5 compressed raw data (GoPro GPR, DNG compression 9): this LibRaw " LIBRAW_VERSION_STR
                       " has no VC-5 decoder (LibRaw decodes it only when built with GoPro's gpr library, "
                       "USE_GPRSDK, and Debian's is not); convert it to an uncompressed DNG first");
    throw fail(e == LIBRAW_FILE_UNSUPPORTED ? "not a raw file LibRaw reads" : "cannot read the raw file", e);
  }
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
  // A data error LibRaw reported but decoded past (a truncated or damaged file whose missing
  // photosites it filled): the mosaic is not the camera's, so it is refused like a failed decode.
  if (!reports.data.empty() || !reports.memory.empty())
    throw fail("corrupt or incomplete raw data", LIBRAW_DATA_ERROR);
  const unsigned short* mosaic = raw->imgdata.rawdata.raw_image;
  if (!mosaic) throw InputError(file, 0, "no Bayer mosaic in the file: only 2x2 Bayer mosaics are read");
  if (size.width < 2 || size.height < 2) throw InputError(file, 0, "fewer than 2x2 photosites");

  RawImage out;
  out.pattern = bayer_pattern(*raw, file);
  const std::array<std::uint32_t, 4> black = quad_black_levels(*raw, levels, file);
  out.white = levels.white ? *levels.white : raw->imgdata.color.maximum;
  out.black = black;
  out.black_given = levels.black.has_value();
  out.white_given = levels.white.has_value();
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
