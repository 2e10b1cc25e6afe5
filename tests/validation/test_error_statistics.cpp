// error_statistics.h on hand-computed examples (docs/reproduction.md "Statistics"), and the
// per-scene records: shards of a run hold the whole run's scenes, and a cell summarised from
// them is the run's own cell.
#include <gmcc/validation/error_statistics.h>
#include <gmcc/validation/experiment_report.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <boost/test/unit_test.hpp>

#include <cmath>

using namespace gmcc;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_SUITE(statistics)

BOOST_AUTO_TEST_CASE(four_values_by_hand) {
  // Sorted 1 2 3 4. Quantiles by h = 3p: Q1 at h = 0.75 → 1.75, median at 1.5 → 2.5, Q3 at 2.25
  // → 3.25, p95 at 2.85 → 3.85. s² = (2.25 + 2.25 + 0.25 + 0.25)/3 = 5/3, SE = √(5/12).
  const ErrorStatistics s = error_statistics({4, 1, 3, 2});
  BOOST_TEST(s.n == 4u);
  BOOST_TEST(s.mean == 2.5);
  BOOST_TEST(s.standard_error == std::sqrt(5.0 / 12), tt::tolerance(1e-15));
  BOOST_TEST(s.median == 2.5);
  BOOST_TEST(s.trimean == (1.75 + 2 * 2.5 + 3.25) / 4);
  BOOST_TEST(s.best25 == 1.0);  // ⌈4/4⌉ = 1 value each
  BOOST_TEST(s.worst25 == 4.0);
  BOOST_TEST(s.p95 == 3.85, tt::tolerance(1e-15));
  BOOST_TEST(s.max == 4.0);
}

BOOST_AUTO_TEST_CASE(five_values_by_hand) {
  // Sorted 0 5 10 15 20: h = 4p lands on order statistics except for p95 (h = 3.8 → 0.2·15 +
  // 0.8·20 = 19). ⌈5/4⌉ = 2: best 25% = (0 + 5)/2, worst 25% = (15 + 20)/2. s² = 250/4.
  const ErrorStatistics s = error_statistics({10, 0, 5, 20, 15});
  BOOST_TEST(s.mean == 10.0);
  BOOST_TEST(s.standard_error == std::sqrt(62.5 / 5), tt::tolerance(1e-15));
  BOOST_TEST(s.median == 10.0);
  BOOST_TEST(s.trimean == (5 + 2 * 10 + 15) / 4.0);
  BOOST_TEST(s.best25 == 2.5);
  BOOST_TEST(s.worst25 == 17.5);
  BOOST_TEST(s.p95 == 19.0, tt::tolerance(1e-15));
  BOOST_TEST(s.max == 20.0);
}

BOOST_AUTO_TEST_CASE(eight_values_by_hand) {
  // Sorted 1 … 8: Q1 at h = 1.75 → 2.75, median 4.5, Q3 at 5.25 → 6.25, p95 at 6.65 → 7.65;
  // ⌈8/4⌉ = 2 values in each quarter.
  const ErrorStatistics s = error_statistics({8, 7, 6, 5, 4, 3, 2, 1});
  BOOST_TEST(s.median == 4.5);
  BOOST_TEST(s.trimean == (2.75 + 9 + 6.25) / 4);
  BOOST_TEST(s.best25 == 1.5);
  BOOST_TEST(s.worst25 == 7.5);
  BOOST_TEST(s.p95 == 7.65, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(fewer_than_four_values) {
  const ErrorStatistics none = error_statistics({});
  BOOST_TEST(none.n == 0u);
  // Nothing to summarise: every statistic undefined, not a false 0 (reports write null / empty).
  for (double x : {none.mean, none.standard_error, none.median, none.trimean, none.best25, none.worst25, none.p95,
                   none.max})
    BOOST_TEST(std::isnan(x));
  const ErrorStatistics one = error_statistics({7});
  BOOST_TEST(std::isnan(one.standard_error));  // no spread from one value
  for (double x : {one.mean, one.median, one.trimean, one.best25, one.worst25, one.p95, one.max}) BOOST_TEST(x == 7.0);
  // {1, 3}: Q1 at h = 0.25 → 1.5, Q3 at 0.75 → 2.5, p95 at 0.95 → 2.9; s² = 2, SE = 1.
  const ErrorStatistics two = error_statistics({3, 1});
  BOOST_TEST(two.standard_error == 1.0, tt::tolerance(1e-15));
  BOOST_TEST(two.median == 2.0);
  BOOST_TEST(two.trimean == 2.0);
  BOOST_TEST(two.best25 == 1.0);
  BOOST_TEST(two.worst25 == 3.0);
  BOOST_TEST(two.p95 == 2.9, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(even_median_is_the_midpoint_of_the_middle_pair) {
  // The median before this header was (a + b)/2; (1 − ½)·a + ½·b is the same double.
  for (auto [a, b] : {std::pair{0.1, 0.2}, {1.0 / 3, 2.0 / 3}, {17.463, 12.727}, {1e-300, 3e-300}})
    BOOST_TEST(error_statistics({a, b}).median == (a + b) / 2);
}

BOOST_AUTO_TEST_CASE(the_mean_is_summed_in_the_order_given) {
  // 1e16 + 1 + 1 − 1e16: in this order each 1 is lost to rounding (ulp(1e16) = 2, ties to
  // even), so the sum is 0: the values are summed as given (scene order in the reports).
  BOOST_TEST(error_statistics({1e16, 1, 1, -1e16}).mean == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(scene_records)

BOOST_AUTO_TEST_CASE(shards_partition_the_scenes_and_summarise_to_the_whole) {
  const ExperimentSetup setup = synthetic_setup(
      read_spectral_csv(std::string(GMCC_DATA_DIR) + "/munsell_matt_1269_joensuu_5nm.csv"),
      read_spectral_csv(std::string(GMCC_DATA_DIR) + "/cie_daylight_basis_S0_S1_S2.csv"), "D55", {"D75", "P2856"});
  ExperimentConfig config;
  config.scenes = 5;
  config.max_surfaces = 3;
  config.seed = 9;
  config.keep_scenes = true;
  const ExperimentResult whole = run_gamut_experiment(setup, config);
  BOOST_TEST(whole.scenes.size() == 2u * 3 * 5);
  std::vector<SceneRecord> parts;
  config.shard_count = 4;  // 30 scenes: 7, 8, 7, 8
  for (config.shard_index = 1; config.shard_index <= 4; ++config.shard_index) {
    const ExperimentResult part = run_gamut_experiment(setup, config);
    BOOST_TEST(part.scenes.size() == (config.shard_index % 2 ? 7u : 8u));
    parts.insert(parts.end(), part.scenes.begin(), part.scenes.end());
  }
  BOOST_REQUIRE(parts.size() == whole.scenes.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const SceneRecord &a = parts[i], &b = whole.scenes[i];
    BOOST_TEST((a.light == b.light && a.surfaces == b.surfaces && a.scene == b.scene));
    BOOST_TEST(a.drawn == b.drawn);
    BOOST_TEST(a.drawn.size() == static_cast<std::size_t>(a.surfaces));
    BOOST_TEST(a.rules.size() == rule_count);
    for (std::size_t r = 0; r < a.rules.size(); ++r) BOOST_TEST(a.rules[r].error_deg == b.rules[r].error_deg);
  }
  // The cell (P2856, 2) summarised from the shards' records is the whole run's cell.
  std::vector<const SceneRecord*> cell;
  for (const SceneRecord& s : parts)
    if (s.light == 1 && s.surfaces == 2) cell.push_back(&s);
  const ExperimentCell c = summarise_cell("P2856", 2, cell, 3);
  const ExperimentCell& w = whole.cells[4];
  BOOST_TEST((w.light == "P2856" && w.surfaces == 2 && c.scenes == 5u));
  for (std::size_t r = 0; r < 3; ++r) {
    BOOST_TEST(c.rules[r].error.mean == w.rules[r].error.mean);
    BOOST_TEST(c.rules[r].worst_case.p95 == w.rules[r].worst_case.p95);
    BOOST_TEST(c.rules[r].reproduction.trimean == w.rules[r].reproduction.trimean);
  }
}

BOOST_AUTO_TEST_SUITE_END()
