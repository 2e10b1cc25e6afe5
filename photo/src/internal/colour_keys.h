#pragma once
// An image's colours as 64-bit keys r·2^32 + g·2^16 + b (channels below 2^16): keys in increasing
// order are the colours in (r, g, b) order, so sorting keys sorts colours. How image_colours and
// image_hull_sets write and read them. Internal to gmcc::photo.

#include <gmcc/input/image_file.h>

#include <array>
#include <cstddef>
#include <cstdint>

namespace gmcc::internal {

// Pixel i's channels after the black level, clamped at 0 (its linear colour).
inline std::array<std::uint32_t, 3> linear_channels(const RgbImage& image, std::uint32_t black_level, std::size_t i) {
  std::array<std::uint32_t, 3> c;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::uint32_t v = image.samples[3 * i + k];
    c[k] = v > black_level ? v - black_level : 0;
  }
  return c;
}

inline std::uint64_t colour_key(const std::array<std::uint32_t, 3>& c) {
  return (std::uint64_t(c[0]) << 32) | (std::uint64_t(c[1]) << 16) | std::uint64_t(c[2]);
}

inline std::array<std::uint32_t, 3> key_channels(std::uint64_t key) {
  return {static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>((key >> 16) & 0xffff),
          static_cast<std::uint32_t>(key & 0xffff)};
}

}  // namespace gmcc::internal
