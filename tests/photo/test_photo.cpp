// Whole-image gamut mapping (gmcc::photo): canonical gamuts learned image by image against the
// hull of the union computed at once, the intensity scaling, and the 3-D route on pixel colours:
// the true map lies in F3, max-trace is the largest trace over F3's vertices, the lights the maps
// imply, and chromaticity lifts refused.
#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/learn_canonical.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>

using namespace gmcc;

namespace {

// Rational points on the sphere of radius 1/2 about (1, 1, 1): every one is a vertex of the
// hull of any set of them (stereographic projection of (a, b)).
std::vector<Colour> sphere_points(std::mt19937& rng, int n) {
  std::uniform_int_distribution<int> u(-40, 40);
  std::vector<Colour> out;
  for (int i = 0; i < n; ++i) {
    Rational a(u(rng), 7), b(u(rng), 7);
    a.canonicalize();  // mpq_class(p, q) keeps p/q as given
    b.canonicalize();
    const Rational q = a * a + b * b + 1;
    out.push_back({1 + a / q, 1 + b / q, 1 + (a * a + b * b - 1) / (2 * q)});
  }
  return out;
}

Colour random_light(std::mt19937& rng) {
  std::uniform_int_distribution<int> u(1, 50);
  Colour e{Rational(u(rng), 10), Rational(u(rng), 10), Rational(u(rng), 10)};
  for (Rational* c : {&e.r, &e.g, &e.b}) c->canonicalize();
  return e;
}

}  // namespace

BOOST_AUTO_TEST_CASE(learned_3d_gamut_is_the_hull_of_the_union) {
  std::mt19937 rng(2610);
  CanonicalLearner3 learner(CanonicalIntensity::none);
  std::vector<Colour> all;
  for (int image = 0; image < 40; ++image) {  // 40 × 300 sphere points: compaction runs
    const std::vector<Colour> colours = sphere_points(rng, 300);
    const Colour e = random_light(rng);
    learner.add(colours, e);
    for (const Colour& c : colours) all.push_back({c.r / e.r, c.g / e.g, c.b / e.b});
  }
  BOOST_TEST(learner.images() == 40u);
  BOOST_TEST(learner.contributing() == 40u);
  const std::vector<Colour> g = learner.gamut();
  BOOST_TEST((g == colour_hull_vertices(all)));
  BOOST_CHECK_THROW(learner.add(all, Colour{1, 0, 1}), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(max_intensity_scales_each_image_to_one) {
  std::mt19937 rng(7);
  CanonicalLearner3 learner;  // CanonicalIntensity::max
  std::vector<Colour> all;
  for (int image = 0; image < 5; ++image) {
    std::vector<Colour> colours = sphere_points(rng, 50);
    Rational exposure(image + 1, 3);  // the same surfaces, brighter or darker
    exposure.canonicalize();
    for (Colour& c : colours) c = {c.r * exposure, c.g * exposure, c.b * exposure};
    learner.add(colours, Colour{1, 2, 3});
  }
  learner.add({Colour{0, 0, 0}}, Colour{1, 1, 1});  // black only: adds nothing
  BOOST_TEST(learner.contributing() == 5u);
  Rational top = 0;
  for (const Colour& c : learner.gamut()) top = std::max({top, c.r, c.g, c.b});
  BOOST_TEST(top == 1);
  BOOST_TEST(to_string(canonical_intensity_from_string("none")) == "none");
  BOOST_CHECK_THROW(canonical_intensity_from_string("mean"), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(learned_2d_gamut_is_the_hull_of_white_balanced_chromaticities) {
  std::mt19937 rng(11);
  CanonicalLearner2 learner;
  std::vector<Point2> all;
  for (int image = 0; image < 30; ++image) {
    const std::vector<Colour> colours = sphere_points(rng, 200);
    const Colour e = random_light(rng);
    learner.add(colours, e);
    for (const Colour& c : colours) {
      const Rational r = c.r / e.r, g = c.g / e.g, b = c.b / e.b;  // the white-balanced colour
      all.push_back({Rational(r / b), Rational(g / b)});
    }
  }
  const std::vector<Point2> g = learner.gamut(), h = convex_hull(all).vertices;
  BOOST_TEST(g.size() == h.size());
  BOOST_TEST((g == h));
}

// Surfaces S under a light e: the image is S ∘ e, so d = 1 ⊘ e takes it into conv(S ∪ {0})
// exactly, and the rules' lights point near e.
BOOST_AUTO_TEST_CASE(estimate_3d_on_pixel_colours) {
  std::mt19937 rng(5);
  const std::vector<Colour> surfaces = sphere_points(rng, 60);
  const CanonicalConstraints3 canonical(surfaces);
  const Colour e{Rational(3, 2), 1, Rational(1, 2)};
  ImageColours image;
  for (std::size_t i = 0; i < surfaces.size(); i += 2)
    image.colours.push_back({surfaces[i].r * e.r, surfaces[i].g * e.g, surfaces[i].b * e.b});
  const ImageEstimate3 r = estimate_3d(canonical, image);
  BOOST_TEST_REQUIRE((r.feasible.kind == ConvexKind3::polytope));
  BOOST_TEST(contains(r.feasible, Point3{1 / e.r, 1 / e.g, 1 / e.b}));
  for (Rule3 rule : all_rules_3) {
    BOOST_TEST_REQUIRE(r[rule].has_value());
    BOOST_TEST_REQUIRE(r[rule]->light.has_value());
    BOOST_TEST(recovery_angular_error_deg(*r[rule]->light, e) < 10.0);
    BOOST_TEST(r[rule]->selection.worst_case_deg.has_value());
    BOOST_TEST(to_string(rule_3_from_string(to_string(rule))) == to_string(rule));
  }
  // Max-trace: no vertex of F3 has a larger d1 + d2 + d3.
  BOOST_TEST_REQUIRE(r.max_trace->selection.estimate.exact.has_value());
  const Point3 m = *r.max_trace->selection.estimate.exact;
  const Rational top = m.x + m.y + m.z;
  for (const Point3& v : r.feasible.vertices) {
    const Rational t = v.x + v.y + v.z;
    BOOST_TEST(t <= top);
  }
  // The light of a map: c ⊘ d, unit length.
  const auto light = light_of_map_3({2, 4, 4}, Colour{1, 1, 1});
  BOOST_TEST_REQUIRE(light.has_value());
  BOOST_TEST((*light)[0] == 2.0 / std::sqrt(6.0), boost::test_tools::tolerance(1e-15));
  BOOST_TEST(!light_of_map_3({0, 1, 1}, Colour{1, 1, 1}).has_value());
  // Only the rules asked for.
  Estimate3Options only;
  only.rules = {Rule3::max_trace};
  const ImageEstimate3 t = estimate_3d(canonical, image, only);
  BOOST_TEST(!t.max_volume.has_value());
  BOOST_TEST((t.max_trace->selection.estimate.exact == r.max_trace->selection.estimate.exact));
  BOOST_TEST((t.feasible == r.feasible));
  // Without the exact F3 (what the CLI and Python ask): the same answers, F3 empty of vertices
  // until asked for, then the same set; fewer of its vertices were made exact than it has.
  Estimate3Options lazy;
  lazy.exact_feasible_set = false;
  const ImageEstimate3 z = estimate_3d(canonical, image, lazy);
  BOOST_TEST(z.feasible.vertices.empty());
  BOOST_TEST((z.lazy_feasible.kind() == r.feasible.kind));
  BOOST_TEST(z.lazy_feasible.size() == r.feasible.vertices.size());
  BOOST_TEST(z.lazy_feasible.exact_vertices() < z.lazy_feasible.size());
  for (Rule3 rule : all_rules_3) {
    const MapEstimate3 &a = z[rule]->selection.estimate, &b = r[rule]->selection.estimate;
    BOOST_TEST(a.map == b.map);
    BOOST_TEST(a.error_bound == b.error_bound);
    BOOST_TEST((a.exact == b.exact));
    BOOST_TEST(*z[rule]->selection.worst_case_deg == *r[rule]->selection.worst_case_deg);
    BOOST_TEST(*z[rule]->light == *r[rule]->light);
  }
  BOOST_TEST((z.lazy_feasible.exact() == r.feasible));
}

BOOST_AUTO_TEST_CASE(estimate_3d_refuses_chromaticity_lifts) {
  const CanonicalConstraints3 canonical({Colour{1, 1, 1}, Colour{1, 0, 0}, Colour{0, 1, 0}, Colour{0, 0, 1}});
  ImageColours lifts;
  lifts.colours = {Colour{Rational(1, 2), 2, 1}, Colour{3, 1, 1}};
  lifts.set = ColourSet::hull;
  try {
    estimate_3d(canonical, lifts);
    BOOST_FAIL("lifts accepted");
  } catch (const std::invalid_argument& e) {
    BOOST_TEST(std::string(e.what()).find("chromaticity lifts") != std::string::npos);
  }
  ImageColours none;
  BOOST_CHECK_THROW(estimate_3d(canonical, none), std::invalid_argument);
}
