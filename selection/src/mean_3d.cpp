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

namespace {
constexpr Mean3dMethod all_mean3d_methods[] = {Mean3dMethod::analytic, Mean3dMethod::quadrature,
                                               Mean3dMethod::monte_carlo};
}  // namespace

Mean3dMethod mean3d_method_from_string(const std::string& name) {
  for (Mean3dMethod m : all_mean3d_methods)
    if (to_string(m) == name) return m;
  throw std::invalid_argument("unknown 3-D mean method '" + name +
                              "' (expected analytic, quadrature or monte-carlo)");
}

std::vector<std::string> mean3d_method_names() {
  std::vector<std::string> names;
  for (Mean3dMethod m : all_mean3d_methods) names.push_back(to_string(m));
  return names;
}

namespace {
void check_range(const char* option, unsigned long long value, IntegerRange range) {
  if (value < range.lo || value > range.hi)
    throw OptionError(option, "must be from " + std::to_string(range.lo) + " to " + std::to_string(range.hi));
}
}  // namespace

void check_options(const Mean3dOptions& o) {
  check_range("precision", o.precision_bits, mean3d_precision_range);
  if (o.precision_bits != 0 && o.precision_bits < min_forced_precision_bits)
    throw OptionError("precision", "must be 0 (automatic) or from " + std::to_string(min_forced_precision_bits) +
                                       " to " + std::to_string(mean3d_precision_range.hi) + " bits");
  check_range("order", o.order, mean3d_order_range);
  check_range("samples", o.samples, mean3d_samples_range);
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
