// Per-scene cost of the synthetic experiment (issue "Performance"), as Google Benchmark targets
// on the same scenes in one process:
//   scene_double     the pipeline on plain doubles, written the straightforward way (the ratio's
//                    baseline: no filters, no certification, no exactness; wrong sometimes);
//   scene_certified  what `gmcc reproduce` runs per scene: the exact feasible set kept symbolic
//                    (feasible_polygon), the truth's membership decided exactly, and the three
//                    rules' map, worst-case, illuminant and reproduction errors certified by
//                    rule_errors (exact route where it declines);
//   scene_exact      the exact route for every scene: exact F, select_maps (exact max-area and
//                    2-D mean, certified 3-D mean) and the exact angles;
//   whole_experiment run_gamut_experiment on 2 threads, 4 × 11 × N scenes (wall time, setup
//                    excluded; --scenes 500 for the paper's 22,000).
// Scenes: per test light (D75, D100, P2856, P15000), K Munsell chips each (--surfaces K,
// default 11, the "11 image colours"; 0 cycles K through 1..11 like the experiment).
//
//   bench_scene [--surfaces K] [--scenes N] [benchmark flags, e.g. --benchmark_format=json]
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/certified_rule_errors.h>
#include <gmcc/selection/select_maps.h>
#include <gmcc/input/spectral_table.h>
#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <benchmark/benchmark.h>

#include "bench_support.h"

#include "../tests/baseline/double_pipeline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <map>
#include <random>
#include <string>
#include <vector>

#ifndef GMCC_DATA_DIR
#define GMCC_DATA_DIR "data"
#endif

namespace {
using namespace gmcc;

// ---------------------------------------------------------------- the plain-double pipeline
using P = std::array<double, 2>;

using baseline::cross;
using baseline::hull;  // Andrew's monotone chain, CCW, collinear dropped

struct DLine {
  double a, b, c;  // a·x + b·y <= c
};

void clip(std::vector<P>& poly, const DLine& l, std::vector<P>& out) {
  out.clear();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const P& p = poly[i];
    const P& q = poly[(i + 1) % n];
    const double sp = l.a * p[0] + l.b * p[1] - l.c, sq = l.a * q[0] + l.b * q[1] - l.c;
    if (sp <= 0) out.push_back(p);
    if ((sp < 0 && sq > 0) || (sp > 0 && sq < 0)) {
      const double t = sp / (sp - sq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  poly.swap(out);
}

struct DoubleScene {
  std::array<P, 3> maps;
  std::array<double, 3> error, worst, illuminant, reproduction;
  bool empty = false;
};

double angle(const std::array<double, 3>& u, const std::array<double, 3>& v) {
  const double c0 = u[1] * v[2] - u[2] * v[1], c1 = u[2] * v[0] - u[0] * v[2], c2 = u[0] * v[1] - u[1] * v[0];
  return std::atan2(std::sqrt(c0 * c0 + c1 * c1 + c2 * c2), u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) * (180 / M_PI);
}
double map_angle(const P& m, const P& t) { return angle({m[0], m[1], 1}, {t[0], t[1], 1}); }

DoubleScene double_scene(const std::vector<DLine>& gamut, const P& gamut_max, const std::vector<P>& image,
                         const P& truth, const std::array<double, 3>& c) {
  DoubleScene s;
  const std::vector<P> qs = hull(image);
  double q1 = 0, q2 = 0;
  for (const P& q : qs) q1 = std::max(q1, q[0]), q2 = std::max(q2, q[1]);
  std::vector<P> poly{{0, 0}, {gamut_max[0] / q1, 0}, {gamut_max[0] / q1, gamut_max[1] / q2}, {0, gamut_max[1] / q2}};
  std::vector<P> buffer;
  for (const P& q : qs)
    for (const DLine& g : gamut) {
      clip(poly, {g.a * q[0], g.b * q[1], g.c}, buffer);
      if (poly.empty()) {
        s.empty = true;
        return s;
      }
    }
  // max-area: vertices and edge stationary points
  const std::size_t n = poly.size();
  P best = poly[0];
  double best_value = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const P& p = poly[i];
    const P& q = poly[(i + 1) % n];
    if (p[0] * p[1] > best_value) best_value = p[0] * p[1], best = p;
    const double da = q[0] - p[0], db = q[1] - p[1];
    if (da * db < 0) {
      const double t = -(da * p[1] + db * p[0]) / (2 * da * db);
      const P m{p[0] + t * da, p[1] + t * db};
      if (t > 0 && t < 1 && m[0] * m[1] > best_value) best_value = m[0] * m[1], best = m;
    }
  }
  s.maps[0] = best;
  // 2-D mean: area centroid by a fan from vertex 0
  double w_sum = 0, x_sum = 0, y_sum = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double w = cross(poly[0], poly[i], poly[i + 1]);
    w_sum += w, x_sum += w * (poly[0][0] + poly[i][0] + poly[i + 1][0]), y_sum += w * (poly[0][1] + poly[i][1] + poly[i + 1][1]);
  }
  s.maps[1] = w_sum > 0 ? P{x_sum / (3 * w_sum), y_sum / (3 * w_sum)} : poly[0];
  // 3-D mean: τ = ½ Σ θ_i c_i/|c_i|
  double t[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const P& a = poly[i];
    const P& b = poly[(i + 1) % n];
    const double c0 = a[1] - b[1], c1 = b[0] - a[0], c2 = a[0] * b[1] - a[1] * b[0];
    const double norm = std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
    if (norm == 0) continue;
    const double w = std::atan2(norm, a[0] * b[0] + a[1] * b[1] + 1) / norm;
    t[0] += w * c0, t[1] += w * c1, t[2] += w * c2;
  }
  s.maps[2] = t[2] != 0 ? P{t[0] / t[2], t[1] / t[2]} : poly[0];
  for (int r = 0; r < 3; ++r) {
    const P& m = s.maps[r];
    s.error[r] = map_angle(m, truth);
    s.worst[r] = 0;
    for (const P& v : poly) s.worst[r] = std::max(s.worst[r], map_angle(m, v));
    s.illuminant[r] = angle({c[0] / m[0], c[1] / m[1], c[2]}, {c[0] / truth[0], c[1] / truth[1], c[2]});
    s.reproduction[r] = angle({m[0] / truth[0], m[1] / truth[1], 1}, {1, 1, 1});
  }
  return s;
}

// ---------------------------------------------------------------- the exact routes
double exact_scene(const CanonicalConstraints& gamut, const std::vector<Point2>& image, const Point2& truth,
                   const Colour& c, int& truth_inside) {
  const ConvexSet2 F = feasible_set(gamut, image);
  if (F.kind == ConvexKind::empty) return 0;
  truth_inside += contains(F, truth);
  const Selections sel = select_maps(F);
  double sum = 0;
  for (const auto* x : {&sel[gmcc::Rule::max_area], &sel[gmcc::Rule::mean_2d], &sel[gmcc::Rule::mean_3d]}) {
    const MapEstimate& e = (*x)->estimate;
    const Point2 m = e.exact ? *e.exact : Point2{rational_from_double(e.map[0]), rational_from_double(e.map[1])};
    sum += map_angular_error_deg(m, truth) + *(*x)->worst_case_deg;
    if (sgn(m.x) > 0 && sgn(m.y) > 0)
      sum += illuminant_angular_error_deg(m, truth, c) + reproduction_angular_error_deg(m, truth);
  }
  return sum;
}

// As run_cell does it: the certified route, the exact one where it declines.
double certified_scene(const CanonicalConstraints& gamut, const std::vector<const Point2*>& colours,
                       const std::vector<Point2>& image, const Point2& truth, const Colour& c, int& truth_inside,
                       int& declined) {
  const FeasiblePolygon P = feasible_polygon(gamut, colours);
  if (P.kind() == ConvexKind::empty) return 0;
  const bool inside = P.contains(truth);
  const auto errors = certified_rule_errors(P, truth, c);
  if (!errors) {
    ++declined;
    return exact_scene(gamut, image, truth, c, truth_inside);
  }
  truth_inside += inside;
  double sum = 0;
  for (const RuleErrors& e : *errors)
    sum += e.map_error_deg + e.worst_case_deg + e.illuminant_error_deg + e.reproduction_error_deg;
  return sum;
}

struct Scene {
  std::size_t light;
  std::vector<Point2> exact;
  std::vector<const Point2*> pointers;  // into exact, as the experiment passes its colours
  std::vector<P> approx;
};
struct Workload {
  ExperimentSetup setup;
  std::unique_ptr<CanonicalConstraints> prepared;
  std::vector<Scene> scenes;
  std::vector<DLine> dgamut;
  P gmax{0, 0};
  std::array<double, 3> cd{};
};
std::uint64_t scenes_per_light = 200;
int surfaces = 11;
std::string data_dir = GMCC_DATA_DIR;

const Workload& workload() {
  static const Workload w = [] {
    Workload w;
    w.setup = gmcc::bench::paper_setup(data_dir);
    const ConvexSet2 G = canonical_gamut(
        perspective_chromaticities(w.setup.canonical_surfaces, NonPositiveBluePolicy::drop).points, {});
    w.prepared = std::make_unique<CanonicalConstraints>(G);
    std::mt19937_64 g(6);
    for (std::size_t l = 0; l < w.setup.lights.size(); ++l)
      for (std::uint64_t s = 0; s < scenes_per_light; ++s) {
        const int k = surfaces > 0 ? surfaces : static_cast<int>(1 + s % 11);
        std::vector<std::size_t> pool(w.setup.lights[l].surfaces.size());
        for (std::size_t i = 0; i < pool.size(); ++i) pool[i] = i;
        std::shuffle(pool.begin(), pool.end(), g);
        Scene sc{l, {}, {}, {}};
        for (int i = 0; i < k; ++i) {
          const Point2 q = perspective_chromaticity(w.setup.lights[l].surfaces[pool[static_cast<std::size_t>(i)]]);
          sc.approx.push_back(to_double_nearest(q));
          sc.exact.push_back(q);
        }
        for (const Point2& q : sc.exact) sc.pointers.push_back(&q);
        w.scenes.push_back(std::move(sc));
      }
    // The gamut's edges as double lines a·x + b·y <= c (outward normals of the CCW edges).
    for (std::size_t i = 0; i < G.vertices.size(); ++i) {
      const P p = to_double_nearest(G.vertices[i]), q = to_double_nearest(G.vertices[(i + 1) % G.vertices.size()]);
      w.dgamut.push_back({q[1] - p[1], p[0] - q[0], (q[1] - p[1]) * p[0] + (p[0] - q[0]) * p[1]});
      w.gmax = {std::max(w.gmax[0], p[0]), std::max(w.gmax[1], p[1])};
    }
    const Colour& c = w.setup.canonical_light;
    w.cd = {to_double_nearest(c.r), to_double_nearest(c.g), to_double_nearest(c.b)};
    return w;
  }();
  return w;
}

// One benchmark iteration is one scene, cycling through the workload; counters per scene.
void scene_double(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const Scene& s = w.scenes[i++ % w.scenes.size()];
    const DoubleScene d = double_scene(w.dgamut, w.gmax, s.approx, to_double_nearest(w.setup.lights[s.light].true_map), w.cd);
    sink += d.empty ? 0 : d.error[0] + d.worst[2] + d.illuminant[1] + d.reproduction[2];
  }
  benchmark::DoNotOptimize(sink);
}
void scene_certified(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  int inside = 0, declined = 0;
  double sink = 0;
  for (auto _ : state) {
    const Scene& s = w.scenes[i++ % w.scenes.size()];
    sink += certified_scene(*w.prepared, s.pointers, s.exact, w.setup.lights[s.light].true_map, w.setup.canonical_light,
                            inside, declined);
  }
  benchmark::DoNotOptimize(sink);
  state.counters["declined"] = benchmark::Counter(declined, benchmark::Counter::kAvgIterations);
  state.counters["truth_in_F"] = benchmark::Counter(inside, benchmark::Counter::kAvgIterations);
}
void scene_exact(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  int inside = 0;
  double sink = 0;
  for (auto _ : state) {
    const Scene& s = w.scenes[i++ % w.scenes.size()];
    sink += exact_scene(*w.prepared, s.exact, w.setup.lights[s.light].true_map, w.setup.canonical_light, inside);
  }
  benchmark::DoNotOptimize(sink);
  state.counters["truth_in_F"] = benchmark::Counter(inside, benchmark::Counter::kAvgIterations);
}
// The whole synthetic experiment in this process (setup excluded): 4 lights × 11 counts ×
// `--scenes` scenes, on 2 threads, as `gmcc reproduce synthetic` runs it. Wall time.
void whole_experiment(benchmark::State& state) {
  const Workload& w = workload();
  ExperimentConfig config;
  config.scenes = scenes_per_light;
  config.threads = 2;
  for (auto _ : state) benchmark::DoNotOptimize(run_gamut_experiment(w.setup, config).cells.size());
  state.counters["scenes"] = static_cast<double>(4 * 11 * scenes_per_light);
}

BENCHMARK(scene_double)->Unit(benchmark::kMicrosecond);
BENCHMARK(scene_certified)->Unit(benchmark::kMicrosecond);
BENCHMARK(scene_exact)->Unit(benchmark::kMicrosecond);
BENCHMARK(whole_experiment)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  gmcc::bench::initialise(argc, argv, {&scenes_per_light, &surfaces, &data_dir});
  workload();  // built before any timing
  benchmark::AddCustomContext("surfaces", surfaces > 0 ? std::to_string(surfaces) : "1-11");
  benchmark::AddCustomContext("canonical_vertices", std::to_string(workload().dgamut.size()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
