// The benchmark's edge-based methods run alone against the same methods run beside the pixel
// method (which learns the pixel canonical gamut and makes the pixel hull the edge methods alone
// skip): the same records at σ = 1 and 4, and with a black level, on seeded noisy Mondrians; and the fold whose training images keep no colour
// above black still refused when only an edge method is asked for.
#include <gmcc/input/colour_csv.h>
#include <gmcc/input/image_file.h>
#include <gmcc/input/input_error.h>
#include <gmcc/validation/benchmark.h>
#include <gmcc/validation/mondrian.h>

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace gmcc;

namespace {

// Six noisy 40 × 40 Mondrians of the shipped sample's chips in a temporary folder, each under
// its own light, in three folds (image i in fold i mod 3); those of folds 0 and 2 all black with
// `black`.
std::vector<BenchmarkImage> mondrians(const std::string& name, bool black) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::create_directories(dir);
  const ColourTable chips = read_colour_csv(std::string(GMCC_DATA_DIR) + "/samples/image_munsell_D75.csv");
  std::vector<BenchmarkImage> out;
  for (int i = 0; i < 6; ++i) {
    MondrianSpec spec;
    spec.width = spec.height = 40;
    spec.columns = spec.rows = 4;
    spec.seed = static_cast<std::uint64_t>(i + 1);
    spec.noise = 100;
    RgbImage image = render_mondrian(chips.colours, spec).image;
    if (black && i % 3 != 1) std::fill(image.samples.begin(), image.samples.end(), 0);
    const std::string file = (dir / ("m" + std::to_string(i) + ".png")).string();
    std::ofstream(file, std::ios::binary) << encode_png16(image);
    BenchmarkImage im;
    im.name = "m" + std::to_string(i);
    im.path = file;
    im.light = {Rational(i + 2), Rational(3), Rational(7 - i)};
    im.fold = i % 3;
    out.push_back(im);
  }
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(edge_methods_alone_give_the_records_they_give_beside_the_pixel_method) {
  const std::vector<BenchmarkImage> images = mondrians("gmcc_test_benchmark_edges", false);
  // Alone, edge1 and edge2 take the pixel colours' scale from their largest channels, beside the
  // pixel method from their hull: a black level (subtracted from both) as well as none.
  for (const auto& [sigma, black] : {std::pair<double, std::uint32_t>{1.0, 0}, {4.0, 0}, {1.0, 9000}}) {
    BenchmarkOptions both, alone;
    both.methods = {"gm3d-max-trace", "gm3d-edge1-max-trace", "gm3d-edge2-max-trace"};
    alone.methods = {"gm3d-edge1-max-trace", "gm3d-edge2-max-trace"};
    for (BenchmarkOptions* o : {&both, &alone}) {
      o->edge_sigma = sigma;
      o->threads = 1;
      o->pixels.rules.saturation = 65535;
      o->pixels.rules.black_level = black;
      o->pixels.black_level_given = black > 0;
    }
    const BenchmarkResult a = run_benchmark(images, both), b = run_benchmark(images, alone);
    std::vector<const BenchmarkRecord*> edges;
    for (const BenchmarkRecord& r : a.records)
      if (r.method != "gm3d-max-trace") edges.push_back(&r);
    BOOST_TEST_REQUIRE(edges.size() == b.records.size());
    int answered = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const BenchmarkRecord &x = *edges[i], &y = b.records[i];
      BOOST_TEST(x.method == y.method);
      BOOST_TEST(x.image == y.image);
      BOOST_TEST((x.light == y.light));
      BOOST_TEST((x.error_deg == y.error_deg));
      BOOST_TEST(x.answered == y.answered);
      BOOST_TEST(x.unanswered == y.unanswered);
      BOOST_TEST(x.feasible_kind == y.feasible_kind);
      BOOST_TEST((x.feasible_vertices == y.feasible_vertices));
      BOOST_TEST((x.truth_in_feasible == y.truth_in_feasible));
      BOOST_TEST((x.worst_case_deg == y.worst_case_deg));
      answered += y.answered;
    }
    BOOST_TEST(answered > 0);
  }
}

BOOST_AUTO_TEST_CASE(an_edge_method_alone_still_refuses_a_fold_of_black_training_images) {
  // Folds 0 and 2 black: fold 1's training images give no colour above black.
  const std::vector<BenchmarkImage> images = mondrians("gmcc_test_benchmark_edges_black", true);
  BenchmarkOptions o;
  o.methods = {"gm3d-edge1-max-trace"};
  o.threads = 1;
  o.pixels.rules.saturation = 65535;
  const auto no_colour = [](const InputError& e) {
    return std::string(e.what()).find("training images give no colour above black") != std::string::npos;
  };
  BOOST_CHECK_EXCEPTION(run_benchmark(images, o), InputError, no_colour);
  o.methods = {"gm3d-max-trace"};
  BOOST_CHECK_EXCEPTION(run_benchmark(images, o), InputError, no_colour);
}
