// Whole-image gamut mapping (gmcc::photo): canonical gamuts learned image by image against the
// hull of the union computed at once, the intensity scaling, and the 3-D route on pixel colours:
// the true map lies in F3, max-trace is the largest trace over F3's vertices, the lights the maps
// imply, and chromaticity lifts refused.
#include <gmcc/geometry/colour_hull_3.h>
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_ray_3d.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/learn_canonical.h>

#include <boost/test/unit_test.hpp>
#include <array>
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

// Colours given as their hull's vertices already (add_hull_vertices) or any superset of them
// (add): the same gamut, with the intensity rule and with a given scale, and the same counts.
BOOST_AUTO_TEST_CASE(hull_vertices_added_as_given_learn_the_same_gamut) {
  std::mt19937 rng(4648);
  for (const CanonicalIntensity intensity : {CanonicalIntensity::max, CanonicalIntensity::none}) {
    CanonicalLearner3 hulled(intensity), given(intensity), scaled(intensity), scaled_given(intensity);
    for (int image = 0; image < 30; ++image) {  // 30 × 200 points: compaction runs
      std::vector<Colour> colours = sphere_points(rng, 200);
      for (int i = 0; i < 40; ++i)  // inner points: no vertex
        colours.push_back({(colours[i].r + colours[i + 1].r) / 2, (colours[i].g + colours[i + 1].g) / 2,
                           (colours[i].b + colours[i + 1].b) / 2});
      const std::vector<Colour> vertices = colour_hull_vertices(colours);
      const Colour e = random_light(rng);
      const Rational scale(image + 1, 7);
      hulled.add(colours, e);
      given.add_hull_vertices(vertices, e);
      scaled.add(colours, e, scale);
      scaled_given.add_hull_vertices(vertices, e, scale);
    }
    given.add_hull_vertices({Colour{0, 0, 0}}, Colour{1, 1, 1});  // black only: adds nothing
    hulled.add({Colour{0, 0, 0}}, Colour{1, 1, 1});
    BOOST_TEST((given.gamut() == hulled.gamut()));
    BOOST_TEST((scaled_given.gamut() == scaled.gamut()));
    BOOST_TEST(given.images() == hulled.images());
    BOOST_TEST(given.contributing() == hulled.contributing());
    BOOST_CHECK_THROW(given.add_hull_vertices({Colour{1, -1, 1}}, Colour{1, 1, 1}), std::invalid_argument);
    BOOST_CHECK_THROW(given.add_hull_vertices({Colour{1, 1, 1}}, Colour{1, 0, 1}), std::invalid_argument);
    BOOST_CHECK_THROW(given.add_hull_vertices({Colour{1, 1, 1}}, Colour{1, 1, 1}, Rational(0)), std::invalid_argument);
  }
}

// The learned points written out (issue 46: one division a channel, the factor from each
// channel's largest value): each colour divided by its light, then by the image's factor —
// white_balanced_maximum as the largest c_k/e_k over every colour, or the given scale.
BOOST_AUTO_TEST_CASE(learned_points_are_the_colours_over_light_and_factor) {
  std::mt19937 rng(4649);
  for (const CanonicalIntensity intensity : {CanonicalIntensity::max, CanonicalIntensity::none})
    for (const bool scaled : {false, true}) {
      CanonicalLearner3 learner(intensity);
      std::vector<Colour> points;
      for (int image = 0; image < 6; ++image) {
        std::vector<Colour> colours = colour_hull_vertices(sphere_points(rng, 60));
        const Colour e = random_light(rng);
        Rational top = 0;  // by brute force
        for (const Colour& c : colours) top = std::max({top, Rational(c.r / e.r), Rational(c.g / e.g), Rational(c.b / e.b)});
        BOOST_TEST(white_balanced_maximum(colours, e) == top);
        Rational scale(image + 2, 5);
        scale.canonicalize();
        const Rational factor = scaled ? scale : intensity == CanonicalIntensity::max ? top : Rational(1);
        for (const Colour& c : colours)
          points.push_back({c.r / e.r / factor, c.g / e.g / factor, c.b / e.b / factor});
        if (scaled) learner.add_hull_vertices(colours, e, scale);
        else learner.add_hull_vertices(colours, e);
      }
      BOOST_TEST((learner.gamut() == colour_hull_vertices(points)), "scaled " << scaled);
    }
  // A light with a channel <= 0 (outside the precondition): the largest c_k/e_k still.
  const std::vector<Colour> cs{Colour{1, 2, 3}, Colour{4, 1, 2}};
  BOOST_TEST(white_balanced_maximum(cs, Colour{-1, 1, 1}) == 3);
  BOOST_TEST(white_balanced_maximum({}, Colour{1, 1, 1}) == 0);
  BOOST_TEST(white_balanced_maximum(cs, Colour{2, 4, 1}) == 3);
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
  BOOST_TEST_REQUIRE(r[Rule3::max_trace]->selection.estimate.exact.has_value());
  const Point3 m = *r[Rule3::max_trace]->selection.estimate.exact;
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
  BOOST_TEST(!t[Rule3::max_volume].has_value());
  BOOST_TEST((t[Rule3::max_trace]->selection.estimate.exact == r[Rule3::max_trace]->selection.estimate.exact));
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

namespace {

Rational power_of_two(int k) {
  Rational x(1);
  if (k >= 0) mpq_mul_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(k));
  else mpq_div_2exp(x.get_mpq_t(), x.get_mpq_t(), static_cast<mp_bitcnt_t>(-k));
  return x;
}

std::vector<Colour> scaled(const std::vector<Colour>& cs, const Rational& s) {
  std::vector<Colour> out;
  for (const Colour& c : cs) out.push_back({c.r * s, c.g * s, c.b * s});
  return out;
}

}  // namespace

// Photographs with dark pixels kept: canonical colours and image colours with zero channels, so
// F3 has vertices on coordinate planes. The truth is decided on F3's rows (never "false" for want
// of a perspective image), and wherever it is in F3 each rule's map-space error is at most its
// certified worst case, the space that worst case bounds.
BOOST_AUTO_TEST_CASE(truth_in_f3_and_worst_cases_in_their_own_space) {
  std::mt19937 rng(4141);
  std::uniform_int_distribution<int> u(0, 12), pos(1, 12), light(2, 9);
  int truths_in = 0, truths_out = 0, zero_component = 0;
  for (int scene = 0; scene < 120; ++scene) {
    std::vector<Colour> surfaces;
    for (int i = 0; i < 14; ++i) surfaces.push_back({Rational(u(rng)), Rational(u(rng)), Rational(u(rng))});
    surfaces.push_back({Rational(pos(rng)), Rational(pos(rng)), Rational(pos(rng))});
    const Colour e{Rational(light(rng), 4), Rational(light(rng), 4), Rational(light(rng), 4)};
    ImageColours image;
    image.set = ColourSet::distinct;
    for (std::size_t i = 0; i < surfaces.size(); ++i)
      if (i % 2 == 0 || i + 1 == surfaces.size())
        image.colours.push_back({surfaces[i].r * e.r, surfaces[i].g * e.g, surfaces[i].b * e.b});
    if (scene % 2) image.colours.push_back({Rational(pos(rng)), Rational(pos(rng)), Rational(pos(rng))});
    const CanonicalConstraints3 canonical(surfaces);
    Estimate3Options o;
    o.truth = e;
    o.canonical_light = Colour{1, 1, 1};
    ImageEstimate3 r;
    try {
      r = estimate_3d(canonical, image, o);
    } catch (const UnboundedFeasibleSet&) {
      continue;
    }
    BOOST_TEST_REQUIRE(r.truth_in_feasible.has_value());
    const Point3 truth_map{Rational(1) / e.r, Rational(1) / e.g, Rational(1) / e.b};
    BOOST_TEST(*r.truth_in_feasible == feasible_set_3d_meets_ray({{&canonical, &image.colours}}, truth_map));
    for (const Point3& v : r.feasible.vertices)
      zero_component += sgn(v.x) == 0 || sgn(v.y) == 0 || sgn(v.z) == 0;
    (*r.truth_in_feasible ? truths_in : truths_out)++;
    for (Rule3 rule : all_rules_3) {
      if (!r[rule]) continue;
      const ImageSelection3& s = *r[rule];
      if (s.light) {
        BOOST_TEST_REQUIRE(s.recovery_error_deg.has_value());
        BOOST_TEST(*s.recovery_error_deg == recovery_angular_error_deg(*s.light, e));
      }
      if (*r.truth_in_feasible && s.selection.worst_case_deg) {
        BOOST_TEST_REQUIRE(s.map_error_deg.has_value());
        BOOST_TEST(*s.map_error_deg <= *s.selection.worst_case_deg, "scene " << scene << " " << to_string(rule) << " " << *s.map_error_deg << " > " << *s.selection.worst_case_deg << " kind " << to_string(r.feasible.kind) << " n " << r.feasible.vertices.size());
      }
    }
  }
  // The image under its light is always in F3 here (its colours are canonical colours under e),
  // the added random colour sometimes throws it out.
  BOOST_TEST(truths_in > 40);
  BOOST_TEST(zero_component > 0);
  Estimate3Options bad;
  bad.truth = Colour{1, 0, 1};
  const CanonicalConstraints3 canonical({Colour{1, 1, 1}});
  ImageColours one;
  one.colours = {Colour{1, 1, 1}};
  BOOST_CHECK_THROW(estimate_3d(canonical, one, bad), std::invalid_argument);
}

// Lights at any representable scale: a canonical gamut, an image and a truth scaled by 2^±600
// (far beyond double's range when formed as c ⊘ d in doubles) give the same light, the same
// errors and the same truth in F3 as unscaled, and light_of_map_3 is exact-scale invariant.
BOOST_AUTO_TEST_CASE(lights_at_extreme_scales) {
  std::mt19937 rng(17);
  const std::vector<Colour> surfaces = sphere_points(rng, 40);
  const Colour e{Rational(3, 2), 1, Rational(1, 2)};
  std::vector<Colour> pixels;
  for (std::size_t i = 0; i < surfaces.size(); i += 2)
    pixels.push_back({surfaces[i].r * e.r, surfaces[i].g * e.g, surfaces[i].b * e.b});
  // Scales of the canonical gamut, the image, the truth and the canonical light (whose maps stay
  // within double's range: the maps are reported as doubles too).
  auto run = [&](int canonical_k, int image_k, int truth_k, int light_k) {
    const CanonicalConstraints3 canonical(scaled(surfaces, power_of_two(canonical_k)));
    ImageColours image;
    image.colours = scaled(pixels, power_of_two(image_k));
    Estimate3Options o;
    const Rational t = power_of_two(truth_k), c = power_of_two(light_k);
    o.truth = Colour{e.r * t, e.g * t, e.b * t};
    o.canonical_light = Colour{c, c, c};
    return estimate_3d(canonical, image, o);
  };
  const ImageEstimate3 plain = run(0, 0, 0, 0);
  BOOST_TEST_REQUIRE(plain[Rule3::max_trace].has_value());
  for (const std::array<int, 4>& k : std::vector<std::array<int, 4>>{{600, 0, 0, 0},
                                                                     {-600, 0, 0, 0},
                                                                     {0, 600, 0, 0},
                                                                     {0, -600, 0, 0},
                                                                     {0, 0, 600, 0},
                                                                     {0, 0, -600, 0},
                                                                     {600, 0, 0, 600},
                                                                     {-600, 0, 0, -600},
                                                                     {600, 600, -600, 600}}) {
    const ImageEstimate3 r = run(k[0], k[1], k[2], k[3]);
    BOOST_TEST((r.truth_in_feasible == plain.truth_in_feasible));
    for (Rule3 rule : all_rules_3) {
      BOOST_TEST_REQUIRE(r[rule]->light.has_value());
      for (int c = 0; c < 3; ++c) {
        BOOST_TEST(std::isfinite((*r[rule]->light)[c]));
        BOOST_TEST((*r[rule]->light)[c] == (*plain[rule]->light)[c], boost::test_tools::tolerance(1e-12));
      }
      BOOST_TEST(*r[rule]->recovery_error_deg == *plain[rule]->recovery_error_deg, boost::test_tools::tolerance(1e-9));
    }
  }
  const Point3 d{Rational(2), Rational(4), Rational(4)};
  const auto base = light_of_map_3(d, Colour{1, 1, 1});
  for (int k : {-1070, -600, -1, 1, 600, 1070}) {
    const Rational s = power_of_two(k);
    const auto l = light_of_map_3(Point3{d.x * s, d.y * s, d.z * s}, Colour{1, 1, 1});
    BOOST_TEST_REQUIRE(l.has_value());
    BOOST_TEST((*l == *base));  // a power of two is divided out exactly
  }
  // Components more than 2^1100 apart: the small one underflows to 0, never a NaN.
  const auto wide = light_of_map_3(Point3{Rational(1), power_of_two(1100), Rational(1)}, Colour{1, 1, 1});
  BOOST_TEST_REQUIRE(wide.has_value());
  BOOST_TEST((*wide)[1] == 0.0);
  BOOST_TEST((*wide)[0] == std::sqrt(0.5), boost::test_tools::tolerance(1e-15));
}

// The illumination constraint in 3-D (Barnard's ECRULE; illumination_cone_3d.h): F3 ∩ K, K the cone
// of the plausible lights' maps, against an independent description of the same set. Every
// vertex of the constrained set lies in F3 and in K (its central projection in the hull of the
// maps' projections); every vertex of F3 in K is in it, and so is every point of F3 whose
// projection is in that hull (sampled as convex combinations of F3's vertices); max-trace on the
// smaller set never exceeds it on F3; the truth is in the constrained set iff it is in F3 and in K.
BOOST_AUTO_TEST_CASE(illumination_cone_constrains_f3_exactly) {
  std::mt19937 rng(45);
  std::uniform_int_distribution<int> u(1, 12), w(0, 4), light(2, 12);
  int empty_positive = 0, nonempty = 0;
  for (int scene = 0; scene < 60; ++scene) {
    std::vector<Colour> surfaces;
    for (int i = 0; i < 12; ++i) surfaces.push_back({Rational(u(rng)), Rational(u(rng)), Rational(u(rng))});
    const Colour e{Rational(light(rng)), Rational(light(rng)), Rational(light(rng))};
    ImageColours image;
    for (std::size_t i = 0; i < surfaces.size(); i += 2)
      image.colours.push_back({surfaces[i].r * e.r, surfaces[i].g * e.g, surfaces[i].b * e.b});
    std::vector<Colour> lights;
    const int n = 1 + scene % 5;
    for (int j = 0; j < n; ++j) lights.push_back({Rational(light(rng)), Rational(light(rng)), Rational(light(rng))});
    if (scene % 2 == 0) lights.push_back({e.r * 3, e.g * 3, e.b * 3});  // the true light among them, brighter
    const CanonicalConstraints3 canonical(surfaces);
    Estimate3Options plain, constrained;
    plain.truth = constrained.truth = e;
    constrained.illuminants = lights;
    const ImageEstimate3 F = estimate_3d(canonical, image, plain), FK = estimate_3d(canonical, image, constrained);
    // K's projections (c = white: the maps 1/l).
    std::vector<Point2> kp;
    for (const Colour& l : lights) {
      const Rational a = 1 / l.r, b = 1 / l.g, c = 1 / l.b, s = a + b + c;
      kp.push_back({Rational(a / s), Rational(b / s)});
    }
    const ConvexSet2 K = convex_hull(kp);
    auto in_k = [&](const Point3& v) {
      const Rational s = v.x + v.y + v.z;
      return sgn(s) == 0 || contains(K, Point2{Rational(v.x / s), Rational(v.y / s)});
    };
    for (const Point3& v : FK.feasible.vertices) {
      BOOST_TEST(contains(F.feasible, v), "scene " << scene);
      BOOST_TEST(in_k(v), "scene " << scene);
    }
    for (const Point3& v : F.feasible.vertices)
      if (in_k(v)) BOOST_TEST(contains(FK.feasible, v), "scene " << scene);
    for (int k = 0; k < 20 && !F.feasible.vertices.empty(); ++k) {
      Point3 p{0, 0, 0};
      Rational total = 0;
      for (const Point3& v : F.feasible.vertices) {
        const Rational t(w(rng));
        p = {Rational(p.x + t * v.x), Rational(p.y + t * v.y), Rational(p.z + t * v.z)};
        total += t;
      }
      if (sgn(total) == 0) continue;
      p = {Rational(p.x / total), Rational(p.y / total), Rational(p.z / total)};
      if (in_k(p)) BOOST_TEST(contains(FK.feasible, p), "scene " << scene);
    }
    const Point3 truth_map{1 / e.r, 1 / e.g, 1 / e.b};
    BOOST_TEST(*FK.truth_in_feasible == (*F.truth_in_feasible && in_k(truth_map)), "scene " << scene);
    if (FK[Rule3::max_trace] && F[Rule3::max_trace]) {
      const Point3 a = measured_map(FK[Rule3::max_trace]->selection.estimate), b = measured_map(F[Rule3::max_trace]->selection.estimate);
      const Rational ta = a.x + a.y + a.z, tb = b.x + b.y + b.z;
      BOOST_TEST(ta <= tb);
      (FK[Rule3::max_trace]->light ? nonempty : empty_positive)++;
    }
  }
  BOOST_TEST(nonempty > 10);  // both outcomes reached: lights that admit maps and lights that do not
  BOOST_TEST(empty_positive > 3);
  Estimate3Options bad;
  bad.illuminants = {Colour{1, 0, 1}};
  const CanonicalConstraints3 canonical({Colour{1, 1, 1}, Colour{2, 1, 1}});
  ImageColours one;
  one.colours = {Colour{1, 1, 1}};
  BOOST_CHECK_THROW(estimate_3d(canonical, one, bad), std::invalid_argument);
}
