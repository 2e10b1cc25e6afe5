// Forsyth's CRULE in 3-D (issue 16), as Google Benchmark targets on the same scenes in one run:
//   crule_prepared     feasible_set_3d from a CanonicalConstraints3 prepared once (filtered clip);
//   crule_lp           the route it replaced (canonical hull per call, image hull, exact LP,
//                      CGAL half-space intersection), kept as the tests' oracle;
//   crule_3d_prepared  F3 and both selections (max-volume, centroid) with their worst cases, the
//                      exact route (exact volume and centroid: `gmcc select --space 3d`);
//   crule_3d_certified the same on the certified route the experiments take (centroid certified,
//                      no volume);
//   crule_lazy, crule_3d_lazy  F3 kept symbolic (LazyConvexSet3), alone and with both selections
//                      and their worst cases on the certified route;
//   crule_3d_lazy_selections  those selections alone, on the scenes' lazy F3s remade fresh;
//   max_volume_filtered / max_volume_unfiltered, centroid_exact / centroid_certified
//                      one selection on the scenes' F3s (built once): the staged max_volume
//                      against its exact stage over every candidate; the exact centroid against
//                      the certified one;
//   crule_double, crule_3d_double  the same-run baseline in plain doubles (double_crule.h): F3
//                      alone (compare crule_lazy), and F3 with both selections and their worst
//                      cases (compare crule_3d_lazy); checked against the exact route on 50
//                      scenes over every light before any timing (check_double_crule, the
//                      differences in the benchmark context as double_check);
//   feasible_polygon_2d, scene_certified_2d  the 2-D certified route on the same scenes
//                      (feasible_polygon, then rule_errors as the experiment runs it);
//   select_3d/N        `gmcc select --space 3d` without file reading: F3 of an image of N colours
//                      against the Munsell/D55 canonical gamut (1269 colours and black);
//   crule_experiment   the CRULE feasible sets of the full experiment's 22,000 scenes (4 lights
//                      × 11 counts × 500 scenes, 1–11 surfaces), on 2 threads (wall time).
// Scenes: per test light (D75, D100, P2856, P15000), K Munsell chips (--surfaces K, default 11).
//
//   bench_crule [--surfaces K] [--scenes N] [--data DIR] [benchmark flags]
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_polygon.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/selection/centroid_3.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/max_volume.h>
#include <gmcc/selection/certified_rule_errors.h>
#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/input/spectral_table.h>
#include <gmcc/validation/synthetic_experiment.h>

#include "support/cgal_references.h"
#include "internal/centroid_3_route.h"
#include "internal/max_volume_route.h"

#include <benchmark/benchmark.h>

#include "bench_support.h"
#include "double_crule.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

#ifndef GMCC_DATA_DIR
#define GMCC_DATA_DIR "data"
#endif

namespace {
using namespace gmcc;

struct Scene {
  std::size_t light;
  std::vector<Colour> colours;
  std::vector<Point2> chromaticities;
  std::vector<const Point2*> pointers;
  std::vector<gmcc::bench::D3> approx;  // the colours as the nearest doubles (the double route's input)
};
struct Workload {
  ExperimentSetup setup;
  std::unique_ptr<CanonicalConstraints> prepared_2d;
  std::unique_ptr<CanonicalConstraints3> prepared_3d;
  gmcc::bench::DoubleGamut3 gamut_double;  // G_c3's facets in doubles, prepared once as prepared_3d
  std::vector<Scene> scenes;
  std::vector<std::vector<Colour>> experiment;  // 4 × 11 × 500 scenes, 1–11 surfaces
};
std::uint64_t scenes_per_light = 200;
int surfaces = 11;
std::string data_dir = GMCC_DATA_DIR;

std::vector<std::size_t> shuffled(std::size_t n, std::mt19937_64& g) {
  std::vector<std::size_t> pool(n);
  for (std::size_t i = 0; i < n; ++i) pool[i] = i;
  std::shuffle(pool.begin(), pool.end(), g);
  return pool;
}

const Workload& workload() {
  static const Workload w = [] {
    Workload w;
    w.setup = gmcc::bench::paper_setup(data_dir);
    w.prepared_2d = std::make_unique<CanonicalConstraints>(canonical_gamut(
        perspective_chromaticities(w.setup.canonical_surfaces, NonPositiveBluePolicy::drop).points, {}));
    w.prepared_3d = std::make_unique<CanonicalConstraints3>(w.setup.canonical_surfaces);
    w.gamut_double = gmcc::bench::double_gamut_3(w.setup.canonical_surfaces);
    std::mt19937_64 g(6);
    for (std::size_t l = 0; l < w.setup.lights.size(); ++l)
      for (std::uint64_t s = 0; s < scenes_per_light; ++s) {
        const std::vector<std::size_t> pool = shuffled(w.setup.lights[l].surfaces.size(), g);
        Scene sc{l, {}, {}, {}, {}};
        for (int i = 0; i < surfaces; ++i) {
          const Colour& c = w.setup.lights[l].surfaces[pool[static_cast<std::size_t>(i)]];
          sc.colours.push_back(c);
          sc.chromaticities.push_back(perspective_chromaticity(c));
          sc.approx.push_back({to_double_nearest(c.r), to_double_nearest(c.g), to_double_nearest(c.b)});
        }
        for (const Point2& q : sc.chromaticities) sc.pointers.push_back(&q);
        w.scenes.push_back(std::move(sc));
      }
    std::mt19937_64 e(7);
    for (std::size_t l = 0; l < w.setup.lights.size(); ++l)
      for (int n = 1; n <= 11; ++n)
        for (int s = 0; s < 500; ++s) {
          const std::vector<std::size_t> pool = shuffled(w.setup.lights[l].surfaces.size(), e);
          std::vector<Colour> c;
          for (int i = 0; i < n; ++i) c.push_back(w.setup.lights[l].surfaces[pool[static_cast<std::size_t>(i)]]);
          w.experiment.push_back(std::move(c));
        }
    return w;
  }();
  return w;
}

// N image colours: random mixtures of three Munsell chips under D75 with a random shading,
// quantised to 16 bits (k/65535 of the brightest channel), all distinct; seeded.
std::vector<Colour> image_colours(std::size_t n) {
  const Workload& w = workload();
  const std::vector<Colour>& s = w.setup.lights[0].surfaces;
  double top = 0;
  for (const Colour& c : s) top = std::max({top, to_double_nearest(c.r), to_double_nearest(c.g), to_double_nearest(c.b)});
  std::mt19937_64 g(8);
  std::uniform_int_distribution<std::size_t> pick(0, s.size() - 1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Colour> out;
  std::vector<std::array<long, 3>> seen;
  while (out.size() < n) {
    const Colour &a = s[pick(g)], &b = s[pick(g)], &c = s[pick(g)];
    double x = unit(g), y = unit(g);
    if (x + y > 1) x = 1 - x, y = 1 - y;
    const double f = 0.2 + 0.8 * unit(g);
    std::array<long, 3> q;
    const Colour* cs[3] = {&a, &b, &c};
    for (int k = 0; k < 3; ++k) {
      double v = 0;
      const double wts[3] = {x, y, 1 - x - y};
      for (int j = 0; j < 3; ++j) {
        const Rational& ch = k == 0 ? cs[j]->r : k == 1 ? cs[j]->g : cs[j]->b;
        v += wts[j] * to_double_nearest(ch);
      }
      q[k] = std::lround(f * v / top * 65535);
    }
    seen.push_back(q);
    out.push_back({Rational(q[0], 65535), Rational(q[1], 65535), Rational(q[2], 65535)});
  }
  // Distinct colours, as an image's colour set: drop repeats (kept order-independent by sorting).
  std::vector<std::size_t> order(out.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return seen[i] < seen[j]; });
  std::vector<Colour> unique;
  for (std::size_t i = 0; i < order.size(); ++i)
    if (i == 0 || seen[order[i]] != seen[order[i - 1]]) unique.push_back(out[order[i]]);
  return unique;
}

void crule_prepared(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0, polytopes = 0;
  for (auto _ : state)
    polytopes += feasible_set_3d(*w.prepared_3d, w.scenes[i++ % w.scenes.size()].colours).kind == ConvexKind3::polytope;
  state.counters["polytope"] = benchmark::Counter(static_cast<double>(polytopes), benchmark::Counter::kAvgIterations);
}
void crule_lp(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0, polytopes = 0;
  for (auto _ : state)
    polytopes += test::feasible_set_3d_reference(w.setup.canonical_surfaces, w.scenes[i++ % w.scenes.size()].colours,
                                                 CanonicalBlack::include).kind == ConvexKind3::polytope;
  state.counters["polytope"] = benchmark::Counter(static_cast<double>(polytopes), benchmark::Counter::kAvgIterations);
}
void crule_3d_prepared(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(crule_3d(*w.prepared_3d, w.scenes[i++ % w.scenes.size()].colours).volume);
}
void crule_3d_certified(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        crule_3d(*w.prepared_3d, w.scenes[i++ % w.scenes.size()].colours, Crule3dRoute::certified).centroid);
}
// F3 kept symbolic (lazy_convex_set_3.h): no vertex in lowest terms.
void crule_lazy(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  for (auto _ : state) {
    const std::vector<Colour>& image = w.scenes[i++ % w.scenes.size()].colours;
    benchmark::DoNotOptimize(feasible_set_3d_lazy({{w.prepared_3d.get(), &image}}).size());
  }
}
// The certified route of crule_3d_certified on the lazy F3, the exact F3 never made (what
// estimate_3d runs for the CLI and Python): max-volume and the certified centroid with their
// worst cases.
void crule_3d_lazy(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  for (auto _ : state) {
    const std::vector<Colour>& image = w.scenes[i++ % w.scenes.size()].colours;
    const LazyConvexSet3 F = feasible_set_3d_lazy({{w.prepared_3d.get(), &image}});
    if (F.kind() == ConvexKind3::empty) continue;
    benchmark::DoNotOptimize(with_worst_case(F, max_volume(F)));
    benchmark::DoNotOptimize(with_worst_case(F, centroid_3(F, Crule3dRoute::certified)));
  }
}
// The scenes' non-empty lazy F3s as feasible_set_3d_lazy makes them, kept as their parts (kind,
// homogeneous vertices in canonical order, faces) so that a fresh set, no vertex yet exact, can be
// remade from them outside the timing.
struct LazyParts {
  ConvexKind3 kind;
  std::vector<std::array<mpz_class, 4>> homogeneous;
  std::vector<std::vector<std::size_t>> faces;
};
const std::vector<LazyParts>& lazy_feasible_sets() {
  static const std::vector<LazyParts> sets = [] {
    std::vector<LazyParts> out;
    for (const Scene& s : workload().scenes) {
      const LazyConvexSet3 F = feasible_set_3d_lazy({{workload().prepared_3d.get(), &s.colours}});
      if (F.kind() == ConvexKind3::empty) continue;
      LazyParts p{F.kind(), {}, F.faces()};
      for (std::size_t i = 0; i < F.size(); ++i) p.homogeneous.push_back(F.homogeneous(i));
      out.push_back(std::move(p));
    }
    return out;
  }();
  return sets;
}
// crule_3d_lazy's selections alone: max-volume and the certified centroid with their worst cases
// on the scenes' lazy F3s, each remade fresh (no vertex exact yet, as crule_3d_lazy sees it)
// outside the timing.
void crule_3d_lazy_selections(benchmark::State& state) {
  const std::vector<LazyParts>& sets = lazy_feasible_sets();
  const auto& stages = internal::max_volume_stage_counts();
  const std::uint64_t filter0 = stages[0], exact0 = internal::certified_centroid_stage_counts()[1];
  std::size_t i = 0, made = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const LazyParts& p = sets[i++ % sets.size()];
    const LazyConvexSet3 F = LazyConvexSet3::from_homogeneous(p.kind, p.homogeneous, p.faces);
    state.ResumeTiming();
    benchmark::DoNotOptimize(with_worst_case(F, max_volume(F)));
    benchmark::DoNotOptimize(with_worst_case(F, centroid_3(F, Crule3dRoute::certified)));
    made += F.exact_vertices();
  }
  const auto per_scene = [&](double x) { return benchmark::Counter(x, benchmark::Counter::kAvgIterations); };
  state.counters["exact_vertices"] = per_scene(static_cast<double>(made));
  state.counters["mv_filter_share"] = per_scene(static_cast<double>(stages[0] - filter0));
  state.counters["centroid_exact_share"] =
      per_scene(static_cast<double>(internal::certified_centroid_stage_counts()[1] - exact0));
}
// The same in plain doubles (double_crule.h): F3 alone, then the whole scene.
void crule_double(benchmark::State& state) {
  const Workload& w = workload();
  gmcc::bench::DoubleClip3 clip;
  std::size_t i = 0, cuts = 0, rows = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(clip.feasible_set(w.gamut_double, w.scenes[i++ % w.scenes.size()].approx).vertices.size());
    cuts += clip.cuts(), rows += clip.rows();
  }
  state.counters["cuts"] = benchmark::Counter(static_cast<double>(cuts), benchmark::Counter::kAvgIterations);
  state.counters["rows"] = benchmark::Counter(static_cast<double>(rows), benchmark::Counter::kAvgIterations);
  state.counters["scans"] = benchmark::Counter(static_cast<double>(clip.scans()), benchmark::Counter::kAvgIterations);
  state.counters["scanned"] = benchmark::Counter(static_cast<double>(clip.scanned()), benchmark::Counter::kAvgIterations);
}
void crule_3d_double(benchmark::State& state) {
  const Workload& w = workload();
  gmcc::bench::DoubleClip3 clip;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto s = gmcc::bench::double_crule_scene(clip, w.gamut_double, w.scenes[i++ % w.scenes.size()].approx);
    benchmark::DoNotOptimize(s.max_volume_worst_deg);
    benchmark::DoNotOptimize(s.centroid_worst_deg);
  }
}
// The scenes' non-empty F3s, built once.
const std::vector<ConvexSet3>& feasible_sets() {
  static const std::vector<ConvexSet3> sets = [] {
    std::vector<ConvexSet3> out;
    for (const Scene& s : workload().scenes) {
      ConvexSet3 F = feasible_set_3d(*workload().prepared_3d, s.colours);
      if (F.kind != ConvexKind3::empty) out.push_back(std::move(F));
    }
    return out;
  }();
  return sets;
}
template <class Select>
void on_feasible_sets(benchmark::State& state, Select select) {
  const std::vector<ConvexSet3>& sets = feasible_sets();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(select(sets[i++ % sets.size()]).map);
}
void max_volume_filtered(benchmark::State& state) { on_feasible_sets(state, [](const ConvexSet3& F) { return max_volume(F); }); }
void max_volume_unfiltered(benchmark::State& state) {
  on_feasible_sets(state, [](const ConvexSet3& F) {
    return internal::max_volume_over(F, internal::all_max_volume_candidates(F));
  });
}
void centroid_exact(benchmark::State& state) {
  on_feasible_sets(state, [](const ConvexSet3& F) { return centroid_3(F, Crule3dRoute::exact); });
}
void centroid_certified(benchmark::State& state) {
  const std::uint64_t exact0 = internal::certified_centroid_stage_counts()[1];
  on_feasible_sets(state, [](const ConvexSet3& F) { return centroid_3(F, Crule3dRoute::certified); });
  state.counters["exact_share"] = benchmark::Counter(
      static_cast<double>(internal::certified_centroid_stage_counts()[1] - exact0), benchmark::Counter::kAvgIterations);
}
void feasible_polygon_2d(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(feasible_polygon(*w.prepared_2d, w.scenes[i++ % w.scenes.size()].pointers).kind());
}
void scene_certified_2d(benchmark::State& state) {
  const Workload& w = workload();
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const Scene& s = w.scenes[i++ % w.scenes.size()];
    const FeasiblePolygon P = feasible_polygon(*w.prepared_2d, s.pointers);
    if (P.kind() == ConvexKind::empty) continue;
    const Point2& truth = w.setup.lights[s.light].true_map;
    benchmark::DoNotOptimize(P.contains(truth));
    const auto errors = certified_rule_errors(P, truth, w.setup.canonical_light);
    if (errors)
      for (const RuleErrors& e : *errors) sink += e.map_error_deg + e.worst_case_deg;
  }
  benchmark::DoNotOptimize(sink);
}
void select_3d(benchmark::State& state) {
  const Workload& w = workload();
  const std::vector<Colour> image = image_colours(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(feasible_set_3d(*w.prepared_3d, image).vertices.size());
  state.counters["colours"] = static_cast<double>(image.size());
}
void crule_experiment(benchmark::State& state) {
  const Workload& w = workload();
  const std::clock_t cpu0 = std::clock();  // the process's CPU time, both threads
  for (auto _ : state) {
    std::atomic<std::size_t> next{0}, polytopes{0};
    auto work = [&] {
      for (std::size_t i; (i = next++) < w.experiment.size();)
        polytopes += feasible_set_3d(*w.prepared_3d, w.experiment[i]).kind == ConvexKind3::polytope;
    };
    std::thread a(work), b(work);
    a.join(), b.join();
    state.counters["polytope_share"] = static_cast<double>(polytopes) / static_cast<double>(w.experiment.size());
  }
  state.counters["scenes"] = static_cast<double>(w.experiment.size());
  state.counters["process_cpu_s"] = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
}

// The double route against the exact one on n scenes spread over the workload (every light),
// before any timing: F3's kind and vertex count (feasible_set_3d), its centroid (exact,
// convex_set_3.h) and both selections with their worst cases (crule_3d, certified route). Aborts
// with a message when they disagree grossly (a map off by a relative 1e-6, a worst case by 1e-6°,
// another kind, a vertex count off by more than a quarter; near-degenerate F3s may differ by a few
// vertices); the largest differences go into the benchmark context (double_check).
void check_double_crule(std::size_t n) {
  using gmcc::bench::D3;
  const Workload& w = workload();
  gmcc::bench::DoubleClip3 clip;
  std::size_t checked = 0, count_differs = 0, centroid_over_1e9 = 0, degenerate = 0;
  double centroid_rel = 0, selection_rel = 0, worst_deg = 0;
  auto fail = [](std::size_t i, const char* what, double v) {
    std::fprintf(stderr, "bench_crule: the double CRULE route disagrees with the exact one on scene %zu: %s (%g)\n", i, what, v);
    std::abort();
  };
  auto rel = [](const D3& a, const std::array<double, 3>& e) {
    const double scale = std::max({std::abs(e[0]), std::abs(e[1]), std::abs(e[2])});
    return std::max({std::abs(a[0] - e[0]), std::abs(a[1] - e[1]), std::abs(a[2] - e[2])}) / scale;
  };
  auto worst = [&](std::size_t i, const std::optional<double>& d, const std::optional<double>& e) {
    if (d.has_value() != e.has_value()) fail(i, "a worst case present on one route only", 0);
    if (d) worst_deg = std::max(worst_deg, std::abs(*d - *e));
    if (d && std::abs(*d - *e) > 1e-6) fail(i, "worst case, degrees apart", std::abs(*d - *e));
  };
  const std::size_t stride = std::max<std::size_t>(1, w.scenes.size() / n);
  for (std::size_t i = 0; i < w.scenes.size() && checked + degenerate < n; i += stride) {
    const Scene& s = w.scenes[i];
    const ConvexSet3 F = feasible_set_3d(*w.prepared_3d, s.colours);
    const gmcc::bench::DoubleCrule3 d = gmcc::bench::double_crule_scene(clip, w.gamut_double, s.approx);
    const bool polytope = d.kind == gmcc::bench::DoublePolytope::Kind::polytope;
    if (polytope != (F.kind == ConvexKind3::polytope)) fail(i, "F3's kind", 0);
    if (!polytope) {
      ++degenerate;
      continue;
    }
    ++checked;
    const std::size_t dv = clip.feasible_set(w.gamut_double, s.approx).vertices.size();
    count_differs += dv != F.vertices.size();
    if (4 * std::max(dv, F.vertices.size()) > 5 * std::min(dv, F.vertices.size()))
      fail(i, "F3's vertex count, double route", static_cast<double>(dv));
    const Point3 c = centroid(F);
    const double cr = rel(d.centroid, {to_double_nearest(c.x), to_double_nearest(c.y), to_double_nearest(c.z)});
    centroid_rel = std::max(centroid_rel, cr);
    centroid_over_1e9 += cr > 1e-9;
    const Crule3d e = crule_3d(*w.prepared_3d, s.colours, Crule3dRoute::certified);
    const double mr = std::max(rel(d.max_volume, e.max_volume->estimate.map), rel(d.centroid, e.centroid->estimate.map));
    selection_rel = std::max(selection_rel, mr);
    if (cr > 1e-6 || mr > 1e-6) fail(i, "a map, relative difference", std::max(cr, mr));
    worst(i, d.max_volume_worst_deg, e.max_volume->worst_case_deg);
    worst(i, d.centroid_worst_deg, e.centroid->worst_case_deg);
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "%zu scenes (every %zu-th; %zu not polytopes): vertex count differs on %zu; centroid vs exact max rel %.2g "
                "(%zu over 1e-9); selections max rel %.2g; worst cases max %.2g deg apart",
                checked + degenerate, stride, degenerate, count_differs, centroid_rel, centroid_over_1e9, selection_rel,
                worst_deg);
  benchmark::AddCustomContext("double_check", line);
}

BENCHMARK(crule_prepared)->Unit(benchmark::kMicrosecond);
BENCHMARK(crule_lp)->Unit(benchmark::kMicrosecond);
BENCHMARK(crule_3d_prepared)->Unit(benchmark::kMicrosecond);
BENCHMARK(crule_3d_certified)->Unit(benchmark::kMicrosecond);
BENCHMARK(crule_lazy)->Unit(benchmark::kMicrosecond);
BENCHMARK(crule_3d_lazy)->Unit(benchmark::kMicrosecond);
BENCHMARK(crule_3d_lazy_selections)->Unit(benchmark::kMicrosecond);
BENCHMARK(crule_double)->Unit(benchmark::kMicrosecond);
BENCHMARK(crule_3d_double)->Unit(benchmark::kMicrosecond);
BENCHMARK(max_volume_filtered)->Unit(benchmark::kMicrosecond);
BENCHMARK(max_volume_unfiltered)->Unit(benchmark::kMicrosecond);
BENCHMARK(centroid_exact)->Unit(benchmark::kMicrosecond);
BENCHMARK(centroid_certified)->Unit(benchmark::kMicrosecond);
BENCHMARK(feasible_polygon_2d)->Unit(benchmark::kMicrosecond);
BENCHMARK(scene_certified_2d)->Unit(benchmark::kMicrosecond);
BENCHMARK(select_3d)->Arg(1000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(crule_experiment)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  gmcc::bench::initialise(argc, argv, {&scenes_per_light, &surfaces, &data_dir});
  workload();  // built before any timing
  check_double_crule(50);
  benchmark::AddCustomContext("surfaces", std::to_string(surfaces));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
