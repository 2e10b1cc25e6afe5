// From a linear image to the colours the geometry takes (image_pixels.h), on noisy Mondrians of
// 1, 4 and 10 megapixels (mondrian.h: the shipped sample's 8 chips, noise ±100 codes): decoding
// the PNG, the pixel rules with the exact hull colour set, and, as a baseline in the same run,
// the same distinct colours' chromaticity hull in plain doubles (no exactness: a near-collinear
// triple may be decided wrongly). Reported as ratios in docs/performance.md "Images to colours".
#include <gmcc/input/colour_csv.h>
#include <gmcc/input/image_file.h>
#include <gmcc/photo/image_pixels.h>
#include <gmcc/validation/mondrian.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace {

const gmcc::RgbImage& image(std::size_t megapixels) {
  static std::map<std::size_t, gmcc::RgbImage> cache;
  auto it = cache.find(megapixels);
  if (it != cache.end()) return it->second;
  const gmcc::ColourTable chips =
      gmcc::read_colour_csv(std::string(GMCC_DATA_DIR) + "/samples/image_munsell_D75.csv");
  gmcc::MondrianSpec spec;
  spec.width = megapixels == 1 ? 1152 : megapixels == 4 ? 2304 : 3648;
  spec.height = megapixels == 1 ? 864 : megapixels == 4 ? 1728 : 2736;
  spec.black_level = 256;
  spec.noise = 100;
  spec.saturated_pixels = 20;
  return cache.emplace(megapixels, gmcc::render_mondrian(chips.colours, spec).image).first->second;
}

gmcc::PixelRules rules() {
  gmcc::PixelRules r;
  r.black_level = 256;
  r.saturation = 65535;
  r.colour_set = gmcc::ColourSet::hull;
  return r;
}

void decode_png(benchmark::State& state) {
  const std::string bytes = gmcc::encode_png16(image(static_cast<std::size_t>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(gmcc::decode_image(bytes, "bench.png"));
}

void hull_colour_set_exact(benchmark::State& state) {
  const gmcc::RgbImage& im = image(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    const gmcc::ImageColours c = gmcc::image_colours(im, rules());
    state.counters["hull_vertices"] = static_cast<double>(c.counts.hull_vertices);
    state.counters["distinct"] = static_cast<double>(c.counts.colours);
  }
}

// The baseline: the same steps (saturation, black level, distinct colours) and Andrew's monotone
// chain on double chromaticities r/b, g/b with double orientation tests.
void hull_colour_set_double(benchmark::State& state) {
  const gmcc::RgbImage& im = image(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    std::vector<std::uint64_t> keys;
    keys.reserve(im.width * im.height);
    for (std::size_t p = 0; p < im.width * im.height; ++p) {
      std::uint32_t v[3];
      bool clipped = false;
      for (int c = 0; c < 3; ++c) {
        v[c] = im.samples[3 * p + c];
        clipped = clipped || v[c] >= 65535;
        v[c] = v[c] > 256 ? v[c] - 256 : 0;
      }
      if (!clipped) keys.push_back((std::uint64_t(v[0]) << 32) | (std::uint64_t(v[1]) << 16) | v[2]);
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<std::array<double, 2>> pts;
    for (std::uint64_t k : keys) {
      const double b = double(k & 0xffff);
      if (b > 0) pts.push_back({double(k >> 32) / b, double((k >> 16) & 0xffff) / b});
    }
    std::sort(pts.begin(), pts.end());
    auto cross = [](const std::array<double, 2>& o, const std::array<double, 2>& a,
                    const std::array<double, 2>& b) {
      return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    };
    std::vector<std::array<double, 2>> hull(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
      hull[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
      while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
      hull[k++] = pts[i];
    }
    state.counters["hull_vertices"] = static_cast<double>(k > 0 ? k - 1 : 0);
    benchmark::DoNotOptimize(hull.data());
  }
}

BENCHMARK(decode_png)->Arg(1)->Arg(4)->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK(hull_colour_set_exact)->Arg(1)->Arg(4)->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK(hull_colour_set_double)->Arg(1)->Arg(4)->Arg(10)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
