// The image gamut of many colours (issue "Performance"): the exact hull of n chromaticities by
// filtered predicates on the raw colours, against the plain exact route (rational
// chromaticities, then CGAL's hull) as the baseline, for n = 10 … 10^7.
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/chromaticity_hull.h>

#include "support/cgal_references.h"

#include <benchmark/benchmark.h>

#include <random>

namespace {
// Seeded colours: camera-like RGB, uniform in [0,1]² × [0.02, 1].
std::vector<std::array<double, 3>> colours(std::size_t n) {
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> c(0.0, 1.0), b(0.02, 1.0);
  std::vector<std::array<double, 3>> out(n);
  for (auto& x : out) x = {c(g), c(g), b(g)};
  return out;
}

void filtered(benchmark::State& s) {
  const auto input = colours(static_cast<std::size_t>(s.range(0)));
  for (auto _ : s) benchmark::DoNotOptimize(gmcc::chromaticity_hull(input));
  s.SetItemsProcessed(s.iterations() * s.range(0));
}
void rational_then_cgal(benchmark::State& s) {
  const auto input = colours(static_cast<std::size_t>(s.range(0)));
  for (auto _ : s) {
    std::vector<gmcc::Colour> exact;
    exact.reserve(input.size());
    for (const auto& c : input)
      exact.push_back({gmcc::rational_from_double(c[0]), gmcc::rational_from_double(c[1]),
                       gmcc::rational_from_double(c[2])});
    benchmark::DoNotOptimize(gmcc::test::convex_hull_cgal(
        gmcc::perspective_chromaticities(exact, gmcc::NonPositiveBluePolicy::drop).points));
  }
  s.SetItemsProcessed(s.iterations() * s.range(0));
}
}  // namespace

BENCHMARK(filtered)->RangeMultiplier(10)->Range(10, 10000000)->Unit(benchmark::kMillisecond);
BENCHMARK(rational_then_cgal)->RangeMultiplier(10)->Range(10, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
