// Edge-based gamut mapping against pixel gamut mapping at σ = 1, 4 and 16 (issue 46 items 2 and
// 4; docs/performance.md "Edge methods against the pixel method"): `run_benchmark` (the
// library's `gmcc benchmark`, one thread, 3 folds) on one dataset with one method at a time —
// gm3d-max-trace (the pixel method), gm3d-edge1-max-trace, gm3d-edge2-max-trace,
// gm3d-1jet-max-trace, gm3d-2jet-max-trace — and, to split the cost, the derivatives alone
// (gaussian_derivative_rows of every image, 1st and 2nd order). After the runs it prints each
// method's time over the pixel method's at the same σ: ratios measured in one run.
//
//   bench_edge_sigma [--images DIR --truths T.csv] [--size N] [google benchmark flags]
//
// Without --images: six noisy Mondrians (mondrian.h: the shipped sample's 8 chips, noise ±100
// codes, seeds 1–6) of N × N pixels (default 128), written as 16-bit PNGs to a temporary folder
// with a truth table (light (1, 1, 1): the timing does not depend on it). With --images, a truth
// table of the benchmark's `table` layout (image,r,g,b; paths under DIR), such as the NUS or
// Gehler–Shi thumbnails.
#include <gmcc/input/colour_csv.h>
#include <gmcc/photo/image_derivatives.h>
#include <gmcc/input/image_file.h>
#include <gmcc/input/truth_table.h>
#include <gmcc/validation/benchmark.h>
#include <gmcc/validation/mondrian.h>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

std::string images_dir, truths_path;
std::size_t size = 128;
std::filesystem::path made_dir;  // the Mondrians' folder, when this run wrote it

// The dataset: the given one, or the Mondrians written once to a temporary folder.
const std::vector<gmcc::BenchmarkImage>& dataset() {
  static std::vector<gmcc::BenchmarkImage> images;
  if (!images.empty()) return images;
  if (images_dir.empty()) {
    // A folder of this process's own: two runs at once (one folder for both) read each other's
    // half-written PNGs. Removed at the end of main.
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("gmcc_bench_edge_sigma_" + std::to_string(::getpid()));
    made_dir = dir;
    std::filesystem::create_directories(dir);
    const gmcc::ColourTable chips = gmcc::read_colour_csv(std::string(GMCC_DATA_DIR) + "/samples/image_munsell_D75.csv");
    std::ofstream truths(dir / "truths.csv");
    truths << "image,r,g,b\n";
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      gmcc::MondrianSpec spec;
      spec.width = spec.height = size;
      spec.columns = spec.rows = 6;
      spec.seed = seed;
      spec.noise = 100;
      const std::string name = "mondrian" + std::to_string(seed) + ".png";
      std::ofstream(dir / name, std::ios::binary) << gmcc::encode_png16(gmcc::render_mondrian(chips.colours, spec).image);
      truths << name << ",1,1,1\n";
    }
    truths.close();
    images_dir = dir.string();
    truths_path = (dir / "truths.csv").string();
  }
  images = gmcc::benchmark_dataset(images_dir, gmcc::read_truth_table(truths_path), nullptr, "", 3);
  return images;
}

const char* const kMethods[] = {"gm3d-max-trace", "gm3d-edge1-max-trace", "gm3d-edge2-max-trace",
                                "gm3d-1jet-max-trace", "gm3d-2jet-max-trace"};

// One method over the dataset at σ = range(1).
void method(benchmark::State& state) {
  gmcc::BenchmarkOptions o;
  o.methods = {kMethods[state.range(0)]};
  o.edge_sigma = static_cast<double>(state.range(1));
  o.threads = 1;
  o.pixels.rules.saturation = 65535;
  for (auto _ : state) benchmark::DoNotOptimize(gmcc::run_benchmark(dataset(), o));
}

// The 1st- and 2nd-order derivatives of every image at σ = range(0), row by row (the part of an
// edge method that depends on the filter).
void derivatives(benchmark::State& state) {
  std::vector<gmcc::RgbImage> images;
  for (const gmcc::BenchmarkImage& im : dataset()) images.push_back(gmcc::read_image(im.path));
  const double sigma = static_cast<double>(state.range(0));
  for (auto _ : state)
    for (const gmcc::RgbImage& im : images)
      for (gmcc::DerivativeOrder order : {gmcc::DerivativeOrder::first, gmcc::DerivativeOrder::second})
        gmcc::gaussian_derivative_rows(im, 0, sigma, order, [](std::size_t, const double* v) { benchmark::DoNotOptimize(v); });
}

// Records every run's real time per iteration, by name, besides printing it.
class Ratios : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) times[r.benchmark_name()] = r.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> times;
};

}  // namespace

BENCHMARK(method)->ArgsProduct({{0, 1, 2, 3, 4}, {1, 4, 16}})->Unit(benchmark::kMillisecond)->MinTime(0.5);
BENCHMARK(derivatives)->Arg(1)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const bool value = i + 1 < argc;
    if (value && !std::strcmp(argv[i], "--images")) images_dir = argv[++i];
    else if (value && !std::strcmp(argv[i], "--truths")) truths_path = argv[++i];
    else if (value && !std::strcmp(argv[i], "--size")) size = std::stoul(argv[++i]);
    else rest.push_back(argv[i]);
  }
  if (images_dir.empty() != truths_path.empty()) {
    std::fprintf(stderr, "bench_edge_sigma: --images and --truths go together\n");
    return 2;
  }
  int n = static_cast<int>(rest.size());
  benchmark::Initialize(&n, rest.data());
  dataset();
  Ratios reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nmethod / gm3d-max-trace at the same sigma (one run; %zu images):\n%-24s", dataset().size(), "method");
  for (int s : {1, 4, 16}) std::printf("  sigma %-3d", s);
  std::printf("\n");
  const auto time = [&](int m, int s) {
    const auto it = reporter.times.find("method/" + std::to_string(m) + "/" + std::to_string(s) + "/min_time:0.500");
    return it == reporter.times.end() ? 0.0 : it->second;
  };
  for (int m = 1; m < 5; ++m) {
    std::printf("%-24s", kMethods[m]);
    for (int s : {1, 4, 16}) std::printf("  %9.2f", time(0, s) > 0 ? time(m, s) / time(0, s) : 0.0);
    std::printf("\n");
  }
  if (!made_dir.empty()) std::filesystem::remove_all(made_dir);
  return 0;
}
