#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/selection/select_scene.h>

#include "internal/empty_reason.h"
#include "internal/scene_chromaticities.h"

namespace gmcc {
namespace {

bool within_limit(const Point2& p) {
  return p.x <= max_scene_coordinate() && p.y <= max_scene_coordinate();
}

// The recovery policy, when F is empty: F replaced by what it recovers.
RecoveryReport recover(const PreparedCanonical& pc, const std::vector<Point2>& image, SceneResult& r) {
  RecoveryReport rec;
  rec.policy = pc.options.on_empty;
  if (r.feasible.kind != ConvexKind::empty) return rec;
  rec.reason = r.empty_reason;
  if (rec.policy == RecoveryPolicy::grow_canonical) {
    GrowCanonicalOptions g;
    g.start = pc.options.expansion.factor;
    rec.precision = g.precision;
    rec.grown = grow_canonical_until_feasible(pc.chromaticities, image, pc.constraint, g);
    if (!rec.grown->found) return rec;
    r.feasible = rec.grown->feasible;
  } else {
    // min_violation clips its minimisers edge by edge in rationals: O(k·m²) for m gamut edges and
    // k image hull vertices (2000 edges, 3 image vertices: about 13 s; 6000: 150 s). Refused up
    // front beyond max_min_violation_edges (docs/cli.md "Resource limits").
    if (pc.gamut.vertices.size() > max_min_violation_edges)
      throw SceneInputError(SceneInput::on_empty, SceneProblem::bad_option, std::nullopt,
                            "min-violation takes canonical gamuts of at most " +
                                std::to_string(max_min_violation_edges) + " vertices; this one has " +
                                std::to_string(pc.gamut.vertices.size()) +
                                " (grow-canonical has no such limit)");
    rec.min_violation = min_violation(pc.gamut, image, pc.constraint);
    r.feasible = rec.min_violation->feasible;
  }
  rec.applied = true;
  r.empty_reason.clear();
  return rec;
}

}  // namespace

SceneResult scene_feasible_set(const PreparedCanonical& pc, const std::vector<Colour>& image) {
  const SelectSceneOptions& o = pc.options;
  const Chromaticities iq = internal::scene_chromaticities(image, o.nonpositive_blue, SceneInput::image);
  SceneResult r;
  r.image_colours = image.size();
  r.image_dropped = iq.dropped;
  try {
    r.feasible = feasible_set(pc.constrained ? *pc.constrained : pc.constraints, iq.points);
    if (pc.constrained) {
      ConstraintReport cr;
      cr.illuminants = o.illuminants->size();
      cr.maps = *pc.constraint;
      cr.unconstrained = feasible_set(pc.constraints, iq.points);
      r.constraint = std::move(cr);
    }
  } catch (const UnboundedFeasibleSet& e) {
    throw SceneInputError(SceneInput::image, SceneProblem::unbounded, std::nullopt, e.what());
  }
  // F's coordinates are canonical over image chromaticities: both within the limit can still
  // give maps beyond it.
  for (const ConvexSet2* f : {&r.feasible, r.constraint ? &r.constraint->unconstrained : nullptr})
    if (f)
      for (const Point2& v : f->vertices)
        if (!within_limit(v))
          throw SceneInputError(SceneInput::image, SceneProblem::too_large, std::nullopt,
                                "the feasible maps exceed 1e150, the largest coordinate gmcc "
                                "accepts (it reports doubles): the canonical chromaticities are "
                                "that much larger than this image's");
  if (r.feasible.kind == ConvexKind::empty)
    r.empty_reason = internal::empty_reason(!r.constraint || r.constraint->unconstrained.kind == ConvexKind::empty);
  if (o.on_empty != RecoveryPolicy::none) r.recovery = recover(pc, iq.points, r);
  return r;
}

SceneResult select_scene(const PreparedCanonical& pc, const std::vector<Colour>& image,
                         const std::optional<Colour>& truth) {
  return select_scene(pc, image, truth, pc.options);
}

SceneResult select_scene(const PreparedCanonical& pc, const std::vector<Colour>& image,
                         const std::optional<Colour>& truth, const SceneChoices& choices) {
  check_options(choices.mean3d);
  const SelectSceneOptions& o = pc.options;
  const Colour& c = o.canonical_illuminant;
  std::optional<Point2> true_map;
  if (truth) {
    if (sgn(truth->r) <= 0 || sgn(truth->g) <= 0 || sgn(truth->b) <= 0)
      throw SceneInputError(SceneInput::truth, SceneProblem::nonpositive_light, std::nullopt,
                            "the true light needs every channel > 0 (its map c ⊘ e is undefined)");
    true_map = illuminant_map(*truth, c);
  }
  SceneResult r = scene_feasible_set(pc, image);
  SelectionOptions selection;
  selection.mean3d = choices.mean3d;
  if (choices.illuminant_worst_case) selection.illuminant_worst_case_for = c;
  r.selections = select_maps(r.feasible, selection);
  if (true_map) {
    TruthReport t;
    t.light = *truth;
    t.map = *true_map;
    t.in_feasible_set = r.feasible.kind != ConvexKind::empty && contains(r.feasible, *true_map);
    for (Rule rule : all_rules)
      if (const std::optional<Selection>& s = r.selections[rule]) t.errors[rule] = exact_rule_errors(*s, *true_map, c);
    r.truth = std::move(t);
  }
  return r;
}

}  // namespace gmcc
