#pragma once
/// \file edge_colours.h
/// The colours of an image's edges for edge-based gamut mapping (Gijsenij, Gevers & van de Weijer
/// 2010 §4): per pixel, the Gaussian derivative magnitudes of the three channels at scale σ
/// (image_derivatives.h: the gradient magnitude sqrt(f_x² + f_y²) for the 1st order, the
/// 2nd-order magnitude for the 2nd), taken exactly as rationals, at the pixels the pixel rules keep
/// whose whole neighbourhood is kept (docs/photographs.md §5 "Edge-based gamut mapping").
///
/// A magnitude is linear in the image under a diagonal map with positive d (|d_k·g| = d_k·|g|
/// channel by channel), so edge colours obey the same diagonal model as pixel colours, and the
/// whole 3-D machinery (learned canonical gamut, F3, rules) applies to them unchanged. Magnitudes
/// are non-negative: the signed derivatives f_x, f_y, f_xx, … are not taken (their gamuts are
/// centrally symmetric and need signed colours, which gmcc's 3-D geometry does not take).

#include <gmcc/photo/image_derivatives.h>
#include <gmcc/photo/image_pixels.h>

#include <array>
#include <cstddef>

namespace gmcc {

/// Which edge colours, and where.
struct EdgeRules {
  DerivativeOrder order = DerivativeOrder::first;  ///< first (gradient) or second order
  double sigma = 1;                                ///< the derivatives' scale σ, in (0, 64]
  /// A pixel's edge colour is taken when every pixel within this Chebyshev distance is kept by
  /// the pixel rules: an edge next to a masked chart or a dropped (clipped, dark) pixel is coloured
  /// by it. 2 (a 5 × 5 neighbourhood) suits σ = 1.
  std::size_t neighbourhood = 2;
  /// With the hull_3d colour set: whether the distinct edge colours are found and counted
  /// (`counts.colours`). false: counts.colours is 0 and the hull is taken without sorting every
  /// colour (hull_3d_of_doubles), the same vertices in the same order (the benchmark's route).
  bool count_colours = true;
};

/// The edge colours of `image`: the pixel rules' steps 1–4 (mask, saturation, black level, dark
/// and bright; `pixels.bin` must be 1 and `pixels.prefilter_sigma` 0) choose the pixels, the
/// derivatives are taken of the image minus its black level, and the colour set is
/// `pixels.colour_set` (distinct or hull_3d; the chromaticity hull is refused). `counts.kept`
/// is the number of pixels whose edge colour was taken.
/// \throws std::invalid_argument for a colour set of chromaticity lifts, binning or a
///         pre-filter, σ outside (0, 64], order zero, or as image_colours.
/// Complexity: O(pixels · σ) for the derivatives, taken row by row (gaussian_derivative_rows),
/// O(pixels) for the neighbourhood rule whatever its size, and the colour set's hull (2^20
/// colours at a time). Memory: the pixel rules' bits, 24 bytes an edge pixel (its colour, kept for
/// the exact distinct set) and the derivatives' rows (docs/cli.md "Resource limits").
ImageColours edge_colours(const RgbImage& image, const PixelRules& pixels, const EdgeRules& edges = {});

/// The 1st- and 2nd-order edge colours from one sweep of the derivatives (the n-jet methods,
/// docs/photographs.md §5 "Edge-based gamut mapping"): element 0 is edge_colours(image, pixels,
/// e) for `edges` with order first, element 1 with order second, colour for colour and count for
/// count (`edges.order` is not read). The sweep is gaussian_derivative_rows with both orders
/// asked, which makes the passes along x the two orders share once and hands on each order's
/// values bit for bit; the pixel rules and the neighbourhood rule are applied once.
/// \throws as edge_colours. Memory: as edge_colours, 48 bytes an edge pixel (both orders'
/// colours) and the two-order sweep's rows.
std::array<ImageColours, 2> edge_colours_both_orders(const RgbImage& image, const PixelRules& pixels,
                                                      const EdgeRules& edges);

}  // namespace gmcc
