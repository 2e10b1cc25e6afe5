// The record form (select_scene_record.h) against the exact pipeline (select_scene): every
// enclosure it gives contains the exact value select_scene computes (checked in exact
// arithmetic), every angle is within the contract's accuracy, the kinds, presences and
// memberships are the same; on Munsell scenes like the benchmark's (thin sets take the
// extended-precision stage), random scenes, degenerate (segment, point) and empty feasible sets,
// the illumination constraint and a recovery policy.
#include "../test_support.h"
#include "random_canonical_side.h"

#include <gmcc/selection/select_scene_record.h>
#include <gmcc/input/colour_csv.h>
#include <gmcc/numerics/platform.h>

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <random>

using namespace gmcc;
using R = Rational;

namespace {
const std::vector<Colour> square{{1, 1, 1}, {2, 1, 1}, {2, 2, 1}, {1, 2, 1}};

// x ∈ [mid − rad, mid + rad], exactly.
bool contains(const Enclosure& e, const R& x) {
  const R d = x - R(e.mid);
  return abs(d) <= R(e.rad);
}

// An angle of the record against select_scene's double for it: select_scene measures at the
// map it reports (within 2^-50 relative of the exact angle there); the record at the exact map,
// which for the 3-D mean is irrational, within half an ulp of the reported map — so for it the
// two may differ by the contract's accuracy as well.
void same_angle(const Enclosure& record, double exact_route, bool rational_map) {
  BOOST_TEST(record.rad <= rule_errors_accuracy * (1 + std::fabs(record.mid)));
  const double slack = record.rad + std::fabs(exact_route) * 0x1p-50 +
                       (rational_map ? 0 : rule_errors_accuracy * (1 + std::fabs(exact_route)));
  BOOST_TEST(std::fabs(record.mid - exact_route) <= slack, record.mid << " vs " << exact_route);
}

// The record of one scene against select_scene; returns whether it came from enclosures.
bool agrees(const PreparedCanonical& pc, const std::vector<Colour>& image, const std::optional<Colour>& truth,
            const SceneChoices& choices = {}) {
  const SelectRecord rec = select_scene_record(pc, image, truth, choices);
  const SceneResult full = select_scene(pc, image, truth, choices);
  BOOST_TEST(rec.image_colours == full.image_colours);
  BOOST_TEST(rec.image_dropped == full.image_dropped);
  BOOST_TEST((rec.kind == full.feasible.kind));
  BOOST_TEST(rec.empty_reason == full.empty_reason);
  BOOST_REQUIRE(rec.vertices.size() == full.feasible.vertices.size());
  for (std::size_t i = 0; i < rec.vertices.size(); ++i) {
    BOOST_TEST(contains(rec.vertices[i][0], full.feasible.vertices[i].x));
    BOOST_TEST(contains(rec.vertices[i][1], full.feasible.vertices[i].y));
  }
  BOOST_TEST(rec.truth.has_value() == full.truth.has_value());
  if (rec.truth) BOOST_TEST(rec.truth->in_feasible_set == full.truth->in_feasible_set);
  for (Rule rule : all_rules) {
    const auto& s = full.selections[rule];
    BOOST_REQUIRE(rec.selections[rule].has_value() == s.has_value());
    if (!s) continue;
    const RecordSelection& r = *rec.selections[rule];
    const bool rational = s->estimate.exact.has_value();
    if (rational) {
      BOOST_TEST(contains(r.map[0], s->estimate.exact->x));
      BOOST_TEST(contains(r.map[1], s->estimate.exact->y));
    } else {  // the correctly rounded map is within half an ulp of the exact one, in the enclosure
      for (int k = 0; k < 2; ++k) {
        const double m = s->estimate.map[static_cast<std::size_t>(k)];
        BOOST_TEST(s->estimate.correctly_rounded[static_cast<std::size_t>(k)]);
        const double half_ulp = (std::nextafter(std::fabs(m), INFINITY) - std::fabs(m)) / 2;
        const Enclosure& e = r.map[static_cast<std::size_t>(k)];
        BOOST_TEST(abs(R(m) - R(e.mid)) <= R(e.rad) + R(half_ulp));
      }
    }
    same_angle(r.worst_case_deg, *s->worst_case_deg, rational);
    BOOST_REQUIRE(r.worst_case_illuminant_deg.has_value() == s->worst_case_illuminant_deg.has_value());
    if (r.worst_case_illuminant_deg) same_angle(*r.worst_case_illuminant_deg, *s->worst_case_illuminant_deg, rational);
    if (!full.truth) continue;
    const auto& fe = full.truth->errors[rule];
    const auto& re = rec.truth->errors[rule];
    BOOST_REQUIRE(re.has_value() == fe.has_value());
    same_angle(re->map_error_deg, fe->map_error_deg, rational);
    BOOST_REQUIRE(re->illuminant_error_deg.has_value() == fe->positive_map);
    BOOST_REQUIRE(re->reproduction_error_deg.has_value() == fe->positive_map);
    if (fe->positive_map) {
      same_angle(*re->illuminant_error_deg, fe->illuminant_error_deg, rational);
      same_angle(*re->reproduction_error_deg, fe->reproduction_error_deg, rational);
    }
  }
  return !rec.exact_route;
}

const std::vector<Colour>& munsell() {
  static const std::vector<Colour> c =
      read_colour_csv(std::string(GMCC_DATA_DIR) + "/samples/canonical_munsell_D55.csv").colours;
  return c;
}

// The benchmark's scenes (bench_select_batch): 11 Munsell chips, drawn by mt19937_64 from
// `seed`, under (4/5, 9/10, 11/10).
std::vector<Colour> munsell_scene(std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::vector<Colour> image;
  for (int i = 0; i < 11; ++i) {
    const Colour& c = munsell()[g() % munsell().size()];
    image.push_back({R(c.r * R(4, 5)), R(c.g * R(9, 10)), R(c.b * R(11, 10))});
  }
  return image;
}

// The shipped plausible lights as the illumination constraint.
SelectSceneOptions lights_options() {
  SelectSceneOptions o;
  o.illuminants = read_colour_csv(std::string(GMCC_DATA_DIR) + "/samples/plausible_lights_610_540_450.csv").colours;
  return o;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(select_scene_record_form)

BOOST_AUTO_TEST_CASE(version_is_one) { BOOST_TEST(scene_record_version == 1); }

BOOST_AUTO_TEST_CASE(munsell_scenes_agree_with_the_exact_route) {
  // The benchmark's workload (bench_select_batch): 11 Munsell chips under (4/5, 9/10, 11/10),
  // the canonical gamut of all 1269 chips; half the scenes scored against that light.
  const PreparedCanonical pc = prepare_canonical(munsell(), {});
  const Colour light{R(4, 5), R(9, 10), R(11, 10)};
  int enclosed = 0;
  const int scenes = 150;
  for (int s = 0; s < scenes; ++s)
    enclosed += agrees(pc, munsell_scene(static_cast<std::uint64_t>(s)), s % 2 ? std::optional<Colour>(light) : std::nullopt);
  // The enclosure route is what is being tested: most scenes take it (fewer with the portable
  // numerics, which have no extended-precision stage for thin sets).
  const int percent = numerics::extended_precision_active() ? 90 : 75;
  BOOST_TEST(enclosed * 100 > scenes * percent);
}

BOOST_AUTO_TEST_CASE(random_scenes_and_choices) {
  test::Rng rng(31);
  const test::RandomCanonicalSide side = test::random_canonical_side(rng);
  const std::vector<Colour>& canonical = side.canonical;
  const PreparedCanonical& pc = side.prepared;
  for (int s = 0; s < 60; ++s) {
    std::vector<Colour> image;
    for (int i = 0, n = 1 + s % 5; i < n; ++i) {
      const Colour& c = canonical[rng() % canonical.size()];
      image.push_back({R(c.r * R(4, 5)), R(c.g * R(9, 10)), R(c.b * R(11, 10))});
    }
    SceneChoices choices;
    choices.illuminant_worst_case = s % 3 != 0;
    agrees(pc, image, Colour{R(2, 3), 1, R(5, 4)}, choices);
  }
}

BOOST_AUTO_TEST_CASE(degenerate_and_empty_sets) {
  const PreparedCanonical pc = prepare_canonical(square, {});
  const Colour truth{1, 1, 1};
  // q = (1, 1), (2, 2): the point (1, 1); (1, 1), (2, 1): the segment {1} × [1, 2]; (1, 1),
  // (3, 3): empty. The exact route decides them, converted.
  for (const auto& image : {std::vector<Colour>{{1, 1, 1}, {2, 2, 1}}, std::vector<Colour>{{1, 1, 1}, {2, 1, 1}},
                            std::vector<Colour>{{1, 1, 1}, {3, 3, 1}}}) {
    agrees(pc, image, truth);
    agrees(pc, image, std::nullopt);
  }
  BOOST_TEST(select_scene_record(pc, {{1, 1, 1}, {2, 2, 1}}, truth, {}).kind == ConvexKind::point);
  BOOST_TEST(select_scene_record(pc, {{1, 1, 1}, {2, 1, 1}}, truth, {}).kind == ConvexKind::segment);
  const SelectRecord empty = select_scene_record(pc, {{1, 1, 1}, {3, 3, 1}}, truth, {});
  BOOST_TEST(empty.kind == ConvexKind::empty);
  BOOST_TEST(!empty.exact_route);  // an empty F needs no exact stage
  BOOST_TEST(!empty.truth->in_feasible_set);
  // A polygon: from enclosures, F = [2/3, 4/3]² of the hand case.
  BOOST_TEST(agrees(pc, {{3, 3, 2}}, truth));
}

BOOST_AUTO_TEST_CASE(constraint_and_recovery) {
  // C = [1/2, 1]² (the maps of the four lights under c = (1, 1, 1)). F = [2/3, 4/3]², F ∩ C =
  // [2/3, 1]²: from enclosures. F = [2, 4]² misses C: empty, and not for want of a map.
  SelectSceneOptions o;
  o.illuminants = std::vector<Colour>{{1, 1, 1}, {2, 1, 1}, {1, 2, 1}, {2, 2, 1}};
  const PreparedCanonical constrained = prepare_canonical(square, o);
  BOOST_TEST(agrees(constrained, {{3, 3, 2}}, Colour{1, 1, 1}));
  BOOST_TEST(select_scene_record(constrained, {{3, 3, 2}}, std::nullopt, {}).illuminants == 4u);
  BOOST_TEST(agrees(constrained, {{1, 1, 2}}, Colour{1, 1, 1}));  // an empty F needs no exact stage
  BOOST_TEST(select_scene_record(constrained, {{1, 1, 2}}, std::nullopt, {}).empty_reason.find("plausible") !=
             std::string::npos);
  const PreparedCanonical lights = prepare_canonical(munsell(), lights_options());
  int non_empty = 0, enclosed = 0;
  for (std::uint64_t s = 0; s < 20; ++s) {  // the benchmark's scenes against the shipped plausible lights
    enclosed += agrees(lights, munsell_scene(s), Colour{R(4, 5), R(9, 10), R(11, 10)});
    non_empty += select_scene_record(lights, munsell_scene(s), std::nullopt, {}).kind != ConvexKind::empty;
  }
  BOOST_TEST(non_empty >= 10);
  // Thin sets along the daylight locus: from enclosures through the extended-precision stage,
  // which the portable numerics do not have (they take the exact route, checked above all the same).
  if (numerics::extended_precision_active()) BOOST_TEST(enclosed >= 10);
  SelectSceneOptions grow;
  grow.on_empty = RecoveryPolicy::grow_canonical;
  const PreparedCanonical pc = prepare_canonical(square, grow);
  agrees(pc, {{1, 1, 1}, {3, 3, 1}}, Colour{1, 1, 1});
  BOOST_TEST(select_scene_record(pc, {{1, 1, 1}, {3, 3, 1}}, std::nullopt, {}).recovery->applied);
}

BOOST_AUTO_TEST_CASE(errors_are_the_exact_routes) {
  const PreparedCanonical pc = prepare_canonical(square, {});
  BOOST_CHECK_THROW(select_scene_record(pc, {{1, 1, 1}}, Colour{0, 1, 1}, {}), SceneInputError);
  BOOST_CHECK_THROW(select_scene_record(pc, {{1, 1, 0}}, std::nullopt, {}), SceneInputError);
  SceneChoices quadrature;
  quadrature.mean3d.method = Mean3dMethod::quadrature;
  BOOST_CHECK_THROW(select_scene_record(pc, {{3, 3, 2}}, std::nullopt, quadrature), OptionError);
}

BOOST_AUTO_TEST_SUITE_END()
