#pragma once
/// \file image_file.h
/// Linear camera images as the colour-constancy datasets ship them: 8- or
/// 16-bit RGB PNG (libpng) and TIFF (libtiff), read as stored — no gamma,
/// colour-space or ICC conversion, no scaling — so that a pixel's numbers are
/// the camera's linear responses (docs/conventions.md §8). Writing returns
/// the bytes; the command line puts them in place whole.

#include <gmcc/input/input_error.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gmcc {

/// Largest image file accepted, in bytes, and most pixels (a clear error before
/// memory runs out: 2^28 pixels of 3 16-bit samples take 1.5 GiB).
inline constexpr std::size_t max_image_file_bytes = std::size_t(1) << 30;
/// Most pixels (width × height) an image may have: 2^28.
inline constexpr std::size_t max_image_pixels = std::size_t(1) << 28;

/// An RGB image: samples row by row from the top, r, g, b per pixel, as stored
/// in the file.
struct RgbImage {
  /// Size in pixels.
  ///@{
  std::size_t width = 0, height = 0;
  ///@}
  int bits = 16;                       ///< 8 or 16: the file's sample depth (values < 2^bits)
  std::vector<std::uint16_t> samples;  ///< width · height · 3

  /// The sample of channel 0 (r), 1 (g) or 2 (b) at column x, row y (0 = top). No bounds check. O(1).
  std::uint16_t at(std::size_t x, std::size_t y, int channel) const {
    return samples[(y * width + x) * 3 + static_cast<std::size_t>(channel)];
  }
};

/// Decode a PNG or TIFF held in `bytes` (recognised by its signature, not its
/// name). Accepted: PNG colour type RGB or RGBA, TIFF photometric RGB with 3 or
/// 4 samples per pixel (unsigned integers, interleaved, strips or tiles), 8 or
/// 16 bits; an alpha channel is ignored. \param bytes the whole file's content. \param file  the name used in
/// messages. \throws InputError naming the file: not a PNG or TIFF, truncated
/// or corrupt, grey or palette,
///         another channel count or bit depth, floating-point samples, more
///         than max_image_pixels pixels.
RgbImage decode_image(const std::string& bytes, const std::string& file);

/// Read a PNG or TIFF file (read_binary_file, then decode_image).
RgbImage read_image(const std::string& path);

/// Read a mask image: a PNG of any colour type and depth (grey, 1-bit, palette, with or without
/// alpha, RGB; made RGB for the caller, alpha dropped), or a TIFF of any kind libtiff renders
/// (grey, 1-bit, palette, RGB; a non-RGB one as it displays, so min-is-white 0 is white). A pixel
/// is kept where any channel is non-zero (image_pixels.h). \throws InputError as read_image.
RgbImage read_mask_image(const std::string& path);

/// Decode a mask image held in `bytes` as read_mask_image reads its file. \param bytes the whole
/// file's content. \param file the name used in messages. \throws InputError as decode_image.
RgbImage decode_mask_image(const std::string& bytes, const std::string& file);

/// A 16-bit RGB PNG of `image` (samples as they are, whatever image.bits), no
/// gamma chunk. \throws std::invalid_argument if the image is empty or its
/// samples do not match its size.
std::string encode_png16(const RgbImage& image);

/// A 16-bit RGB TIFF (uncompressed strips) of `image`: for tests and for users'
/// round trips. \throws std::invalid_argument as encode_png16.
std::string encode_tiff16(const RgbImage& image);

}  // namespace gmcc
