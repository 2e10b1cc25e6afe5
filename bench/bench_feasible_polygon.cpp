// The feasible polygon of a many-vertex canonical gamut (issue 13): G_c the hull of the parabola
// (1 + i/N, 1 + (i/N)²), i = 0 … N − 1 (every point a vertex), against the image colours
// (1, 1, 1), (1.001, 1, 1), (1, 1.001, 1), by the convex pass feasible_polygon runs and by the
// Sutherland–Hodgman route it replaced, in the same process. The last lines printed are the
// ratios line_by_line / convex_pass per N (docs/performance-history.md, "Many-vertex canonical gamuts
// (issue 13)"). The old route takes about a minute and a half at N = 10^5 and is not run beyond.
#include <gmcc/geometry/feasible_polygon.h>

#include "internal/feasible_polygon_route.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

namespace {

const gmcc::ConvexSet2& parabola(long n) {
  static std::map<long, gmcc::ConvexSet2> cache;
  gmcc::ConvexSet2& g = cache[n];
  if (g.vertices.empty()) {  // already in canonical form: counter-clockwise from (1, 1), strictly convex
    g.kind = gmcc::ConvexKind::polygon;
    for (long i = 0; i < n; ++i) {
      gmcc::Rational t(i, n);
      t.canonicalize();
      g.vertices.push_back({gmcc::Rational(1 + t), gmcc::Rational(1 + t * t)});
    }
  }
  return g;
}

const std::vector<gmcc::Point2>& image() {
  static const std::vector<gmcc::Point2> q{
      {1, 1}, {gmcc::Rational(1001, 1000), 1}, {1, gmcc::Rational(1001, 1000)}};
  return q;
}

void run(benchmark::State& s, gmcc::internal::Clipping route) {
  const gmcc::CanonicalConstraints g(parabola(s.range(0)));
  std::size_t vertices = 0;
  for (auto _ : s) {
    const gmcc::FeasiblePolygon F = gmcc::internal::feasible_polygon(g, image(), route);
    vertices = F.vertices().size();
    benchmark::DoNotOptimize(vertices);
  }
  s.counters["F_vertices"] = static_cast<double>(vertices);
}
void convex_pass(benchmark::State& s) { run(s, gmcc::internal::Clipping::convex_pass); }
void line_by_line(benchmark::State& s) { run(s, gmcc::internal::Clipping::line_by_line); }

// The console report, and each run's CPU time kept for the ratios (the machine is shared: CPU
// time, as docs/performance.md reports Google Benchmark times).
class Reporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration) times_[r.run_name.function_name + "/" + r.run_name.args] = r.GetAdjustedCPUTime();
    ConsoleReporter::ReportRuns(runs);
  }
  void Ratios() const {
    std::printf("\nline_by_line / convex_pass (CPU time):\n");
    for (const auto& [name, slow] : times_) {
      if (name.rfind("line_by_line/", 0) != 0) continue;
      const std::string n = name.substr(name.find('/') + 1);
      const auto fast = times_.find("convex_pass/" + n);
      if (fast != times_.end()) std::printf("  N = %-8s %10.1fx\n", n.c_str(), slow / fast->second);
    }
  }

 private:
  std::map<std::string, double> times_;
};

}  // namespace

BENCHMARK(convex_pass)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(line_by_line)->RangeMultiplier(10)->Range(1000, 10000)->Unit(benchmark::kMillisecond);
BENCHMARK(line_by_line)->Arg(100000)->Iterations(1)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  Reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.Ratios();
  benchmark::Shutdown();
  return 0;
}
