#pragma once
// Chromaticities of one input of the select pipeline, with its checks (select_scene.h).

#include <gmcc/geometry/chromaticity.h>
#include <gmcc/selection/select_scene_options.h>

namespace gmcc::internal {

// perspective_chromaticities under `policy`, every point within max_scene_coordinate.
// Throws SceneInputError naming `input` (and the colour's index where one colour is at fault).
inline Chromaticities scene_chromaticities(const std::vector<Colour>& colours,
                                           NonPositiveBluePolicy policy, SceneInput input) {
  Chromaticities c;
  try {
    c = perspective_chromaticities(colours, policy);
  } catch (const NonPositiveBlue& e) {
    throw SceneInputError(input, SceneProblem::nonpositive_blue, e.index,
                          "b <= 0: this colour has no perspective chromaticity (r/b, g/b)");
  }
  if (c.points.empty())
    throw SceneInputError(input, SceneProblem::no_usable_colour, std::nullopt,
                          colours.empty() ? "no colours"
                                          : "no usable colour: every colour has b = 0 and so no chromaticity");
  for (std::size_t i = 0; i < c.points.size(); ++i)
    if (c.points[i].x > max_scene_coordinate() || c.points[i].y > max_scene_coordinate())
      throw SceneInputError(input, SceneProblem::too_large, c.source_index[i],
                            "the chromaticity r/b or g/b exceeds 1e150, the largest gmcc accepts "
                            "(it reports doubles): is b nearly 0?");
  return c;
}

}  // namespace gmcc::internal
