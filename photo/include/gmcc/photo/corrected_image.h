#pragma once
/// \file corrected_image.h
/// The image white-balanced by a diagonal map: what a gamut method's answer does to the
/// photograph (Forsyth 1990, the diagonal model; `gmcc estimate --corrected`, docs/cli.md).

#include <gmcc/input/image_file.h>

#include <array>
#include <cstdint>

namespace gmcc {

/// The white-balanced image under the diagonal map m (2-D: (m1, m2, 1)), 16-bit: every channel
/// of a pixel the rules keep, minus the black level (clamped at 0), times d_k, d = m scaled so
/// that its largest component is 1 (no channel grows past its code range), rounded to the nearest
/// code (8-bit codes are widened by 257 first); a pixel with a channel at or above `saturation`
/// stays at the largest code, 65535, in every channel.
/// \param image the image as read. \param black_level what to subtract (image_rules.h).
/// \param saturation the first saturated code (65536: none). \param m the map, every component
///        >= 0 and one > 0.
/// \throws std::invalid_argument if m has a negative or non-finite component or none > 0.
RgbImage corrected_image(const RgbImage& image, std::uint32_t black_level, std::uint32_t saturation,
                         const std::array<double, 3>& m);

}  // namespace gmcc
