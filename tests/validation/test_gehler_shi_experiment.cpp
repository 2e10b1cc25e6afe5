// The Gehler–Shi experiment (gehler_shi_experiment.h) through run_gamut_experiment, on
// noise-free synthetic charts where the diagonal model holds exactly: patches = GT ⊙ canonical
// colours. Then the true map lies in every feasible set, and a point F is the true map.
#include <gmcc/validation/error_statistics.h>
#include <gmcc/validation/gehler_shi_experiment.h>
#include <gmcc/validation/gehler_shi_report.h>

#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

using namespace gmcc;

namespace {

Rational frac(long a, long b) {  // mpq_class(a, b) is not canonical by itself
  Rational q(a, b);
  q.canonicalize();
  return q;
}

// `images` images of one camera, image i lit by a light of its own, its 24 patches
// GT_i ⊙ canonical[k mod canonical.size()] (all inside (0.002, 0.95)).
ChartDataset synthetic_charts(const std::vector<Colour>& canonical, std::size_t images,
                              const std::string& camera = "Canon1D") {
  ChartDataset d;
  for (std::size_t i = 0; i < images; ++i) {
    ChartImage im;
    im.index = i + 1;
    im.name = "S" + std::to_string(i);
    im.camera = camera;
    // Lights from yellowish to bluish: (r, g, b) with b/r from 2/5 to about 2.
    const Rational r = frac(5 + static_cast<long>(i % 7), 20), g = frac(1, 3),
                   b = frac(2 + static_cast<long>(3 * i % 11), 20);
    im.truth = {r, g, b};
    for (std::size_t k = 0; k < chart_patches; ++k) {
      const Colour& c = canonical[k % canonical.size()];
      im.patches[k] = Colour{Rational(r * c.r), Rational(g * c.g), Rational(b * c.b)};
    }
    d.images.push_back(std::move(im));
  }
  return d;
}

ExperimentConfig small_config(int max_surfaces, std::uint64_t scenes = 3, unsigned threads = 1) {
  ExperimentConfig c;
  c.max_surfaces = max_surfaces;
  c.scenes = scenes;
  c.seed = 5;
  c.threads = threads;
  c.keep_scenes = true;
  return c;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(gehler_shi_experiment)

BOOST_AUTO_TEST_CASE(noise_free_charts_have_the_truth_in_every_feasible_set) {
  const std::vector<Colour> canonical{{Rational(1, 2), Rational(1, 2), Rational(1, 2)},
                                      {Rational(9, 10), Rational(3, 10), Rational(1, 5)},
                                      {Rational(1, 5), Rational(4, 5), Rational(3, 10)},
                                      {Rational(1, 4), Rational(3, 10), Rational(9, 10)},
                                      {Rational(7, 10), Rational(7, 10), Rational(1, 5)}};
  const ChartDataset data = synthetic_charts(canonical, 6);
  for (GehlerShiProtocol protocol : {GehlerShiProtocol::leave_one_out, GehlerShiProtocol::paper}) {
    GehlerShiOptions o;
    o.protocol = protocol;
    o.cameras = {"Canon1D"};
    const GehlerShiSetup s = gehler_shi_setup(data, o);
    BOOST_TEST_REQUIRE(s.cameras.size() == 1u);
    BOOST_TEST(s.cameras[0].usable_patches == 6u * 24u);
    BOOST_TEST(s.cameras[0].dropped_patches == 0u);
    const ExperimentResult r = run_gamut_experiment(s.setup, small_config(6));
    BOOST_TEST_REQUIRE(!r.scenes.empty());
    for (const SceneRecord& rec : r.scenes) {
      BOOST_TEST_REQUIRE(!rec.rules.empty());  // never empty: the truth is in F
      for (const RuleRecord& x : rec.rules) BOOST_TEST(x.truth_in_feasible_set);
      for (std::uint32_t id : rec.drawn) BOOST_TEST((id >= 1 && id <= 24));
      BOOST_TEST_REQUIRE(rec.baselines.size() == 2u);
    }
    for (const ExperimentCell& c : r.cells) BOOST_TEST(c.empty == 0u);
    // The leave-one-out hull of every image is the same canonical gamut here (all images share
    // the canonical colours), recomputed only for images with a patch at a vertex: all of them.
    if (protocol == GehlerShiProtocol::leave_one_out) {
      BOOST_TEST(s.cameras[0].recomputed_hulls == 6u);
      for (const ConvexSet2& g : r.canonical_gamuts) BOOST_TEST((g == r.canonical_gamuts.front()));
    }
  }
}

BOOST_AUTO_TEST_CASE(a_point_gamut_gives_a_point_feasible_set_at_the_truth) {
  // Greys only: every canonical chromaticity is (1, 1), G_c a point, F the true map itself;
  // every rule and both baselines (mean and max of GT ⊙ greys point along GT) exactly right.
  std::vector<Colour> greys;
  for (int k = 1; k <= 4; ++k) greys.push_back({Rational(k, 5), Rational(k, 5), Rational(k, 5)});
  const ChartDataset data = synthetic_charts(greys, 4, "Canon5D");
  GehlerShiOptions o;
  o.cameras = {"Canon5D"};
  const GehlerShiSetup s = gehler_shi_setup(data, o);
  BOOST_TEST(s.cameras[0].hull_vertices == 1u);
  const ExperimentResult r = run_gamut_experiment(s.setup, small_config(3));
  BOOST_TEST_REQUIRE(r.scenes.size() == 4u * 3u * 3u);
  for (const SceneRecord& rec : r.scenes) {
    BOOST_TEST((rec.kind == ConvexKind::point));
    BOOST_TEST_REQUIRE(rec.rules.size() == rule_count);
    for (const RuleRecord& x : rec.rules) {
      BOOST_TEST(x.error_deg == 0.0);
      BOOST_TEST(x.illuminant_error_deg == 0.0);
      BOOST_TEST(x.reproduction_error_deg == 0.0);
    }
    for (const RuleRecord& x : rec.baselines) {
      BOOST_TEST(x.scored);
      BOOST_TEST(x.illuminant_error_deg == 0.0);
    }
  }
}

BOOST_AUTO_TEST_CASE(cells_are_the_statistics_of_their_groups_scenes) {
  // Two cameras, near-black and clipped patches dropped: a cell (camera, n) summarises exactly
  // its camera's scenes with error_statistics, in (image, scene) order; the baselines over all
  // scenes too. Identical with two threads.
  const std::vector<Colour> canonical{{Rational(1, 2), Rational(1, 2), Rational(1, 2)},
                                      {Rational(9, 10), Rational(3, 10), Rational(1, 5)},
                                      {Rational(1, 5), Rational(4, 5), Rational(3, 10)},
                                      {Rational(1, 4), Rational(3, 10), Rational(9, 10)}};
  ChartDataset data = synthetic_charts(canonical, 5, "Canon1D");
  ChartDataset other = synthetic_charts(canonical, 4, "Canon5D");
  for (ChartImage& im : other.images) data.images.push_back(std::move(im));
  data.images[0].patches[0] = Colour{Rational(1, 1000), Rational(1, 2), Rational(1, 2)};  // near-black
  data.images[1].patches[1] = Colour{Rational(1, 2), Rational(96, 100), Rational(1, 2)};  // clipped
  data.images[2].patches[2].reset();                                                       // missing
  GehlerShiOptions o;
  const GehlerShiSetup s = gehler_shi_setup(data, o);
  BOOST_TEST(s.cameras[0].dropped_patches == 2u);
  BOOST_TEST(s.cameras[0].missing_patches == 1u);
  BOOST_TEST(s.cameras[1].dropped_patches == 0u);
  const ExperimentResult r = run_gamut_experiment(s.setup, small_config(4, 5, 1));
  const ExperimentResult r2 = run_gamut_experiment(s.setup, small_config(4, 5, 2));
  BOOST_TEST(gehler_shi_table(r, s) == gehler_shi_table(r2, s));
  BOOST_TEST_REQUIRE(r.cells.size() == 8u);
  for (const ExperimentCell& c : r.cells) {
    std::vector<double> illuminant, grey_all;
    for (const SceneRecord& rec : r.scenes) {
      const std::string& camera = s.setup.lights[rec.light].group;
      if (camera != c.light || rec.surfaces != c.surfaces) continue;
      if (!rec.rules.empty() && rec.rules[2].positive_map) illuminant.push_back(rec.rules[2].illuminant_error_deg);
      grey_all.push_back(rec.baselines[0].illuminant_error_deg);
    }
    BOOST_TEST(c.scenes == (c.light == "Canon1D" ? 25u : 20u));
    const ErrorStatistics e = error_statistics(illuminant), g = error_statistics(grey_all);
    BOOST_TEST(c.rules[2].illuminant.mean == e.mean);
    BOOST_TEST(c.rules[2].illuminant.trimean == e.trimean);
    BOOST_TEST(c.rules[2].illuminant.worst25 == e.worst25);
    BOOST_TEST(c.baselines_all[0].illuminant.median == g.median);
    BOOST_TEST(c.baselines_all[0].illuminant.n == g.n);
  }
}

BOOST_AUTO_TEST_CASE(excluded_patches_are_left_out_everywhere) {
  const std::vector<Colour> canonical{{Rational(1, 2), Rational(1, 2), Rational(1, 2)},
                                      {Rational(9, 10), Rational(3, 10), Rational(1, 5)},
                                      {Rational(1, 5), Rational(4, 5), Rational(3, 10)}};
  GehlerShiOptions o;
  o.cameras = {"Canon1D"};
  o.exclude_patches = {19, 20, 21, 22, 23, 24};
  const GehlerShiSetup s = gehler_shi_setup(synthetic_charts(canonical, 3), o);
  BOOST_TEST(s.cameras[0].excluded_patches == 3u * 6u);
  BOOST_TEST(s.cameras[0].usable_patches == 3u * 18u);
  for (const TestLight& l : s.setup.lights)
    for (std::uint32_t id : l.surface_ids) BOOST_TEST(id <= 18u);
  o.exclude_patches = {25};
  BOOST_CHECK_THROW(gehler_shi_setup(synthetic_charts(canonical, 3), o), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(unknown_camera_is_refused) {
  GehlerShiOptions o;
  o.cameras = {"Canon1D"};
  BOOST_CHECK_THROW(gehler_shi_setup(ChartDataset{}, o), std::invalid_argument);
  BOOST_CHECK_THROW(gehler_shi_protocol_from_string("loo"), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
