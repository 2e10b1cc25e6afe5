#pragma once
// Why the select pipeline's F is empty, in the words every front end reports (docs/cli.md
// "JSON output", feasible_set.reason): select_scene.cpp and select_scene_record.cpp. Internal to
// gmcc::selection.

namespace gmcc::internal {

/// `reason` of an empty F: whether F was empty before F ∩ C (the illumination constraint).
inline const char* empty_reason(bool empty_before_constraint) {
  return empty_before_constraint ? "no diagonal map takes every image colour into the canonical gamut"
                                 : "the feasible set is not empty, but it holds no map of a plausible "
                                   "illuminant (the illumination constraint)";
}

}  // namespace gmcc::internal
