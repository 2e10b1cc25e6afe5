#include <gmcc/input/image_file.h>
#include <gmcc/input/text_file.h>
#include <png.h>
#include <tiffio.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace gmcc {
namespace {

// Deflate's largest expansion: 258 bytes from a match of at least 2 bits, 1032:1 (zlib's
// technical notes); PNG and deflate-compressed TIFF data cannot decompress to more.
constexpr std::size_t max_deflate_ratio = 1032;

// ---- PNG (libpng's classic interface: no transformation but byte order and
// alpha) ----

struct PngSource {
  const unsigned char* data;
  std::size_t size, pos;
};

struct PngFailure {
  char message[256] = "";
};

void png_read_bytes(png_structp png, png_bytep out, png_size_t n) {
  auto* source = static_cast<PngSource*>(png_get_io_ptr(png));
  if (n > source->size - source->pos) png_error(png, "truncated: the file ends inside the image");
  std::memcpy(out, source->data + source->pos, n);
  source->pos += n;
}

void png_fail(png_structp png, png_const_charp message) {
  auto* failure = static_cast<PngFailure*>(png_get_error_ptr(png));
  std::snprintf(failure->message, sizeof failure->message, "%s", message);
  png_longjmp(png, 1);
}

void png_quiet(png_structp, png_const_charp) {}

// Decodes into *out; on failure returns false with failure->message set. The row pointers
// live in the caller, so the longjmp of an error skips no destructor. The rows are decoded
// straight into out->samples (8-bit samples packed in its first half, then widened in place), so
// the image is held once: 6 bytes a pixel.
bool decode_png(const std::string& bytes, RgbImage* out, std::vector<png_bytep>* rows,
                PngFailure* failure, bool mask = false) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, failure, png_fail, png_quiet);
  if (!png) {
    std::snprintf(failure->message, sizeof failure->message, "libpng could not start");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  PngSource source{reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), 0};
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    if (!failure->message[0])
      std::snprintf(failure->message, sizeof failure->message, "libpng could not start");
    return false;
  }
  png_set_read_fn(png, &source, png_read_bytes);
  png_set_user_limits(png, 1u << 20, 1u << 20);
  png_read_info(png, info);
  const png_uint_32 width = png_get_image_width(png, info);
  const png_uint_32 height = png_get_image_height(png, info);
  const int depth = png_get_bit_depth(png, info);
  const int type = png_get_color_type(png, info);
  if (mask) {
    // A mask may be of any colour type and depth: made RGB, 8 or 16 bits; only zero matters.
    if (type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if ((type == PNG_COLOR_TYPE_GRAY || type == PNG_COLOR_TYPE_GRAY_ALPHA) && depth < 8)
      png_set_expand_gray_1_2_4_to_8(png);
    if (type == PNG_COLOR_TYPE_GRAY || type == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(png);
    if (type & PNG_COLOR_MASK_ALPHA) png_set_strip_alpha(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_strip_alpha(png);
  } else if (type != PNG_COLOR_TYPE_RGB && type != PNG_COLOR_TYPE_RGB_ALPHA) {
    png_error(png, type == PNG_COLOR_TYPE_PALETTE
                       ? "a palette image: expected linear RGB samples"
                       : "a grey image: expected three channels r, g, b");
  }
  if (!mask && depth != 8 && depth != 16) png_error(png, "expected 8 or 16 bits per sample");
  if (std::size_t(width) * height > max_image_pixels) png_error(png, "more than 2^28 pixels");
  {
    // The filtered rows the header declares must fit in what the file's compressed bytes can
    // hold: deflate expands at most 1032:1 (RFC 1951's longest match, 258 bytes, costs at least
    // two bits), so a larger claim is a truncated file or a decompression bomb, refused before
    // any allocation.
    const std::size_t declared = std::size_t(height) * (1 + png_get_rowbytes(png, info));
    if (declared > max_deflate_ratio * bytes.size() + 4096)
      png_error(png, "the header declares more pixels than the file's bytes can hold (truncated, or a "
                     "decompression bomb)");
  }
  if (depth == 16) png_set_swap(png);  // big-endian in the file; native order here
  if (type == PNG_COLOR_TYPE_RGB_ALPHA) png_set_strip_alpha(png);
  png_read_update_info(png, info);
  const int out_depth = png_get_bit_depth(png, info);
  if (png_get_channels(png, info) != 3 || (out_depth != 8 && out_depth != 16))
    png_error(png, "cannot be read as RGB samples");
  const std::size_t row_bytes = png_get_rowbytes(png, info);
  if (row_bytes != std::size_t(width) * 3 * (out_depth / 8)) png_error(png, "cannot be read as RGB samples");
  out->samples.resize(std::size_t(width) * height * 3);
  auto* storage = reinterpret_cast<unsigned char*>(out->samples.data());
  rows->resize(height);
  for (png_uint_32 y = 0; y < height; ++y) (*rows)[y] = storage + y * row_bytes;
  png_read_image(png, rows->data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  out->width = width;
  out->height = height;
  out->bits = out_depth;
  if (out_depth == 8)  // byte i moves to sample i (bytes 2i, 2i+1): from the end, nothing unread is overwritten
    for (std::size_t i = out->samples.size(); i-- > 0;) {
      const unsigned char v = storage[i];
      out->samples[i] = v;
    }
  return true;
}

void png_write_bytes(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}
void png_flush_nothing(png_structp) {}

bool encode_png(const RgbImage& image, std::string* out, std::vector<std::uint16_t>* row,
                PngFailure* failure) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, failure, png_fail, png_quiet);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, out, png_write_bytes, png_flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 16, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_set_swap(png);
  row->resize(image.width * 3);
  for (std::size_t y = 0; y < image.height; ++y) {
    std::copy_n(image.samples.begin() + static_cast<std::ptrdiff_t>(y * image.width * 3),
                image.width * 3, row->begin());
    png_write_row(png, reinterpret_cast<png_const_bytep>(row->data()));
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

// ---- TIFF (libtiff over a memory buffer) ----

thread_local std::string tiff_message;

// libtiff's first error of a read, kept for the message: one line (its texts may hold newlines)
// of at most 200 bytes.
void tiff_error(const char*, const char* format, va_list args) {
  char text[201];
  std::vsnprintf(text, sizeof text, format, args);
  for (char* c = text; *c; ++c)
    if (static_cast<unsigned char>(*c) < 0x20) *c = ' ';
  if (tiff_message.empty()) tiff_message = text;
}
void tiff_warning(const char*, const char*, va_list) {}

struct TiffMemory {
  std::string* writable = nullptr;  // for writing
  const std::string* readable = nullptr;
  toff_t pos = 0;
  std::size_t size() const { return writable ? writable->size() : readable->size(); }
};

tsize_t tiff_read(thandle_t h, tdata_t data, tsize_t n) {
  auto* m = static_cast<TiffMemory*>(h);
  const std::string& s = m->writable ? *m->writable : *m->readable;
  if (m->pos >= s.size()) return 0;
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(n), s.size() - m->pos);
  std::memcpy(data, s.data() + m->pos, k);
  m->pos += k;
  return static_cast<tsize_t>(k);
}
tsize_t tiff_write(thandle_t h, tdata_t data, tsize_t n) {
  auto* m = static_cast<TiffMemory*>(h);
  if (!m->writable) return 0;
  std::string& s = *m->writable;
  if (s.size() < m->pos + static_cast<std::size_t>(n))
    s.resize(m->pos + static_cast<std::size_t>(n));
  std::memcpy(&s[m->pos], data, static_cast<std::size_t>(n));
  m->pos += static_cast<toff_t>(n);
  return n;
}
toff_t tiff_seek(thandle_t h, toff_t offset, int whence) {
  auto* m = static_cast<TiffMemory*>(h);
  const toff_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? m->pos : m->size();
  m->pos = base + offset;
  return m->pos;
}
int tiff_close(thandle_t) { return 0; }
toff_t tiff_size(thandle_t h) { return static_cast<TiffMemory*>(h)->size(); }
int tiff_map(thandle_t, tdata_t*, toff_t*) { return 0; }
void tiff_unmap(thandle_t, tdata_t, toff_t) {}

struct TiffHandle {
  TIFF* tif;
  ~TiffHandle() {
    if (tif) TIFFClose(tif);
  }
};

void install_tiff_handlers() {
  static const bool once = [] {
    TIFFSetErrorHandler(tiff_error);
    TIFFSetWarningHandler(tiff_warning);
    return true;
  }();
  (void)once;
}

[[noreturn]] void tiff_fail(const std::string& file, const std::string& problem) {
  std::string why = problem;
  if (!tiff_message.empty()) why += " (" + tiff_message + ")";
  tiff_message.clear();
  throw InputError(file, 0, why);
}

// A TIFF held in `bytes`, opened for reading (libtiff reads through `memory`).
struct TiffReader {
  TiffMemory memory;
  TiffHandle h{nullptr};
  TiffReader(const std::string& bytes, const std::string& file) {
    install_tiff_handlers();
    tiff_message.clear();
    memory.readable = &bytes;
    h.tif = TIFFClientOpen(file.c_str(), "rm", &memory, tiff_read, tiff_write, tiff_seek, tiff_close, tiff_size,
                           tiff_map, tiff_unmap);
    if (!h.tif) tiff_fail(file, "not a readable TIFF");
  }
  TiffReader(const TiffReader&) = delete;
  TiffReader& operator=(const TiffReader&) = delete;
};

// What a TIFF's `file_bytes` can decompress to at most under its compression: deflate's 1032:1,
// PackBits' 64:1 (2 bytes give at most 128), none 1:1, LZW and the others a generous 4096:1; plus
// 4 KiB of slack for headers.
std::size_t tiff_capacity(TIFF* tif, std::size_t file_bytes) {
  std::uint16_t compression = COMPRESSION_NONE;
  TIFFGetFieldDefaulted(tif, TIFFTAG_COMPRESSION, &compression);
  const std::size_t ratio = compression == COMPRESSION_NONE       ? 1
                            : compression == COMPRESSION_PACKBITS ? 64
                            : compression == COMPRESSION_ADOBE_DEFLATE || compression == COMPRESSION_DEFLATE
                                ? max_deflate_ratio
                                : 4096;
  return ratio * file_bytes + 4096;
}

bool is_tiff(const std::string& bytes) {
  return bytes.compare(0, 4, "II*\0", 4) == 0 || bytes.compare(0, 4, "MM\0*", 4) == 0 ||
         bytes.compare(0, 4, "II+\0", 4) == 0 || bytes.compare(0, 4, "MM\0+", 4) == 0;
}

// What decode_tiff needs of a TIFF's header, checked: an RGB image of 8- or 16-bit unsigned
// samples, interleaved, that the file's bytes can hold.
struct TiffLayout {
  std::uint32_t width = 0, height = 0;
  std::uint16_t spp = 1, bps = 1;  // samples per pixel (3, or 4 with alpha), bits per sample
};

TiffLayout tiff_layout(TiffHandle& h, std::size_t file_bytes, const std::string& file) {
  TiffLayout t;
  std::uint16_t photometric = 0, planar = PLANARCONFIG_CONTIG, format = SAMPLEFORMAT_UINT;
  TIFFGetField(h.tif, TIFFTAG_IMAGEWIDTH, &t.width);
  TIFFGetField(h.tif, TIFFTAG_IMAGELENGTH, &t.height);
  TIFFGetFieldDefaulted(h.tif, TIFFTAG_SAMPLESPERPIXEL, &t.spp);
  TIFFGetFieldDefaulted(h.tif, TIFFTAG_BITSPERSAMPLE, &t.bps);
  TIFFGetFieldDefaulted(h.tif, TIFFTAG_PLANARCONFIG, &planar);
  TIFFGetFieldDefaulted(h.tif, TIFFTAG_SAMPLEFORMAT, &format);
  if (!TIFFGetField(h.tif, TIFFTAG_PHOTOMETRIC, &photometric)) photometric = 0xffff;
  if (photometric != PHOTOMETRIC_RGB)
    tiff_fail(file, "photometric interpretation " + std::to_string(photometric) +
                        ": expected RGB (2), linear samples r, g, b");
  if (t.spp != 3 && t.spp != 4)
    tiff_fail(file,
              std::to_string(t.spp) + " samples per pixel: expected 3 (r, g, b) or 4 (with alpha)");
  if (t.bps != 8 && t.bps != 16)
    tiff_fail(file, std::to_string(t.bps) + " bits per sample: expected 8 or 16");
  if (format != SAMPLEFORMAT_UINT) tiff_fail(file, "samples are not unsigned integers");
  if (planar != PLANARCONFIG_CONTIG)
    tiff_fail(file, "separate colour planes: expected interleaved r, g, b");
  if (t.width == 0 || t.height == 0) tiff_fail(file, "an empty image");
  if (std::size_t(t.width) * t.height > max_image_pixels) tiff_fail(file, "more than 2^28 pixels");
  // What the file's bytes can hold decompressed: the samples must fit, and so must one tile
  // (padding included, since a tile is encoded whole), before anything is allocated.
  const std::size_t capacity = tiff_capacity(h.tif, file_bytes);
  const std::size_t bytes_per_sample = t.bps / 8;
  if (std::size_t(t.width) * t.height * t.spp * bytes_per_sample > capacity)
    tiff_fail(file, "the header declares more pixels than the file's bytes can hold (truncated, or a "
                    "decompression bomb)");
  if (TIFFIsTiled(h.tif)) {
    std::uint32_t tw = 0, th = 0;
    TIFFGetField(h.tif, TIFFTAG_TILEWIDTH, &tw);
    TIFFGetField(h.tif, TIFFTAG_TILELENGTH, &th);
    if (std::size_t(tw) * th * t.spp * bytes_per_sample > capacity)
      tiff_fail(file, "a " + std::to_string(tw) + "x" + std::to_string(th) +
                          " tile larger than the file's bytes can hold (a decompression bomb)");
  }
  return t;
}

RgbImage decode_tiff(const std::string& bytes, const std::string& file) {
  TiffReader reader(bytes, file);
  TiffHandle& h = reader.h;
  const TiffLayout t = tiff_layout(h, bytes.size(), file);
  const std::uint32_t width = t.width, height = t.height;
  RgbImage image;
  image.width = width;
  image.height = height;
  image.bits = t.bps;
  image.samples.resize(std::size_t(width) * height * 3);
  auto store = [&](const unsigned char* pixel, std::size_t x, std::size_t y) {
    for (int c = 0; c < 3; ++c) {
      std::uint16_t v;
      if (t.bps == 8) {
        v = pixel[c];
      } else {
        std::memcpy(&v, pixel + 2 * c, 2);  // libtiff gives native byte order
      }
      image.samples[(y * width + x) * 3 + static_cast<std::size_t>(c)] = v;
    }
  };
  const std::size_t pixel_bytes = std::size_t(t.spp) * (t.bps / 8);
  if (TIFFIsTiled(h.tif)) {
    std::uint32_t tw = 0, th = 0;
    TIFFGetField(h.tif, TIFFTAG_TILEWIDTH, &tw);
    TIFFGetField(h.tif, TIFFTAG_TILELENGTH, &th);
    if (tw == 0 || th == 0) tiff_fail(file, "a tiled TIFF without tile sizes");
    std::vector<unsigned char> tile(static_cast<std::size_t>(TIFFTileSize(h.tif)));
    if (tile.size() < std::size_t(tw) * th * pixel_bytes) tiff_fail(file, "inconsistent tile size");
    for (std::uint32_t ty = 0; ty < height; ty += th)
      for (std::uint32_t tx = 0; tx < width; tx += tw) {
        if (TIFFReadTile(h.tif, tile.data(), tx, ty, 0, 0) < 0)
          tiff_fail(file, "truncated or corrupt tile data");
        for (std::uint32_t y = ty; y < std::min(height, ty + th); ++y)
          for (std::uint32_t x = tx; x < std::min(width, tx + tw); ++x)
            store(tile.data() + (std::size_t(y - ty) * tw + (x - tx)) * pixel_bytes, x, y);
      }
  } else {
    std::vector<unsigned char> line(static_cast<std::size_t>(TIFFScanlineSize(h.tif)));
    if (line.size() < std::size_t(width) * pixel_bytes) tiff_fail(file, "inconsistent row size");
    for (std::uint32_t y = 0; y < height; ++y) {
      if (TIFFReadScanline(h.tif, line.data(), y, 0) < 0)
        tiff_fail(file, "truncated or corrupt at row " + std::to_string(y + 1));
      for (std::uint32_t x = 0; x < width; ++x) store(line.data() + x * pixel_bytes, x, y);
    }
  }
  tiff_message.clear();
  return image;
}

// A mask TIFF of any kind libtiff can show (grey, 1-bit, palette, RGB; strips or tiles):
// RGB 8/16-bit images as decode_tiff reads them, the others through libtiff's RGBA rendering, so
// a pixel that displays black (every channel 0) is excluded, whatever the photometric
// interpretation (min-is-white included). Checked first as decode_tiff checks images: at most
// max_image_pixels, no more samples than the file's bytes can hold.
RgbImage decode_tiff_mask(const std::string& bytes, const std::string& file) {
  TiffReader reader(bytes, file);
  TiffHandle& h = reader.h;
  std::uint16_t photometric = 0xffff, bps = 1, spp = 1;
  TIFFGetField(h.tif, TIFFTAG_PHOTOMETRIC, &photometric);
  TIFFGetFieldDefaulted(h.tif, TIFFTAG_BITSPERSAMPLE, &bps);
  TIFFGetFieldDefaulted(h.tif, TIFFTAG_SAMPLESPERPIXEL, &spp);
  if (photometric == PHOTOMETRIC_RGB && (bps == 8 || bps == 16)) return decode_tiff(bytes, file);
  std::uint32_t width = 0, height = 0;
  TIFFGetField(h.tif, TIFFTAG_IMAGEWIDTH, &width);
  TIFFGetField(h.tif, TIFFTAG_IMAGELENGTH, &height);
  if (width == 0 || height == 0) tiff_fail(file, "an empty mask");
  if (std::size_t(width) * height > max_image_pixels) tiff_fail(file, "more than 2^28 pixels");
  if ((std::size_t(width) * height * spp * bps + 7) / 8 > tiff_capacity(h.tif, bytes.size()))
    tiff_fail(file, "the header declares more pixels than the file's bytes can hold (truncated, or a "
                    "decompression bomb)");
  std::vector<std::uint32_t> rgba(std::size_t(width) * height);
  if (!TIFFReadRGBAImageOriented(h.tif, width, height, rgba.data(), ORIENTATION_TOPLEFT, 0))
    tiff_fail(file, "a mask TIFF libtiff cannot render (photometric " + std::to_string(photometric) + ", " +
                        std::to_string(bps) + " bits)");
  RgbImage image;
  image.width = width;
  image.height = height;
  image.bits = 8;
  image.samples.resize(rgba.size() * 3);
  for (std::size_t p = 0; p < rgba.size(); ++p) {
    image.samples[3 * p] = static_cast<std::uint16_t>(TIFFGetR(rgba[p]));
    image.samples[3 * p + 1] = static_cast<std::uint16_t>(TIFFGetG(rgba[p]));
    image.samples[3 * p + 2] = static_cast<std::uint16_t>(TIFFGetB(rgba[p]));
  }
  tiff_message.clear();
  return image;
}

void check_encodable(const RgbImage& image) {
  if (image.width == 0 || image.height == 0 || image.width > (1u << 20) ||
      image.height > (1u << 20) || image.samples.size() != image.width * image.height * 3)
    throw std::invalid_argument("encode: an empty image, or samples that do not match its size");
}

}  // namespace

RgbImage decode_image(const std::string& bytes, const std::string& file) {
  static const char png_signature[] = "\x89PNG\r\n\x1a\n";
  if (bytes.compare(0, 8, png_signature, 8) == 0) {
    RgbImage image;
    std::vector<png_bytep> rows;
    PngFailure failure;
    if (!decode_png(bytes, &image, &rows, &failure))
      throw InputError(file, 0, std::string("PNG: ") + failure.message);
    return image;
  }
  if (is_tiff(bytes)) return decode_tiff(bytes, file);
  throw InputError(file, 0, "not a PNG or TIFF image (its first bytes are neither signature)");
}

RgbImage read_image(const std::string& path) {
  return decode_image(read_binary_file(path, max_image_file_bytes, "image file"), path);
}

RgbImage decode_mask_image(const std::string& bytes, const std::string& file) {
  if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n", 8) == 0) {
    RgbImage image;
    std::vector<png_bytep> rows;
    PngFailure failure;
    if (!decode_png(bytes, &image, &rows, &failure, true))
      throw InputError(file, 0, std::string("PNG: ") + failure.message);
    return image;
  }
  if (is_tiff(bytes)) return decode_tiff_mask(bytes, file);
  return decode_image(bytes, file);
}

RgbImage read_mask_image(const std::string& path) {
  return decode_mask_image(read_binary_file(path, max_image_file_bytes, "mask image"), path);
}

std::string encode_png16(const RgbImage& image) {
  check_encodable(image);
  std::string out;
  std::vector<std::uint16_t> row;
  PngFailure failure;
  if (!encode_png(image, &out, &row, &failure))
    throw std::runtime_error(std::string("PNG encoding failed: ") + failure.message);
  return out;
}

std::string encode_tiff16(const RgbImage& image) {
  check_encodable(image);
  install_tiff_handlers();
  tiff_message.clear();
  std::string out;
  TiffMemory memory;
  memory.writable = &out;
  {
    TiffHandle h{TIFFClientOpen("memory", "w", &memory, tiff_read, tiff_write, tiff_seek,
                                tiff_close, tiff_size, tiff_map, tiff_unmap)};
    if (!h.tif) throw std::runtime_error("TIFF encoding failed: " + tiff_message);
    TIFFSetField(h.tif, TIFFTAG_IMAGEWIDTH, static_cast<std::uint32_t>(image.width));
    TIFFSetField(h.tif, TIFFTAG_IMAGELENGTH, static_cast<std::uint32_t>(image.height));
    TIFFSetField(h.tif, TIFFTAG_SAMPLESPERPIXEL, 3);
    TIFFSetField(h.tif, TIFFTAG_BITSPERSAMPLE, 16);
    TIFFSetField(h.tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
    TIFFSetField(h.tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(h.tif, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
    TIFFSetField(h.tif, TIFFTAG_ROWSPERSTRIP, 16);
    std::vector<std::uint16_t> row(image.width * 3);
    for (std::size_t y = 0; y < image.height; ++y) {
      std::copy_n(image.samples.begin() + static_cast<std::ptrdiff_t>(y * image.width * 3),
                  image.width * 3, row.begin());
      if (TIFFWriteScanline(h.tif, row.data(), static_cast<std::uint32_t>(y), 0) < 0)
        throw std::runtime_error("TIFF encoding failed: " + tiff_message);
    }
  }  // TIFFClose writes the directory
  return out;
}

}  // namespace gmcc
