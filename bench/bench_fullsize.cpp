// One full-size photograph, step by step (issue 46 items 1 and 4; docs/performance.md "A
// full-size image against decoding it"): decoding the PNG, the pixel rules (Gijsenij et al.
// 2010's), the exact 3-D hull colour set, the 2-D chromaticity lifts, the 3-D estimate with every rule, the five
// baselines, and all of it together as `gmcc benchmark` does for one image with its default
// methods. The ratios to decoding alone are what docs/performance.md reports.
//
//   bench_fullsize [IMAGE.png] [Google Benchmark flags]
//
// Without IMAGE: a noisy Mondrian of the Gehler–Shi size, 2041 × 1359 (mondrian.h: the shipped
// sample's 8 chips, noise ±256 codes, so that most pixels are distinct colours). With IMAGE (for
// example a stand-in made by make_fullsize_dataset from a real photograph): that file. The
// canonical gamut is learned from the image's own colours under four lights (white and three
// that tilt it by 6/5 and 4/5 in two channels), as a canonical gamut is learned from the lights of
// many images: F3 is then a solid of maps around theirs, as on a dataset, where the image under
// one white light alone would leave the single map 1 (a degenerate F3, the LP route). The cost of
// F3 and the rules depends on the image's hull and the gamut's facets, not on where they came from.
#include <gmcc/input/colour_csv.h>
#include <gmcc/input/image_file.h>
#include <gmcc/input/text_file.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/grey_edge.h>
#include <gmcc/photo/image_hull_sets.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/photo/learn_canonical.h>
#include <gmcc/validation/mondrian.h>

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

namespace {

std::string g_image_path;  // empty: the Mondrian

const std::string& png_bytes() {
  static const std::string bytes = [] {
    if (!g_image_path.empty()) return gmcc::read_binary_file(g_image_path, gmcc::max_image_file_bytes, "image file");
    const gmcc::ColourTable chips =
        gmcc::read_colour_csv(std::string(GMCC_DATA_DIR) + "/samples/image_munsell_D75.csv");
    gmcc::MondrianSpec spec;
    spec.width = 2041;
    spec.height = 1359;
    spec.noise = 256;
    spec.saturated_pixels = 200;
    return gmcc::encode_png16(gmcc::render_mondrian(chips.colours, spec).image);
  }();
  return bytes;
}

const gmcc::RgbImage& decoded() {
  static const gmcc::RgbImage image = gmcc::decode_image(png_bytes(), "bench.png");
  return image;
}

gmcc::PixelRules rules(gmcc::ColourSet set) {
  gmcc::PixelRules r = gmcc::gijsenij_pixel_rules();
  r.saturation = (1u << decoded().bits) - 1;
  r.colour_set = set;
  return r;
}

const gmcc::CanonicalConstraints3& canonical() {
  static const gmcc::CanonicalConstraints3 c = [] {
    gmcc::CanonicalLearner3 learner;
    const std::vector<gmcc::Colour> colours = gmcc::image_colours(decoded(), rules(gmcc::ColourSet::hull_3d)).colours;
    const gmcc::Rational one(1), more(6, 5), less(4, 5);
    for (const gmcc::Colour& light : {gmcc::Colour{one, one, one}, gmcc::Colour{more, one, less},
                                      gmcc::Colour{less, more, one}, gmcc::Colour{one, less, more}})
      learner.add(colours, light);
    return gmcc::CanonicalConstraints3(learner.gamut());
  }();
  return c;
}

gmcc::Estimate3Options estimate_options() {
  gmcc::Estimate3Options o;
  o.exact_feasible_set = false;  // as the benchmark and the command line ask
  return o;
}

void baselines(const gmcc::RgbImage& image, const std::vector<bool>& kept) {
  std::vector<gmcc::GreyEdgeParameters> parameters;
  for (gmcc::Baseline b : gmcc::all_baselines)
    parameters.push_back(gmcc::baseline_parameters(b));
  benchmark::DoNotOptimize(gmcc::grey_edge_estimates(image, 0, kept, parameters));
}

void decode(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(gmcc::decode_image(png_bytes(), "bench.png"));
  state.counters["pixels"] = static_cast<double>(decoded().width * decoded().height);
}

void kept_pixels(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(gmcc::kept_pixels(decoded(), rules(gmcc::ColourSet::hull_3d)));
}

void hull_3d_colours(benchmark::State& state) {
  for (auto _ : state) {
    const gmcc::ImageColours c = gmcc::image_colours(decoded(), rules(gmcc::ColourSet::hull_3d));
    state.counters["hull_vertices"] = static_cast<double>(c.counts.hull_vertices);
  }
}

void chromaticity_lifts(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(gmcc::image_colours(decoded(), rules(gmcc::ColourSet::hull)));
}

// The two colour sets from one sort of the distinct colours, the kept pixels given.
void both_colour_sets(benchmark::State& state) {
  const gmcc::PixelRules r = rules(gmcc::ColourSet::hull_3d);
  const gmcc::KeptPixels kept = gmcc::kept_pixels(decoded(), r);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        gmcc::image_colour_sets(decoded(), r, kept, {gmcc::ColourSet::hull_3d, gmcc::ColourSet::hull}));
}

// The same two sets from the sieve (image_hull_sets: no distinct count), as the benchmark takes them.
void hull_sets(benchmark::State& state) {
  const gmcc::PixelRules r = rules(gmcc::ColourSet::hull_3d);
  const gmcc::KeptPixels kept = gmcc::kept_pixels(decoded(), r);
  for (auto _ : state)
    benchmark::DoNotOptimize(gmcc::image_hull_sets(decoded(), r, kept, {gmcc::ColourSet::hull_3d, gmcc::ColourSet::hull}));
}

void estimate_3d_every_rule(benchmark::State& state) {
  const gmcc::ImageColours c = gmcc::image_colours(decoded(), rules(gmcc::ColourSet::hull_3d));
  for (auto _ : state) {
    const gmcc::ImageEstimate3 e = gmcc::estimate_3d(canonical(), c, estimate_options());
    state.counters["f3_vertices"] = static_cast<double>(e.lazy_feasible.size());
    state.counters["f3_kind"] = static_cast<double>(e.lazy_feasible.kind());
  }
  state.counters["canonical_facets"] = static_cast<double>(canonical().half_spaces());
}

void five_baselines(benchmark::State& state) {
  const std::vector<bool> kept = gmcc::kept_pixels(decoded(), rules(gmcc::ColourSet::hull_3d)).kept;
  for (auto _ : state) baselines(decoded(), kept);
}

// What `gmcc benchmark` does for one image with its default methods, minus the 2-D selection:
// decode, the kept pixels once, the 3-D hull colours and the 2-D lifts from one sieve
// (image_hull_sets), every 3-D rule, the baselines.
void whole_image(benchmark::State& state) {
  canonical();
  for (auto _ : state) {
    const gmcc::RgbImage image = gmcc::decode_image(png_bytes(), "bench.png");
    const gmcc::PixelRules r = rules(gmcc::ColourSet::hull_3d);
    const gmcc::KeptPixels kept = gmcc::kept_pixels(image, r);
    const std::vector<gmcc::ImageColours> sets =
        gmcc::image_hull_sets(image, r, kept, {gmcc::ColourSet::hull_3d, gmcc::ColourSet::hull});
    benchmark::DoNotOptimize(gmcc::estimate_3d(canonical(), sets[0], estimate_options()));
    baselines(image, kept.kept);
  }
}

}  // namespace

BENCHMARK(decode)->Unit(benchmark::kMillisecond);
BENCHMARK(kept_pixels)->Unit(benchmark::kMillisecond);
BENCHMARK(hull_3d_colours)->Unit(benchmark::kMillisecond);
BENCHMARK(chromaticity_lifts)->Unit(benchmark::kMillisecond);
BENCHMARK(both_colour_sets)->Unit(benchmark::kMillisecond);
BENCHMARK(hull_sets)->Unit(benchmark::kMillisecond);
BENCHMARK(estimate_3d_every_rule)->Unit(benchmark::kMillisecond);
BENCHMARK(five_baselines)->Unit(benchmark::kMillisecond);
BENCHMARK(whole_image)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  if (argc > 1 && argv[1][0] != '-') {
    g_image_path = argv[1];
    for (int i = 1; i + 1 < argc; ++i) argv[i] = argv[i + 1];
    --argc;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
