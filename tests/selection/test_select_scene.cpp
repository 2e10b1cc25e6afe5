// The library's select pipeline (select_scene.h): hand cases with exact answers, agreement with
// the steps it is made of (the route gmcc select took before it existed), degenerate and empty
// feasible sets as results, recovery, the illumination constraint, scoring against truth, and
// the errors it names.
#include "../test_support.h"
#include "random_canonical_side.h"

#include <gmcc/geometry/canonical_gamut.h>
#include <gmcc/geometry/chromaticity.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/select_scene.h>
#include <gmcc/input/colour_csv.h>

#include "internal/worst_case_illuminant_route.h"

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using R = Rational;

namespace {
// Chromaticities: the square [1, 2]².
const std::vector<Colour> square{{1, 1, 1}, {2, 1, 1}, {2, 2, 1}, {1, 2, 1}};

void same_selection(const std::optional<Selection>& a, const std::optional<Selection>& b) {
  BOOST_REQUIRE(a.has_value() == b.has_value());
  if (!a) return;
  BOOST_TEST((a->estimate.map == b->estimate.map));
  BOOST_TEST(a->estimate.exact.has_value() == b->estimate.exact.has_value());
  if (a->estimate.exact) BOOST_TEST(*a->estimate.exact == *b->estimate.exact);
  BOOST_TEST((a->worst_case_deg == b->worst_case_deg));
  BOOST_TEST((a->worst_case_illuminant_deg == b->worst_case_illuminant_deg));
}
}  // namespace

BOOST_AUTO_TEST_SUITE(select_scene_pipeline)

BOOST_AUTO_TEST_CASE(hand_case_square) {
  // The image (3, 3, 2) has q = (3/2, 3/2): F = [1, 2]² / (3/2) = [2/3, 4/3]².
  const PreparedCanonical pc = prepare_canonical(square, {});
  BOOST_TEST(pc.colours == 4u);
  BOOST_TEST(pc.gamut.kind == ConvexKind::polygon);
  const SceneResult r = select_scene(pc, {{3, 3, 2}});
  BOOST_TEST(r.feasible.kind == ConvexKind::polygon);
  BOOST_TEST((area(r.feasible) == R(4, 9)));
  BOOST_TEST(*r.selections[gmcc::Rule::max_area]->estimate.exact == (Point2{R(4, 3), R(4, 3)}));
  BOOST_TEST(*r.selections[gmcc::Rule::mean_2d]->estimate.exact == (Point2{1, 1}));
  BOOST_TEST(r.selections[gmcc::Rule::mean_3d]->worst_case_illuminant_deg.has_value());
  BOOST_TEST(!r.recovery.has_value());
  BOOST_TEST(!r.constraint.has_value());
  BOOST_TEST(!r.truth.has_value());
}

BOOST_AUTO_TEST_CASE(agrees_with_its_steps_on_random_scenes) {
  // The route `gmcc select` took before the library pipeline: chromaticities, canonical_gamut,
  // feasible_set, select_maps with c. The prepared canonical side is reused across scenes.
  test::Rng rng(12);
  const test::RandomCanonicalSide side = test::random_canonical_side(rng);
  const std::vector<Colour>& canonical = side.canonical;
  const SelectSceneOptions& o = side.options;
  const PreparedCanonical& pc = side.prepared;
  const ConvexSet2 G = canonical_gamut(
      perspective_chromaticities(canonical, NonPositiveBluePolicy::drop).points, o.expansion);
  BOOST_TEST(pc.gamut == G);
  int non_empty = 0;
  for (int s = 0; s < 30; ++s) {
    std::vector<Colour> image;
    const int n = 1 + s % 5;
    for (int i = 0; i < n; ++i) {
      const Colour& c = canonical[rng() % canonical.size()];
      image.push_back({R(c.r * R(4, 5)), R(c.g * R(9, 10)), R(c.b * R(11, 10))});
    }
    const SceneResult r = select_scene(pc, image);
    const ConvexSet2 F = feasible_set(G, perspective_chromaticities(image, NonPositiveBluePolicy::drop).points);
    BOOST_TEST(r.feasible == F);
    const Selections expected = select_maps(F, {o.mean3d, o.canonical_illuminant});
    for (Rule rule : all_rules) same_selection(r.selections[rule], expected[rule]);
    // Per-scene choices against the same prepared side equal a side prepared with them.
    SceneChoices choices;
    choices.mean3d = {Mean3dMethod::quadrature, 0, 10 + static_cast<unsigned>(s % 3)};
    choices.illuminant_worst_case = s % 2 == 0;
    SelectSceneOptions baked = o;
    static_cast<SceneChoices&>(baked) = choices;
    const SceneResult per_call = select_scene(pc, image, std::nullopt, choices);
    const SceneResult prepared_with = select_scene(prepare_canonical(canonical, baked), image);
    for (Rule rule : all_rules) same_selection(per_call.selections[rule], prepared_with.selections[rule]);
    if (F.kind != ConvexKind::empty)
      BOOST_TEST(per_call.selections[Rule::mean_3d]->estimate.method == "quadrature");
    non_empty += F.kind != ConvexKind::empty;
  }
  BOOST_TEST(non_empty > 20);  // noise-free scenes of canonical colours under one light: F ∋ truth
}

BOOST_AUTO_TEST_CASE(degenerate_feasible_set_is_a_result) {
  // q = (1, 1) and (2, 2): F = [1, 2]² ∩ [1/2, 1]² = the point (1, 1).
  const SceneResult p = select_scene(prepare_canonical(square, {}), {{1, 1, 1}, {2, 2, 1}});
  BOOST_TEST(p.feasible.kind == ConvexKind::point);
  BOOST_TEST(*p.selections[gmcc::Rule::mean_3d]->estimate.exact == (Point2{1, 1}));
  BOOST_TEST(p.empty_reason.empty());
  // q = (1, 1) and (2, 1): F = [1, 1] × [1, 2] ∩ … = the segment x = 1, y in [1, 2].
  const SceneResult s = select_scene(prepare_canonical(square, {}), {{1, 1, 1}, {2, 1, 1}});
  BOOST_TEST(s.feasible.kind == ConvexKind::segment);
  BOOST_TEST(s.selections[gmcc::Rule::max_area].has_value());
}

BOOST_AUTO_TEST_CASE(empty_and_recovered) {
  const std::vector<Colour> wide{{1, 1, 1}, {4, 1, 1}};  // x-extent 1..4 against 1..2
  const SceneResult e = select_scene(prepare_canonical(square, {}), wide);
  BOOST_TEST(e.feasible.kind == ConvexKind::empty);
  BOOST_TEST(!e.empty_reason.empty());
  BOOST_TEST(!e.selections[gmcc::Rule::max_area].has_value());
  SelectSceneOptions o;
  o.on_empty = RecoveryPolicy::grow_canonical;
  const SceneResult g = select_scene(prepare_canonical(square, o), wide);
  BOOST_REQUIRE(g.recovery.has_value());
  BOOST_TEST(g.recovery->applied);
  BOOST_TEST(g.recovery->grown->found);
  BOOST_TEST(g.feasible.kind != ConvexKind::empty);
  BOOST_TEST(g.empty_reason.empty());
  // The least factor is sqrt(2) - 1 (tests/geometry/test_empty_recovery.cpp): bracketed.
  const R f = g.recovery->grown->factor;
  const R f2 = f * f + 2 * f;
  BOOST_TEST((f2 >= 1));
  o.on_empty = RecoveryPolicy::min_violation;
  const SceneResult m = select_scene(prepare_canonical(square, o), wide);
  BOOST_TEST(m.recovery->applied);
  BOOST_TEST(sgn(m.recovery->min_violation->violation) > 0);
  BOOST_TEST(m.selections[gmcc::Rule::max_area].has_value());
  // Not empty: the policy is reported, not applied.
  const SceneResult n = select_scene(prepare_canonical(square, o), {{3, 3, 2}});
  BOOST_TEST(n.recovery.has_value());
  BOOST_TEST(!n.recovery->applied);
}

BOOST_AUTO_TEST_CASE(illumination_constraint) {
  // Lights (1,1,2) and (1,1,3) have maps (2,2) and (3,3): C touches F = [1,2]² at (2,2).
  SelectSceneOptions o;
  o.illuminants = std::vector<Colour>{{1, 1, 2}, {1, 1, 3}};
  const PreparedCanonical pc = prepare_canonical(square, o);
  BOOST_TEST(pc.constraint->kind == ConvexKind::segment);
  const SceneResult r = select_scene(pc, {{1, 1, 1}});
  BOOST_REQUIRE(r.constraint.has_value());
  BOOST_TEST(r.constraint->illuminants == 2u);
  BOOST_TEST((area(r.constraint->unconstrained) == 1));
  BOOST_TEST(r.feasible.kind == ConvexKind::point);
  BOOST_TEST(r.feasible.vertices[0] == (Point2{2, 2}));
}

BOOST_AUTO_TEST_CASE(truth_scores_each_rule) {
  // F = [1, 2]² for the image (1, 1, 1); the true light (2, 2, 3) under c = (1, 1, 1) has the
  // map c ⊘ e in perspective = (3/2, 3/2), inside F.
  const SceneResult r = select_scene(prepare_canonical(square, {}), {{1, 1, 1}}, Colour{2, 2, 3});
  BOOST_REQUIRE(r.truth.has_value());
  const Point2 truth{R(3, 2), R(3, 2)};
  BOOST_TEST(r.truth->map == truth);
  BOOST_TEST(r.truth->in_feasible_set);
  const Point2 max_area = *r.selections[gmcc::Rule::max_area]->estimate.exact;  // (2, 2)
  BOOST_TEST(max_area == (Point2{2, 2}));
  BOOST_REQUIRE(r.truth->errors[gmcc::Rule::max_area].has_value());
  BOOST_TEST(r.truth->errors[gmcc::Rule::max_area]->map_error_deg == map_angular_error_deg(max_area, truth));
  BOOST_TEST(r.truth->errors[gmcc::Rule::max_area]->positive_map);
  BOOST_TEST(r.truth->errors[gmcc::Rule::max_area]->illuminant_error_deg ==
             illuminant_angular_error_deg(max_area, truth, Colour{1, 1, 1}));
  BOOST_TEST(r.truth->errors[gmcc::Rule::max_area]->reproduction_error_deg == reproduction_angular_error_deg(max_area, truth));
  BOOST_TEST(r.truth->errors[gmcc::Rule::mean_2d]->map_error_deg == 0);  // the 2-D mean is (3/2, 3/2) itself
  BOOST_TEST(r.truth->errors[gmcc::Rule::mean_3d].has_value());
  // The canonical light enters the true map: c = (2, 1, 1) doubles its first component.
  SelectSceneOptions o;
  o.canonical_illuminant = {2, 1, 1};
  const SceneResult c = select_scene(prepare_canonical(square, o), {{1, 1, 1}}, Colour{2, 2, 3});
  BOOST_TEST(c.truth->map == (Point2{3, R(3, 2)}));
  BOOST_TEST(!c.truth->in_feasible_set);
  // An empty F still reports the truth's map, with no rule to score.
  const SceneResult e = select_scene(prepare_canonical(square, {}), {{1, 1, 1}, {4, 1, 1}}, Colour{2, 2, 3});
  BOOST_TEST(e.truth.has_value());
  BOOST_TEST(!e.truth->in_feasible_set);
  BOOST_TEST(!e.truth->errors[gmcc::Rule::max_area].has_value());
}

BOOST_AUTO_TEST_CASE(illuminant_worst_case_can_be_left_out) {
  SelectSceneOptions o;
  o.illuminant_worst_case = false;
  const SceneResult r = select_scene(prepare_canonical(square, o), {{3, 3, 2}});
  BOOST_TEST(!r.selections[gmcc::Rule::max_area]->worst_case_illuminant_deg.has_value());
  BOOST_TEST(r.selections[gmcc::Rule::max_area]->worst_case_deg.has_value());
}

BOOST_AUTO_TEST_CASE(errors_name_their_input) {
  SelectSceneOptions reject;
  reject.nonpositive_blue = NonPositiveBluePolicy::reject;
  try {
    select_scene(prepare_canonical(square, reject), {{1, 1, 1}, {1, 1, 0}});
    BOOST_FAIL("b = 0 under reject accepted");
  } catch (const SceneInputError& e) {
    BOOST_TEST((e.input == SceneInput::image));
    BOOST_TEST((e.problem == SceneProblem::nonpositive_blue));
    BOOST_TEST(*e.index == 1u);
    BOOST_TEST(std::string(e.what()).find("--") == std::string::npos);  // no command-line flag
  }
  try {
    prepare_canonical({{1, 1, 0}}, {});
    BOOST_FAIL("no usable canonical colour accepted");
  } catch (const SceneInputError& e) {
    BOOST_TEST((e.input == SceneInput::canonical && e.problem == SceneProblem::no_usable_colour));
  }
  try {
    select_scene(prepare_canonical(square, {}), {{0, 1, 1}, {0, 2, 1}});
    BOOST_FAIL("unbounded F accepted");
  } catch (const SceneInputError& e) {
    BOOST_TEST((e.input == SceneInput::image && e.problem == SceneProblem::unbounded));
  }
  try {
    select_scene(prepare_canonical(square, {}), {{1, 1, 1}}, Colour{0, 1, 1});
    BOOST_FAIL("a true light with a zero channel accepted");
  } catch (const SceneInputError& e) {
    BOOST_TEST((e.input == SceneInput::truth));
  }
  SelectSceneOptions bad;
  bad.on_empty = RecoveryPolicy::grow_canonical;
  bad.expansion = {ExpansionPolicy::centroid_clip, R(1, 10)};
  BOOST_CHECK_THROW(prepare_canonical(square, bad), SceneInputError);
  SelectSceneOptions lights;
  lights.illuminants = std::vector<Colour>{{1, 1, 1}, {1, 0, 2}};
  try {
    prepare_canonical(square, lights);
    BOOST_FAIL("an illuminant with a zero channel accepted");
  } catch (const SceneInputError& e) {
    BOOST_TEST((e.input == SceneInput::illuminants));
    BOOST_TEST(*e.index == 1u);
  }
}

BOOST_AUTO_TEST_CASE(illuminant_worst_case_filters_on_munsell_scenes) {
  // The scenes of bench/bench_select_batch.cpp: 11 Munsell chips of the shipped sample under the
  // light (4/5, 9/10, 11/10). The worst case's double filters (whole edges and dyadic pieces of
  // edges) against the unfiltered exact route, for each rule's map: bit for bit.
  const std::vector<Colour> canonical =
      read_colour_csv(std::string(GMCC_DATA_DIR) + "/samples/canonical_munsell_D55.csv").colours;
  SelectSceneOptions o;
  o.illuminant_worst_case = false;
  const PreparedCanonical pc = prepare_canonical(canonical, o);
  test::Rng rng(1);
  const Colour c{R(9, 10), 1, R(11, 10)};
  int compared = 0;
  for (int s = 0; s < 12; ++s) {
    std::vector<Colour> image;
    for (int i = 0; i < 11; ++i) {
      const Colour& x = canonical[rng() % canonical.size()];
      image.push_back({R(x.r * R(4, 5)), R(x.g * R(9, 10)), R(x.b * R(11, 10))});
    }
    const SceneResult r = select_scene(pc, image);
    for (const auto* sel : {&r.selections[gmcc::Rule::max_area], &r.selections[gmcc::Rule::mean_2d], &r.selections[gmcc::Rule::mean_3d]}) {
      if (!*sel || !(*sel)->estimate.valid) continue;
      const MapEstimate& e = (*sel)->estimate;
      const Point2 m = e.exact ? *e.exact : Point2{rational_from_double(e.map[0]), rational_from_double(e.map[1])};
      const IlluminantWorstCase fast = internal::worst_case_illuminant(r.feasible, m, c, internal::IlluminantRoute::certified);
      const IlluminantWorstCase slow = internal::worst_case_illuminant(r.feasible, m, c, internal::IlluminantRoute::exact);
      BOOST_TEST(fast.angle_deg == slow.angle_deg);
      BOOST_TEST(fast.location == slow.location);
      BOOST_TEST(fast.at_vertex == slow.at_vertex);
      ++compared;
    }
  }
  BOOST_TEST(compared >= 30);
}

BOOST_AUTO_TEST_CASE(recovery_policy_names) {
  for (RecoveryPolicy p : {RecoveryPolicy::none, RecoveryPolicy::grow_canonical, RecoveryPolicy::min_violation})
    BOOST_TEST((recovery_policy_from_string(to_string(p)) == p));
  BOOST_CHECK_THROW(recovery_policy_from_string("magic"), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
