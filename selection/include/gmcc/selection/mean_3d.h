#pragma once
/// \file mean_3d.h
/// The 3-D mean of Finlayson & Hordley (1999) §3.2 — the centroid of (cone over F) ∩ unit ball,
/// projected back to the plane — by any of its three independent routes (docs/math.md §2).

#include <gmcc/selection/mean_3d_analytic.h>
#include <gmcc/selection/mean_3d_monte_carlo.h>
#include <gmcc/selection/mean_3d_quadrature.h>

#include <gmcc/geometry/option_error.h>

#include <cstdint>
#include <string>
#include <vector>

namespace gmcc {

/// The routes to the 3-D mean.
enum class Mean3dMethod {
  analytic,     ///< closed form, certified enclosure (mean_3d_analytic)
  quadrature,   ///< Duffy–Gauss–Legendre, truncation estimate + rounding bound (mean_3d_quadrature)
  monte_carlo,  ///< the paper's sampling, standard error (mean_3d_monte_carlo)
};

/// `analytic`, `quadrature`, `monte-carlo`.
std::string to_string(Mean3dMethod method);
/// Inverse of to_string. \throws std::invalid_argument listing the valid names.
Mean3dMethod mean3d_method_from_string(const std::string& name);
/// Every name to_string gives, in declaration order: the choices a front end offers.
std::vector<std::string> mean3d_method_names();

/// Which route, and its parameters (each used only by its route). The defaults here are every
/// front end's defaults; the ranges below are every front end's limits (docs/cli.md "gmcc select").
struct Mean3dOptions {
  Mean3dMethod method = Mean3dMethod::analytic;  ///< the route: closed form, quadrature or Monte Carlo
  unsigned precision_bits = 0;     ///< analytic: forced precision (0: automatic)
  unsigned order = 12;             ///< quadrature: Gauss–Legendre points per direction
  std::uint64_t samples = 1000000; ///< monte-carlo: points drawn in the unit cube
  std::uint64_t seed = 1;          ///< monte-carlo: generator seed
};

/// The limits of Mean3dOptions: the forced precision 0 (automatic) or from
/// min_forced_precision_bits to 2^20 bits (mean_3d_analytic's cap), the quadrature order 1 to
/// 256 points per direction, the Monte Carlo sample count 1 to 10^9, any seed.
///@{
inline constexpr IntegerRange mean3d_precision_range{0, 1u << 20};
inline constexpr unsigned min_forced_precision_bits = 53;
inline constexpr IntegerRange mean3d_order_range{1, 256};
inline constexpr IntegerRange mean3d_samples_range{1, 1000000000};
inline constexpr IntegerRange mean3d_seed_range{0, ~0ULL};
///@}

/// Checks every parameter of `options` against the limits above (the unused ones too: a front
/// end refuses a parameter given for another route itself).
/// \throws OptionError naming `precision`, `order` or `samples`.
void check_options(const Mean3dOptions& options);

/// The 3-D mean of F by the chosen route. \pre F not empty.
MapEstimate mean_3d(const ConvexSet2& F, const Mean3dOptions& options = {});

}  // namespace gmcc
