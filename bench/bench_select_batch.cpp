// Batch selection throughput (issue 12, docs/performance.md "Batch selection"): scenes of 11
// colours against one canonical gamut, per second, on one core, measured in one run by
//   library_batch     select_scene over the scenes, the canonical side prepared once (the
//                     library batch path: what `gmcc select --images` runs per scene);
//   cli_batch         one `gmcc select --images FILE` process for all the scenes (the library path
//                     plus reading the JSON Lines and writing one record a scene), on all cores
//                     (gmcc's default) and, `_1_thread`, on one;
//   library_record    select_scene_record (the record form, select_scene_record.h), one thread and
//                     two; cli_batch/record the same through `gmcc select --images --record`;
//   cli_per_scene     one `gmcc select --image I.csv --json` process per scene (the route before
//                     batch mode);
// and, to say where a scene's time goes, its parts: feasible_set alone, select_maps without and
// with the illuminant-space worst cases.
// Scenes: 11 distinct Munsell chips drawn (mt19937_64, seed 1) from the shipped canonical sample
// (data/samples/canonical_munsell_D55.csv, 1269 chips under D55), seen under the diagonal light
// (4/5, 9/10, 11/10), which is each scene's true light.
//
//   bench_select_batch [--scenes N] [benchmark flags]     (N distinct scenes, default 1000)
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/prepare_canonical.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/selection/mean_3d.h>
#include <gmcc/selection/select_maps.h>
#include <gmcc/selection/rule_errors.h>
#include <gmcc/selection/worst_case.h>
#include <gmcc/selection/select_scene.h>
#include <gmcc/selection/select_scene_record.h>
#include <gmcc/input/colour_csv.h>

#include <benchmark/benchmark.h>

#include "bench_support.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#ifndef GMCC_DATA_DIR
#define GMCC_DATA_DIR "data"
#endif

extern char** environ;

namespace {
using namespace gmcc;

std::size_t scene_count = 1000;

struct Workload {
  std::string dir;  // temporary folder with the files the processes read
  std::string canonical_path, scenes_path;
  std::vector<std::string> image_paths;
  std::vector<Colour> canonical;
  std::vector<std::vector<Colour>> scenes;
  Colour truth;
  std::unique_ptr<PreparedCanonical> prepared;
};

void write(const std::string& path, const std::string& text) {
  std::ofstream f(path);
  f << text;
  if (!f) throw std::runtime_error("cannot write " + path);
}

std::string csv(const Colour& c) { return to_string(c.r) + "," + to_string(c.g) + "," + to_string(c.b); }

const Workload& workload() {
  static Workload w = [] {
    Workload w;
    char tmpl[] = "/tmp/bench_select_batch-XXXXXX";
    if (!mkdtemp(tmpl)) throw std::runtime_error("mkdtemp");
    w.dir = tmpl;
    w.canonical_path = std::string(GMCC_DATA_DIR) + "/samples/canonical_munsell_D55.csv";
    w.canonical = read_colour_csv(w.canonical_path).colours;
    const Colour light{Rational(4, 5), Rational(9, 10), Rational(11, 10)};
    w.truth = light;
    std::mt19937_64 g(1);
    std::string jsonl;
    for (std::size_t s = 0; s < scene_count; ++s) {
      std::vector<std::size_t> pool(w.canonical.size());
      for (std::size_t i = 0; i < pool.size(); ++i) pool[i] = i;
      std::vector<Colour> image;
      std::string text, json = "{\"id\":" + std::to_string(s) + ",\"colours\":[";
      for (std::size_t i = 0; i < 11; ++i) {
        std::swap(pool[i], pool[i + g() % (pool.size() - i)]);
        const Colour& c = w.canonical[pool[i]];
        image.push_back({Rational(c.r * light.r), Rational(c.g * light.g), Rational(c.b * light.b)});
        text += csv(image.back()) + "\n";
        json += std::string(i ? "," : "") + "[\"" + to_string(image.back().r) + "\",\"" +
                to_string(image.back().g) + "\",\"" + to_string(image.back().b) + "\"]";
      }
      json += "],\"truth\":[\"4/5\",\"9/10\",\"11/10\"]}\n";
      jsonl += json;
      w.image_paths.push_back(w.dir + "/image" + std::to_string(s) + ".csv");
      write(w.image_paths.back(), text);
      w.scenes.push_back(std::move(image));
    }
    w.scenes_path = w.dir + "/scenes.jsonl";
    write(w.scenes_path, jsonl);
    SelectSceneOptions options;  // the defaults of `gmcc select`
    w.prepared = std::make_unique<PreparedCanonical>(prepare_canonical(w.canonical, options));
    return w;
  }();
  return w;
}

// Run the built gmcc with `args`, stdout into a file of the work folder; returns its status.
int run_gmcc(const Workload& w, const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>(GMCC_BINARY)};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string out = w.dir + "/out";
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid;
  const int e = posix_spawn(&pid, GMCC_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (e) throw std::runtime_error(std::string("posix_spawn: ") + std::strerror(e));
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// CPU seconds used so far by this process (RUSAGE_SELF) or its finished children (the gmcc runs).
double cpu_seconds(int who) {
  rusage u{};
  getrusage(who, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Scenes per wall-clock second (scenes_per_s) and per CPU second of the process that selects them
// (scenes_per_cpu_s: this one for the library, the gmcc children for the command line), which a
// busy machine disturbs less.
struct Rate {
  benchmark::State& state;
  int who;
  double start = cpu_seconds(who);
  void report(std::size_t scenes_per_iteration) {
    const double scenes = static_cast<double>(scenes_per_iteration) * static_cast<double>(state.iterations());
    state.counters["scenes_per_s"] = benchmark::Counter(scenes, benchmark::Counter::kIsRate);
    state.counters["scenes_per_cpu_s"] = scenes / (cpu_seconds(who) - start);
  }
};

void library_batch(benchmark::State& state) {
  const Workload& w = workload();
  Rate rate{state, RUSAGE_SELF};
  std::size_t i = 0;
  for (auto _ : state) {
    const SceneResult r = select_scene(*w.prepared, w.scenes[i++ % w.scenes.size()], w.truth);
    benchmark::DoNotOptimize(r.selections[gmcc::Rule::mean_3d]);
  }
  rate.report(1);
}

// Without the illuminant-space worst cases (--illuminant-worst-case off).
void library_batch_no_illuminant_worst_case(benchmark::State& state) {
  const Workload& w = workload();
  PreparedCanonical prepared = *w.prepared;
  prepared.options.illuminant_worst_case = false;
  Rate rate{state, RUSAGE_SELF};
  std::size_t i = 0;
  for (auto _ : state) {
    const SceneResult r = select_scene(prepared, w.scenes[i++ % w.scenes.size()], w.truth);
    benchmark::DoNotOptimize(r.selections[gmcc::Rule::mean_3d]);
  }
  rate.report(1);
}

// The record form (select_scene_record.h): the same scenes, from enclosures; `exact_route` counts
// the scenes that took select_scene instead (per scene).
void library_record(benchmark::State& state, bool illuminant_worst_case) {
  const Workload& w = workload();
  SceneChoices choices;
  choices.illuminant_worst_case = illuminant_worst_case;
  Rate rate{state, RUSAGE_SELF};
  std::size_t i = 0, exact = 0;
  for (auto _ : state) {
    const SelectRecord r = select_scene_record(*w.prepared, w.scenes[i++ % w.scenes.size()], w.truth, choices);
    exact += r.exact_route;
    benchmark::DoNotOptimize(r.selections[gmcc::Rule::mean_3d]);
  }
  rate.report(1);
  state.counters["exact_route"] = static_cast<double>(exact) / static_cast<double>(state.iterations());
}

// The record form on two threads, each taking every other scene (the 2 cores of issue 28's
// target): scenes per wall-clock second of both.
void library_record_2_threads(benchmark::State& state) {
  const Workload& w = workload();
  Rate rate{state, RUSAGE_SELF};
  const std::size_t per_iteration = 200;
  std::size_t start = 0;
  for (auto _ : state) {
    auto run = [&](std::size_t first) {
      for (std::size_t k = first; k < per_iteration; k += 2) {
        const SelectRecord r = select_scene_record(*w.prepared, w.scenes[(start + k) % w.scenes.size()], w.truth, SceneChoices{});
        benchmark::DoNotOptimize(r.selections[gmcc::Rule::mean_3d]);
      }
    };
    std::thread other(run, 1);
    run(0);
    other.join();
    start += per_iteration;
  }
  rate.report(per_iteration);
}

void cli_batch(benchmark::State& state, bool illuminant_worst_case, bool record, const char* threads) {
  const Workload& w = workload();
  std::vector<std::string> args{"select", "--canonical", w.canonical_path, "--images", w.scenes_path,
                                "--canonical-illuminant", "1,1,1", "--illuminant-worst-case",
                                illuminant_worst_case ? "on" : "off"};
  if (record) args.push_back("--record");
  if (*threads) args.insert(args.end(), {"--threads", threads});  // else all cores, gmcc's default
  Rate rate{state, RUSAGE_CHILDREN};
  for (auto _ : state)
    if (run_gmcc(w, args) != 0) state.SkipWithError("gmcc select --images failed");
  rate.report(w.scenes.size());
}

void cli_per_scene(benchmark::State& state) {
  const Workload& w = workload();
  Rate rate{state, RUSAGE_CHILDREN};
  std::size_t i = 0;
  for (auto _ : state)
    if (run_gmcc(w, {"select", "--canonical", w.canonical_path, "--image",
                     w.image_paths[i++ % w.image_paths.size()], "--json", "--truth", "4/5,9/10,11/10",
                     "--canonical-illuminant", "1,1,1"}) != 0)
      state.SkipWithError("gmcc select failed");
  rate.report(1);
}

// The parts of a scene.
void part_feasible_set(benchmark::State& state) {
  const Workload& w = workload();
  Rate rate{state, RUSAGE_SELF};
  std::size_t i = 0;
  for (auto _ : state) {
    const auto q = perspective_chromaticities(w.scenes[i++ % w.scenes.size()], NonPositiveBluePolicy::drop);
    benchmark::DoNotOptimize(feasible_set(w.prepared->constraints, q.points));
  }
  rate.report(1);
}

void part_select_maps(benchmark::State& state, bool illuminant) {
  const Workload& w = workload();
  std::vector<ConvexSet2> F;
  for (const auto& s : w.scenes)
    F.push_back(feasible_set(w.prepared->constraints, perspective_chromaticities(s, NonPositiveBluePolicy::drop).points));
  std::size_t i = 0;
  SelectionOptions o;
  if (illuminant) o.illuminant_worst_case_for = Colour{1, 1, 1};
  Rate rate{state, RUSAGE_SELF};
  for (auto _ : state) benchmark::DoNotOptimize(select_maps(F[i++ % F.size()], o));
  rate.report(1);
}

// One step of select_maps, or the truth's errors, over the scenes' exact F.
void part_step(benchmark::State& state, int step) {
  const Workload& w = workload();
  std::vector<ConvexSet2> F;
  std::vector<Selections> sel;
  for (const auto& s : w.scenes) {
    F.push_back(feasible_set(w.prepared->constraints, perspective_chromaticities(s, NonPositiveBluePolicy::drop).points));
    sel.push_back(select_maps(F.back()));
  }
  const Point2 truth{Rational(11, 8), Rational(11, 9)};
  Rate rate{state, RUSAGE_SELF};
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % F.size();
    switch (step) {
      case 0: benchmark::DoNotOptimize(max_area(F[k])); break;
      case 1: benchmark::DoNotOptimize(mean_2d(F[k])); break;
      case 2: benchmark::DoNotOptimize(mean_3d(F[k])); break;
      case 3: benchmark::DoNotOptimize(worst_case_map_deg(F[k], *sel[k][gmcc::Rule::mean_2d]->estimate.exact)); break;
      default:
        for (const auto* x : {&sel[k][gmcc::Rule::max_area], &sel[k][gmcc::Rule::mean_2d], &sel[k][gmcc::Rule::mean_3d]})
          benchmark::DoNotOptimize(exact_rule_errors(**x, truth, Colour{1, 1, 1}));
    }
  }
  rate.report(1);
}

BENCHMARK(library_batch)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(library_batch_no_illuminant_worst_case)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(library_record, all, true)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(library_record, no_illuminant_worst_case, false)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(library_record_2_threads)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(cli_batch, all, true, false, "")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(cli_batch, all_1_thread, true, false, "1")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(cli_batch, no_illuminant_worst_case, false, false, "")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK_CAPTURE(cli_batch, record, true, true, "")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);
BENCHMARK_CAPTURE(cli_batch, record_1_thread, true, true, "1")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);
BENCHMARK(cli_per_scene)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(100);
BENCHMARK(part_feasible_set)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(part_select_maps, no_illuminant_worst_case, false)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(part_select_maps, with_illuminant_worst_case, true)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(part_step, max_area, 0)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(part_step, mean_2d, 1)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(part_step, mean_3d, 2)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(part_step, worst_case_map_of_mean_2d, 3)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(part_step, truth_errors_3_rules, 4)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  gmcc::bench::initialise(argc, argv, {&scene_count, nullptr, nullptr});
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  // The work folder and its files.
  const Workload& w = workload();
  for (const std::string& p : w.image_paths) std::remove(p.c_str());
  std::remove(w.scenes_path.c_str());
  std::remove((w.dir + "/out").c_str());
  rmdir(w.dir.c_str());
  return 0;
}
