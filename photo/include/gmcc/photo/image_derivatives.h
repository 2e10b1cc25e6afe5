#pragma once
/// \file image_derivatives.h
/// Gaussian derivatives of a linear image, channel by channel (the scale-space derivatives of
/// van de Weijer, Gevers & Gijsenij 2007 §3 and Gijsenij, Gevers & van de Weijer 2010 §4):
/// f_σ = f ⊗ G_σ and its 1st- and 2nd-order derivatives, computed in IEEE double with a fixed
/// order of operations (the same bytes on every run and platform with IEEE arithmetic). A
/// derivative is linear in the image, so a diagonal map d acts on it as on the image: the
/// derivative of d ⊙ f is d ⊙ (the derivative of f), which is what lets the gamut and grey-edge
/// methods use them (docs/photographs.md §5).

#include <gmcc/input/image_file.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace gmcc {

/// An image of three double channels, row-major: width · height · 3 samples.
struct DoubleImage {
  /// size in pixels
  ///@{
  std::size_t width = 0, height = 0;
  ///@}
  std::vector<double> samples;        ///< width · height · 3, r, g, b per pixel
  /// Channel c at pixel index i = y · width + x. No bounds check.
  double at(std::size_t i, int c) const { return samples[3 * i + static_cast<std::size_t>(c)]; }
};

/// The image minus its black level (clamped at 0), as doubles. O(pixels).
DoubleImage linear_image(const RgbImage& image, std::uint32_t black_level);

/// Which derivative structure: the smoothed image (order 0), the gradient magnitude per channel
/// sqrt(f_x² + f_y²) (order 1), or the 2nd-order magnitude sqrt(f_xx² + 4 f_xy² + f_yy²)
/// (order 2; van de Weijer et al. 2007 eq. 9).
enum class DerivativeOrder { zero = 0, first = 1, second = 2 };

/// Gaussian derivatives of every channel at scale σ: the kernel G_σ sampled at the integers of
/// [−⌈3σ⌉, ⌈3σ⌉] and normalised to sum 1; the 1st-order kernel −x/σ²·G_σ(x) normalised so that
/// Σ x·k(x) = −1 (a ramp's slope exactly), the 2nd-order (x²/σ⁴ − 1/σ²)·G_σ(x) with its mean
/// removed and normalised so that Σ x²/2·k(x) = 1; separable, the image's edge replicated. Up to
/// σ = 11 each pass is the direct sum; above, an FFT convolution with the same kernels (Cooley &
/// Tukey 1965), at a cost per pixel nearly independent of σ and within 2^-40·Σ|k|·max|in| of the
/// exact sums per pass (docs/photographs.md "Gaussian derivatives by FFT").
/// σ = 0 with order 0 returns the image itself; order 1 or 2 needs σ > 0. A channel constant over
/// the whole image has 1st- and 2nd-order magnitudes exactly 0 (its true value), never round-off.
/// A magnitude whose squares would leave the doubles' normal range (tiny derivatives, reached through
/// the Gaussian's tails at σ below about 0.1) is taken from its components scaled by the largest,
/// so that it is 0 only where they all are.
/// \returns per pixel and channel: f_σ (order 0), or the magnitudes above (orders 1, 2), >= 0.
/// \throws std::invalid_argument for σ < 0, σ > 64, not finite, or 0 with order 1 or 2.
DoubleImage gaussian_derivative(const DoubleImage& image, double sigma, DerivativeOrder order);

/// The same derivatives row by row, without an image of doubles (docs/cli.md "Resource limits":
/// an image in flight): the values of gaussian_derivative(linear_image(image, black_level), σ,
/// order), bit for bit, handed to `row(y, values)` for y = 0, 1, …, height − 1 in order, with the
/// row's width · 3 values (r, g, b per pixel) valid during the call. The separable passes along x
/// are kept for the rows the passes along y need: min(height, 2⌈3σ⌉ + 1) rows of 24 bytes a
/// pixel for each of the order's one (0), two (1) or three (2) kernels, plus one row of each
/// kind of result (σ ≤ 11); above σ = 11, min(height, N) rows per kernel and N − 2⌈3σ⌉ rows of
/// each kind of result (N the smallest power of 2 of at least 4⌈3σ⌉ + 2: at most about 4 times
/// the direct route's rows); σ = 0 with order 0 gives the linear image's rows. Ctrl-C is answered within a
/// row (numerics/interrupt.h).
/// \throws std::invalid_argument as gaussian_derivative; Interrupted; whatever `row` throws.
void gaussian_derivative_rows(const RgbImage& image, std::uint32_t black_level, double sigma,
                              DerivativeOrder order, const std::function<void(std::size_t, const double*)>& row);

/// Several orders at one σ from one sweep: `row(y, values)` gets, for each order o with
/// `orders[o]` true, the row values[o] that gaussian_derivative_rows(image, black_level, σ, o, …)
/// hands on, bit for bit (null for an order not asked). The passes along x and y the orders share
/// are made once (orders 1 and 2 share the smoothing and 1st-order kernels along x: five passes
/// along y and three along x for both, where one at a time makes ten and five), and the memory
/// is that of the passes made: the rings of the kernels along x and one row (σ ≤ 11) or block
/// (above) of each pass along y and each order.
/// \throws std::invalid_argument as gaussian_derivative (σ = 0 with order 1 or 2 asked);
/// Interrupted; whatever `row` throws.
void gaussian_derivative_rows(const RgbImage& image, std::uint32_t black_level, double sigma,
                              const std::array<bool, 3>& orders,
                              const std::function<void(std::size_t, const std::array<const double*, 3>&)>& row);

}  // namespace gmcc
