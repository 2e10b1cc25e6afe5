#pragma once
/// \file raw_file.h
/// Camera raw files (DNG, CR2, NEF, ARW, …) read linearly through LibRaw, without any of a raw
/// converter's processing: no demosaicing, no white balance, no colour matrix, no gamma, no
/// scaling (docs/conventions.md §8, "Camera raw files"). Each 2×2 quad of the Bayer mosaic
/// becomes one RGB pixel, with the black level of each photosite subtracted (negative results
/// clamped to 0) and the two greens summed, so that the quad's colour is kept exactly:
///
///     (2·(R − k_R), (G₁ − k_G₁) + (G₂ − k_G₂), 2·(B − k_B))
///
/// is twice the quad's mean colour, a common factor that leaves chromaticities and the
/// direction of every light estimate unchanged. A quad with any photosite at or above the
/// white level is saturated: its pixel is written as raw_saturated_value in all three channels,
/// which the saturation rule (image_pixels.h) then drops.

#include <gmcc/input/image_file.h>

#include <cstdint>
#include <optional>
#include <string>

namespace gmcc {

/// The value of every channel of a saturated quad's pixel; the pixel rules' saturation threshold
/// for a raw image. Unsaturated pixels stay below it (raw_levels_checked).
inline constexpr std::uint16_t raw_saturated_value = 65535;

/// Black and white levels that replace the file's own (the command line's --black-level and
/// --saturation, a truth table's columns).
struct RawLevels {
  std::optional<std::uint32_t> black;  ///< one black level for every photosite
  std::optional<std::uint32_t> white;  ///< a photosite at or above this is saturated
};

/// A raw file's mosaic reduced to quads, and what was read from it.
struct RawImage {
  RgbImage image;             ///< (width/2) × (height/2) pixels as above, bits = 16
  std::string pattern;        ///< the quad's colours row by row, e.g. "RGGB"
  /// The least and greatest photosite black level used.
  ///@{
  std::uint32_t black_min = 0, black_max = 0;
  ///@}
  std::uint32_t white = 0;    ///< the white level used
  std::string camera;         ///< make and model as the file names them
  std::size_t saturated = 0;  ///< quads written as saturated
};

/// Whether `path` names a camera raw file by its extension (.dng, .cr2, .cr3, .nef, .nrw, .arw,
/// .srf, .sr2, .raf, .orf, .rw2, .rwl, .pef, .srw, .3fr, .iiq, .erf, .kdc, .dcr, .mos, .mrw,
/// .x3f, case-insensitive): those go to decode_raw_image, every other image to decode_image.
bool is_raw_file_name(const std::string& path);

/// Decode a raw file held in `bytes` as above. \param bytes the whole file's content.
/// \param file the name used in messages.
/// \param levels levels that replace the file's metadata.
/// \throws InputError naming the file: a format LibRaw does not read, a truncated or corrupt
///         file, a mosaic that is not a 2×2 Bayer pattern of red, two greens and blue (X-Trans,
///         Foveon, a linear DNG), fewer than 2×2 photosites, more than max_image_pixels
///         photosites, a white level above 32768 or not above the black level (the sums would
///         not stay below raw_saturated_value).
RawImage decode_raw_image(const std::string& bytes, const std::string& file, const RawLevels& levels = {});

/// Read a raw file (read_binary_file, then decode_raw_image).
RawImage read_raw_image(const std::string& path, const RawLevels& levels = {});

}  // namespace gmcc
