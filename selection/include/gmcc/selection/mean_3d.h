#pragma once
/// \file mean_3d.h
/// The 3-D mean of Finlayson & Hordley (1999) §3.2 — the centroid of (cone over F) ∩ unit ball,
/// projected back to the plane — by any of its three independent routes (docs/math.md §2).

#include <gmcc/selection/mean_3d_analytic.h>
#include <gmcc/selection/mean_3d_monte_carlo.h>
#include <gmcc/selection/mean_3d_quadrature.h>

#include <cstdint>
#include <string>

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

/// Which route, and its parameters (each used only by its route).
struct Mean3dOptions {
  Mean3dMethod method = Mean3dMethod::analytic;  ///< the route: closed form, quadrature or Monte Carlo
  unsigned precision_bits = 0;     ///< analytic: forced precision (0: automatic)
  unsigned order = 12;             ///< quadrature: Gauss–Legendre points per direction
  std::uint64_t samples = 1000000; ///< monte-carlo: points drawn in the unit cube
  std::uint64_t seed = 1;          ///< monte-carlo: generator seed
};

/// The 3-D mean of F by the chosen route. \pre F not empty.
MapEstimate mean_3d(const ConvexSet2& F, const Mean3dOptions& options = {});

}  // namespace gmcc
