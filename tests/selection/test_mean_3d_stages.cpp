// The 3-D mean's closed form by stages (selection/src/mean_3d_analytic.cpp; docs/math.md "The
// double-word stage"): which stage answers (reported as precision_bits: 106 the double-word
// stages, 64 the x87 ones, more the MPFI ones), and that whichever answers gives the double
// nearest an independent 2048-bit MPFR evaluation (tests/support/mean_3d_reference.h), on the
// seeded hard sets (thin, far from the origin, small, many-vertex, segments) and typical ones.
#include "../support/hard_polygons.h"
#include "../support/mean_3d_reference.h"

#include <gmcc/selection/mean_3d.h>

#include "internal/dw_rational.h"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <map>
#include <string>

using namespace gmcc;

namespace {
constexpr std::uint64_t stages_seed = 20171015;  // Joldes, Muller & Popescu, TOMS 44(2)
}  // namespace

BOOST_AUTO_TEST_SUITE(mean_3d_stages)

BOOST_AUTO_TEST_CASE(every_stage_gives_the_nearest_double) {
  std::map<std::string, std::map<unsigned, int>> by_stage;  // category → precision → count
  for (const test::HardCase& c : test::hard_cases(stages_seed, 8 * 12)) {
    if (c.set.kind == ConvexKind::point || c.set.kind == ConvexKind::empty) continue;
    const MapEstimate e = mean_3d_analytic(c.set);
    BOOST_TEST_REQUIRE(e.valid, c.name);
    const test::Mean3dReference ref = test::mean_3d_reference(c.set);
    for (int k = 0; k < 2; ++k) {
      BOOST_TEST(e.correctly_rounded[k], c.name);
      BOOST_TEST(e.map[k] == ref.nearest_double(k), c.name << " component " << k << " at " << e.precision_bits
                                                            << " bits: " << e.map[k] << " vs " << ref.nearest_double(k));
    }
    ++by_stage[c.category][e.precision_bits];
  }
  for (const auto& [category, counts] : by_stage)
    for (const auto& [bits, n] : counts) BOOST_TEST_MESSAGE(category << ": " << n << " at " << bits << " bits");
  // Typical sets are decided by the double-word stage.
  BOOST_TEST(by_stage["random"][106] >= 11);
}

BOOST_AUTO_TEST_CASE(the_double_word_stage_decides_typical_sets) {
  int dw = 0, n = 0;
  for (unsigned i = 0; i < 40; ++i) {
    const test::HardCase c = test::make_wide_case(stages_seed, i);
    const MapEstimate e = mean_3d_analytic(c.set);
    const test::Mean3dReference ref = test::mean_3d_reference(c.set);
    ++n, dw += e.precision_bits == 106;
    for (int k = 0; k < 2; ++k) BOOST_TEST(e.map[k] == ref.nearest_double(k), c.name);
    // The bound is the deciding stage's: about half an ulp plus 2^-90 relative.
    for (int k = 0; k < 2; ++k) BOOST_TEST(e.error_bounds[k] <= std::fabs(e.map[k]) * 0x1p-52, c.name);
  }
  BOOST_TEST(dw == n);
}

BOOST_AUTO_TEST_CASE(a_forced_precision_skips_the_double_word_stage) {
  const test::HardCase c = test::make_wide_case(stages_seed, 0);
  const MapEstimate automatic = mean_3d_analytic(c.set), forced = mean_3d_analytic(c.set, {256});
  BOOST_TEST(forced.precision_bits == 256u);
  BOOST_TEST(automatic.map == forced.map);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(mean_3d_stages_inputs)

// A rational vertex coordinate's double-word enclosure contains it, for numerators and
// denominators of every length from 1 to 400 bits (both sides of 64 and 128) and either sign.
BOOST_AUTO_TEST_CASE(rationals_are_enclosed) {
  gmp_randclass random(gmp_randinit_default);
  random.seed(28);
  for (int i = 0; i < 20000; ++i) {
    const unsigned nb = 1 + static_cast<unsigned>(i % 400), db = 1 + static_cast<unsigned>((i * 7) % 400);
    mpz_class num = random.get_z_bits(nb), den = random.get_z_bits(db) + 1;
    if (i % 3 == 0) num = -num;
    const internal::DWEnclosure e = internal::enclose_dw(num.get_mpz_t(), den.get_mpz_t());
    if (!e.finite()) continue;  // beyond the range: no claim
    const mpq_class q(num, den);
    const mpq_class mid = mpq_class(e.mid.hi) + mpq_class(e.mid.lo);
    BOOST_TEST(abs(q - mid) <= mpq_class(e.rad), "bits " << nb << "/" << db);
    BOOST_TEST(e.rad <= std::fabs(e.mid.hi) * 0x1p-96);  // five charges of 2^-100 at most
  }
}

BOOST_AUTO_TEST_SUITE_END()
