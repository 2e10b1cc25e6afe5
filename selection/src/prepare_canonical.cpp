#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/selection/prepare_canonical.h>

#include "internal/scene_chromaticities.h"

namespace gmcc {
namespace {

void check_options(const SelectSceneOptions& o) {
  const Expansion& e = o.expansion;
  if (sgn(e.factor) < 0)
    throw SceneInputError(SceneInput::expansion, SceneProblem::bad_option, std::nullopt,
                          "the expansion factor must be >= 0");
  if (sgn(e.factor) > 0 && e.policy == ExpansionPolicy::none)
    throw SceneInputError(SceneInput::expansion, SceneProblem::bad_option, std::nullopt,
                          "an expansion factor > 0 needs a policy (centroid-clip or multiplicative)");
  const Colour& c = o.canonical_illuminant;
  if (sgn(c.r) <= 0 || sgn(c.g) <= 0 || sgn(c.b) <= 0)
    throw SceneInputError(SceneInput::canonical_illuminant, SceneProblem::nonpositive_light, std::nullopt,
                          "every channel of the canonical light must be > 0");
  if (o.on_empty == RecoveryPolicy::grow_canonical && e.policy == ExpansionPolicy::centroid_clip)
    throw SceneInputError(SceneInput::on_empty, SceneProblem::bad_option, std::nullopt,
                          "grow-canonical grows the gamut by the multiplicative policy; it cannot "
                          "continue a centroid-clip expansion");
  if (o.illuminants && o.illuminants->empty())
    throw SceneInputError(SceneInput::illuminants, SceneProblem::bad_option, std::nullopt,
                          "no illuminants: the constraint needs at least one light");
  check_options(o.mean3d);
}

}  // namespace

PreparedCanonical prepare_canonical(const std::vector<Colour>& canonical,
                                    const SelectSceneOptions& options) {
  check_options(options);
  Chromaticities cq = internal::scene_chromaticities(canonical, options.nonpositive_blue,
                                                     SceneInput::canonical);
  ConvexSet2 gamut = canonical_gamut(cq.points, options.expansion);
  for (const Point2& v : gamut.vertices)
    if (v.x > max_scene_coordinate() || v.y > max_scene_coordinate())
      throw SceneInputError(SceneInput::expansion, SceneProblem::too_large, std::nullopt,
                            "the expanded canonical gamut exceeds 1e150, the largest coordinate "
                            "gmcc accepts (it reports doubles)");
  std::optional<ConvexSet2> constraint;
  if (options.illuminants) {
    try {
      constraint = illumination_constraint(*options.illuminants, options.canonical_illuminant);
    } catch (const NonPositiveIlluminant& e) {
      throw SceneInputError(SceneInput::illuminants, SceneProblem::nonpositive_light, e.index,
                            "an illuminant needs every channel > 0 (its map c ⊘ e is undefined)");
    }
  }
  CanonicalConstraints constraints(gamut);
  std::optional<CanonicalConstraints> constrained;
  if (constraint) constrained.emplace(gamut, *constraint);
  return PreparedCanonical{options,           std::move(cq.points), canonical.size(),
                           cq.dropped,        std::move(gamut),     std::move(constraint),
                           std::move(constraints), std::move(constrained)};
}

}  // namespace gmcc
