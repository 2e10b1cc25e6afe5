// Time per 3-D mean, by route, on a 12-vertex feasible polygon (issue "The 3-D mean three ways").
// Run in Release: build/bench/bench_mean_3d. The ratio closed form : Monte Carlo (10^6 samples)
// is computed from the same run by bench/mean_3d_table.py.
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/selection/mean_3d.h>
#include <gmcc/selection/mean_3d_double.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>

namespace {
// A regular-ish 12-gon of radius 0.6 around (1.2, 0.9) with rational vertices (a typical
// feasible set of the synthetic experiment has this size).
gmcc::ConvexSet2 polygon12() {
  std::vector<gmcc::Point2> p;
  for (int i = 0; i < 12; ++i) {
    const double t = 2 * M_PI * i / 12;
    p.push_back({gmcc::Rational(gmcc::Rational(12, 10) + gmcc::rational_from_double(0.6 * std::cos(t))),
                 gmcc::Rational(gmcc::Rational(9, 10) + gmcc::rational_from_double(0.6 * std::sin(t)))});
  }
  return gmcc::convex_hull(p);
}
const gmcc::ConvexSet2 F = polygon12();

std::string format_bound(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2g", x);
  return b;
}

void analytic_auto(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(gmcc::mean_3d_analytic(F));
  const gmcc::MapEstimate e = gmcc::mean_3d_analytic(F);
  s.SetLabel("precision " + std::to_string(e.precision_bits) + ", bound " + format_bound(e.error_bound));
}
void analytic_mpfi_128(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(gmcc::mean_3d_analytic(F, {128}));
}
void double_naive(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(gmcc::mean_3d_double(F));
}
void quadrature(benchmark::State& s) {
  const auto n = static_cast<unsigned>(s.range(0));
  for (auto _ : s) benchmark::DoNotOptimize(gmcc::mean_3d_quadrature(F, n));
  char label[64];
  std::snprintf(label, sizeof label, "estimate %.2g", gmcc::mean_3d_quadrature(F, n).error_bound);
  s.SetLabel(label);
}
void monte_carlo(benchmark::State& s) {
  const auto n = static_cast<std::uint64_t>(s.range(0));
  for (auto _ : s) benchmark::DoNotOptimize(gmcc::mean_3d_monte_carlo(F, n, 1));
  const gmcc::MapEstimate e = gmcc::mean_3d_monte_carlo(F, n, 1);
  char label[96];
  if (e.valid)
    std::snprintf(label, sizeof label, "standard error %.2g", e.error_bound);
  else
    std::snprintf(label, sizeof label, "no map: %llu kept", static_cast<unsigned long long>(e.samples_kept));
  s.SetLabel(label);
}
}  // namespace

BENCHMARK(analytic_auto);
BENCHMARK(analytic_mpfi_128);
BENCHMARK(double_naive);
BENCHMARK(quadrature)->Arg(4)->Arg(8)->Arg(12)->Arg(16);
BENCHMARK(monte_carlo)->Arg(10000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
