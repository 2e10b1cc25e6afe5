#include <gmcc/selection/mean_3d.h>

#include <stdexcept>

namespace gmcc {

std::string to_string(Mean3dMethod method) {
  switch (method) {
    case Mean3dMethod::analytic: return "analytic";
    case Mean3dMethod::quadrature: return "quadrature";
    case Mean3dMethod::monte_carlo: return "monte-carlo";
  }
  return "analytic";
}

Mean3dMethod mean3d_method_from_string(const std::string& name) {
  for (Mean3dMethod m : {Mean3dMethod::analytic, Mean3dMethod::quadrature, Mean3dMethod::monte_carlo})
    if (to_string(m) == name) return m;
  throw std::invalid_argument("unknown 3-D mean method '" + name +
                              "' (expected analytic, quadrature or monte-carlo)");
}

MapEstimate mean_3d(const ConvexSet2& F, const Mean3dOptions& o) {
  switch (o.method) {
    case Mean3dMethod::analytic: return mean_3d_analytic(F, AnalyticOptions{o.precision_bits});
    case Mean3dMethod::quadrature: return mean_3d_quadrature(F, o.order);
    case Mean3dMethod::monte_carlo: return mean_3d_monte_carlo(F, o.samples, o.seed);
  }
  throw std::invalid_argument("mean_3d: unknown method");
}

}  // namespace gmcc
