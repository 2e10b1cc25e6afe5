#pragma once
// One cell's scenes of the gamut-mapping experiment (gamut_scenes.cpp): drawn from the scene
// generator and scored. Internal to gmcc::validation; run_gamut_experiment (gamut_experiment.cpp)
// shares the cells out among its threads.

#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/geometry/feasible_set_3d.h>
#include <gmcc/selection/select_scene_options.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gmcc::internal {

// Scenes s_begin <= s < s_end of cell (light_index, n), each with its own generator, scored;
// `done` counts the scenes finished.
std::vector<SceneRecord> run_cell(const ExperimentSetup& setup, const ExperimentConfig& config,
                                  const CanonicalConstraints& gamut, const CanonicalConstraints3* crule_gamut,
                                  const std::vector<Point2>& chromaticities,
                                  std::size_t light_index, int n, std::uint64_t s_begin, std::uint64_t s_end,
                                  std::atomic<std::uint64_t>& done);

}  // namespace gmcc::internal
