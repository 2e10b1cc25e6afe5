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

#include <array>
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
  /// The black level used at each position of the quad, in `pattern`'s order.
  std::array<std::uint32_t, 4> black{};
  /// The least and greatest photosite black level used.
  ///@{
  std::uint32_t black_min = 0, black_max = 0;
  ///@}
  std::uint32_t white = 0;    ///< the white level used
  bool black_given = false;   ///< the black level was given (RawLevels), not the file's
  bool white_given = false;   ///< the white level was given (RawLevels), not the file's
  std::string camera;         ///< make and model as the file names them
  std::size_t saturated = 0;  ///< quads written as saturated
};

/// Whether `path` names a camera raw file by its extension (case-insensitive), from the formats
/// LibRaw reads (https://www.libraw.org/supported-cameras): .3fr .ari .arw .bay .bmq .cap .cine
/// .cr2 .cr3 .crw .cs1 .dc2 .dcr .dng .drf .dsc .erf .fff .gpr .ia .iiq .k25 .kc2 .kdc .mdc .mef
/// .mos .mrw .nef .nrw .orf .ori .pef .pxn .qtk .raf .raw .rdc .rw2 .rwl .rwz .sr2 .srf .srw .sti
/// .x3f: those go to decode_raw_image (read_camera_image).
bool is_raw_file_name(const std::string& path);

/// Whether `bytes` are a TIFF holding raw sensor data whatever the file's name: a directory (IFD
/// 0, its chain or a SubIFD) with PhotometricInterpretation 32803 (CFA, TIFF/EP) or 34892
/// (LinearRaw), or a DNGVersion tag (Adobe DNG 1.6 specification, "Tags"). Such a file goes to
/// decode_raw_image, not the RGB TIFF reader.
bool is_raw_file_content(const std::string& bytes);

/// Decode a raw file held in `bytes` as above. \param bytes the whole file's content.
/// \param file the name used in messages.
/// \param levels levels that replace the file's metadata.
/// \throws InputError naming the file: a format LibRaw does not read (VC-5 compressed GPR named
///         as such: Debian's LibRaw has no decoder for it), a truncated or corrupt file (what
///         LibRaw's data-error callback reports, in the message; LibRaw prints nothing), a mosaic that is not a 2×2 Bayer
///         pattern of red, two greens and blue (X-Trans, Foveon, a linear DNG), fewer than 2×2 photosites, more than max_image_pixels
///         photosites, a white level above 32768 or not above the black level (the sums would
///         not stay below raw_saturated_value).
RawImage decode_raw_image(const std::string& bytes, const std::string& file, const RawLevels& levels = {});

/// Read a raw file (read_binary_file, then decode_raw_image).
RawImage read_raw_image(const std::string& path, const RawLevels& levels = {});

}  // namespace gmcc
