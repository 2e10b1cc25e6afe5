#pragma once
/// \file grey_edge.h
/// The statistical baselines of illuminant estimation, in one framework (van de Weijer, Gevers &
/// Gijsenij 2007, eq. 10): the light is proportional, channel by channel, to the Minkowski p-norm
/// of the image's n-th order Gaussian derivative structure at scale σ over the kept pixels,
///   e_c ∝ ( Σ_kept |∂ⁿ f_{c,σ}|^p )^{1/p}
/// (p = ∞: the maximum). Grey world (Buchsbaum 1980) is n = 0, p = 1, σ = 0; white patch or
/// max-RGB (Land 1977) n = 0, p = ∞; shades of grey (Finlayson & Trezzi 2004) n = 0, p = 6;
/// 1st- and 2nd-order grey edge n = 1, 2. These are floating-point methods (the comparison gmcc's
/// exact gamut methods are measured against), computed on exactly the pixels the gamut methods
/// keep (docs/photographs.md §4).

#include <gmcc/photo/image_derivatives.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gmcc {

/// A baseline's parameters: derivative order n, Minkowski norm p (infinity for the maximum)
/// and Gaussian scale σ (0 only with n = 0).
struct GreyEdgeParameters {
  DerivativeOrder order = DerivativeOrder::zero;  ///< n
  double p = 1;      ///< >= 1, or infinity
  double sigma = 0;  ///< >= 0
};

/// The named baselines and the parameters they stand for.
enum class Baseline { grey_world, white_patch, shades_of_grey, grey_edge_1, grey_edge_2 };
/// Every baseline, in the order reports list them.
inline constexpr std::array<Baseline, 5> all_baselines = {Baseline::grey_world, Baseline::white_patch,
                                                           Baseline::shades_of_grey, Baseline::grey_edge_1,
                                                           Baseline::grey_edge_2};
/// `grey_world`, `white_patch`, `shades_of_grey`, `grey_edge_1`, `grey_edge_2`.
std::string to_string(Baseline baseline);
/// The inverse of to_string (dashes for underscores accepted). \throws std::invalid_argument.
Baseline baseline_from_string(const std::string& text);
/// Grey world: n 0, p 1, σ 0. White patch: n 0, p ∞, σ 0. Shades of grey: n 0, p 6, σ 0
/// (Finlayson & Trezzi 2004's choice). Grey edge: n 1 or 2, p 1, σ 1 (van de Weijer et al. 2007
/// report p = 1 near best at every order; σ = 1 suits small images such as 64 × 64 thumbnails).
GreyEdgeParameters baseline_parameters(Baseline baseline);

/// The framework's estimate: unit-length light (r, g, b) from the derivative structure of
/// `image` minus `black_level` (clamped at 0: the linear image, image_derivatives.h) at the pixels
/// `kept` marks; absent when every kept pixel's structure is 0 in some channel (no direction).
/// The structure is taken row by row (gaussian_derivative_rows), never as an image of doubles:
/// once for p = 1 and p = ∞ (the largest value per channel, and for p = 1 the plain sum Σ v in
/// pixel order), twice for another finite p (the largest values, then Σ (v/largest)^p, so that
/// no power overflows). Structure of any
/// size gives its direction: values below 2^-500 (reached through the Gaussian's tails at small
/// σ) are scaled by a power of 2 before the light is formed.
/// \throws std::invalid_argument for bad parameters or a `kept` of the wrong size.
/// Complexity: O(pixels · σ) per pass of the derivatives, O(pixels) without them (σ = 0).
std::optional<std::array<double, 3>> grey_edge_estimate(const RgbImage& image, std::uint32_t black_level,
                                                        const std::vector<bool>& kept,
                                                        const GreyEdgeParameters& parameters);

/// grey_edge_estimate for several baselines at once, each result bit for bit the one alone: the
/// baselines of one σ share each sweep of the derivative structure (gaussian_derivative_rows of
/// several orders), so the five named baselines (grey edge at one σ) cost two sweeps of the pixels
/// (the second for shades of grey's sums) and one of the derivatives of both orders, where one at
/// a time they cost four sweeps of the pixels and one of each order's derivatives (five passes
/// along x where together they take three).
/// \throws as grey_edge_estimate, before any work for a p < 1 or a `kept` of the wrong size.
std::vector<std::optional<std::array<double, 3>>> grey_edge_estimates(const RgbImage& image, std::uint32_t black_level,
                                                                     const std::vector<bool>& kept,
                                                                     const std::vector<GreyEdgeParameters>& parameters);
}  // namespace gmcc
