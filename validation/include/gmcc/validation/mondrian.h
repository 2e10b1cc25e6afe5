#pragma once
/// \file mondrian.h
/// A synthetic linear camera image for testing the image pipeline end to end
/// (docs/conventions.md §8): a Mondrian — a grid of flat rectangles, each
/// one surface's colour under the scene's light — quantised to 16 bits above a
/// black level, with a few saturated pixels.

#include <gmcc/geometry/colour.h>
#include <gmcc/input/image_file.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gmcc {

/// What render_mondrian draws.
struct MondrianSpec {
  /// Image size in pixels.
  ///@{
  std::size_t width = 320, height = 240;
  ///@}
  /// The grid of rectangles (cell sides differ by ≤ 1 pixel).
  ///@{
  std::size_t columns = 8,
              rows = 6;
  ///@}
  std::uint64_t seed = 1;         ///< which surface each cell shows, and the saturated pixels
  std::uint32_t black_level = 0;  ///< added to every sample
  /// The brightest channel of the brightest surface shown is `peak` above the
  /// black level; the rest in proportion (exact scale, samples rounded half
  /// up).
  std::uint32_t peak = 60000;
  std::size_t saturated_pixels = 0;  ///< draws of a pixel set to 65535 in every channel
  /// Sensor noise: each sample of each pixel gets an integer drawn uniformly from [-noise,
  /// noise] (g() mod (2·noise + 1) − noise, pixels row-major, channels r, g, b), clamped to
  /// [0, 65534]; 0 for none.
  std::uint32_t noise = 0;
};

/// A drawn Mondrian: the image, and the surface behind each cell (the truth to test against).
struct Mondrian {
  RgbImage image;                     ///< 16-bit
  std::vector<std::size_t> surfaces;  ///< the surface shown in each cell, row-major
};

/// Render `colours` (surface colours under the light) as a Mondrian. The
/// generator is std::mt19937_64 seeded by std::seed_seq{seed}; cell k
/// (row-major) shows surface g() mod n (n = colours.size()), then each
/// saturated pixel is pixel g() mod (width · height): the same seed gives the
/// same image on every platform. \throws std::invalid_argument if colours is
/// empty, a size is 0, there are more cells than
///         pixels, the black level plus peak exceeds 65534, or the colours
///         shown are all black.
Mondrian render_mondrian(const std::vector<Colour>& colours, const MondrianSpec& spec);

}  // namespace gmcc
