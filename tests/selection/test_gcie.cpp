// Gamut-constrained illuminant estimation (gcie.h): the light chosen is the least of the scores
// computed one light at a time by the projection route (gcie_score), the consistent lights found
// by filtered membership are exactly those of score 0, an image of the canonical surfaces under
// a plausible light is classified as that light, and the tie rule picks the light nearest the
// tied lights' mean chromaticity.
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/selection/gcie.h>

#include <boost/test/unit_test.hpp>

#include <random>

using namespace gmcc;

namespace {

Rational small(std::mt19937& rng, int lo, int hi) { return Rational(std::uniform_int_distribution<int>(lo, hi)(rng)); }

const Colour white{Rational(1), Rational(1), Rational(1)};

// Canonical surfaces (colours under the white light) and their perspective hull.
struct Scene {
  std::vector<Colour> surfaces;
  std::vector<Point2> chromaticities;
};

Scene random_scene(std::mt19937& rng) {
  Scene s;
  std::vector<Point2> xy;
  for (int i = 0; i < 10; ++i) {
    s.surfaces.push_back({small(rng, 1, 30), small(rng, 1, 30), small(rng, 1, 30)});
    xy.push_back({Rational(s.surfaces.back().r / s.surfaces.back().b), Rational(s.surfaces.back().g / s.surfaces.back().b)});
  }
  s.chromaticities = convex_hull(xy).vertices;
  return s;
}

std::vector<Colour> under(const std::vector<Colour>& surfaces, const Colour& l, std::size_t n) {
  std::vector<Colour> out;
  for (std::size_t i = 0; i < n && i < surfaces.size(); ++i)
    out.push_back({surfaces[i].r * l.r, surfaces[i].g * l.g, surfaces[i].b * l.b});
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(gcie)

BOOST_AUTO_TEST_CASE(selection_is_the_least_score_and_consistent_means_score_zero) {
  std::mt19937 rng(2006);
  int none_consistent = 0, some_consistent = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const Scene s = random_scene(rng);
    std::vector<Colour> lights;
    for (int i = 0; i < 6; ++i) lights.push_back({small(rng, 1, 9), small(rng, 1, 9), small(rng, 1, 9)});
    const Colour truth{small(rng, 1, 9), small(rng, 1, 9), small(rng, 1, 9)};
    // Some of the surfaces under the truth, and sometimes a colour no light explains.
    std::vector<Colour> image = under(s.surfaces, truth, std::uniform_int_distribution<std::size_t>(1, 10)(rng));
    if (trial % 3 == 0) image.push_back({small(rng, 0, 40), small(rng, 0, 40), small(rng, 0, 3)});
    const GcieSelection sel = gcie_select(s.chromaticities, white, lights, image);
    std::vector<Rational> scores;
    std::size_t zero = 0, least_count = 0;
    Rational least;
    for (const Colour& l : lights) {
      scores.push_back(gcie_score(s.chromaticities, white, l, image));
      zero += sgn(scores.back()) == 0;
    }
    for (std::size_t i = 0; i < lights.size(); ++i)
      if (i == 0 || scores[i] < least) least = scores[i];
    for (const Rational& x : scores) least_count += x == least;
    BOOST_TEST(sel.consistent == zero);
    BOOST_TEST(sel.score == least);
    BOOST_TEST(scores[sel.light] == least);
    BOOST_TEST(sel.tied == least_count);
    (zero ? some_consistent : none_consistent)++;
  }
  BOOST_TEST(none_consistent > 20);
  BOOST_TEST(some_consistent > 5);
}

BOOST_AUTO_TEST_CASE(the_canonical_surfaces_under_a_plausible_light_are_classified_as_it) {
  std::mt19937 rng(45);
  for (int trial = 0; trial < 100; ++trial) {
    const Scene s = random_scene(rng);
    std::vector<Colour> lights;
    for (int i = 0; i < 8; ++i) lights.push_back({small(rng, 1, 20), small(rng, 1, 20), small(rng, 1, 20)});
    const std::size_t k = std::uniform_int_distribution<std::size_t>(0, lights.size() - 1)(rng);
    // Every surface under light k at some intensity: a diagonal map other than the identity
    // (up to scale) moves an extreme chromaticity out of the canonical hull, so only light k
    // (and any light of its direction) is consistent.
    const Colour scaled{lights[k].r * 3, lights[k].g * 3, lights[k].b * 3};
    const GcieSelection sel = gcie_select(s.chromaticities, white, lights, under(s.surfaces, scaled, 10));
    const Colour& l = lights[sel.light];
    BOOST_TEST((l.r * lights[k].g == l.g * lights[k].r && l.g * lights[k].b == l.b * lights[k].g));
    BOOST_TEST(sgn(sel.score) == 0);
  }
}

BOOST_AUTO_TEST_CASE(ties_go_to_the_light_nearest_their_mean_chromaticity) {
  // One canonical chromaticity (a ray) and an image of black only: every light is consistent;
  // the middle light of three on a line of chromaticities is nearest their mean.
  const std::vector<Point2> ray{{Rational(1), Rational(1)}};
  const std::vector<Colour> lights{{Rational(1), Rational(1), Rational(4)},
                                   {Rational(2), Rational(1), Rational(3)},
                                   {Rational(3), Rational(1), Rational(2)}};
  const GcieSelection sel = gcie_select(ray, white, lights, {{Rational(0), Rational(0), Rational(0)}});
  BOOST_TEST(sel.light == 1u);
  BOOST_TEST(sel.tied == 3u);
  BOOST_TEST(sel.consistent == 3u);
}

BOOST_AUTO_TEST_CASE(bad_input_is_refused) {
  const std::vector<Point2> xy{{Rational(1), Rational(1)}, {Rational(2), Rational(1)}, {Rational(1), Rational(2)}};
  const std::vector<Colour> image{{Rational(1), Rational(1), Rational(1)}};
  BOOST_CHECK_THROW(gcie_select(xy, white, {}, image), std::invalid_argument);
  BOOST_CHECK_THROW(gcie_select({}, white, {white}, image), std::invalid_argument);
  BOOST_CHECK_THROW(gcie_select(xy, white, {{Rational(1), Rational(0), Rational(1)}}, image), std::invalid_argument);
  BOOST_CHECK_THROW(gcie_select(xy, white, {white}, {{Rational(-1), Rational(1), Rational(1)}}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
