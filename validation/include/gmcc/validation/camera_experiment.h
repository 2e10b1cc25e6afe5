#pragma once
/// \file camera_experiment.h
/// The analogue of Finlayson & Hordley (1999) §4, Fig. 5 with a real camera: the paper's SONY
/// DXC-930 sensitivities, the 24 Macbeth chart reflectances, SFU lab lights.

#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/input/spectral_table.h>

#include <string>
#include <vector>

namespace gmcc {

/// The setup: the canonical gamut from `canonical_reflectances` under the canonical light, and
/// scenes drawn from `scene_reflectances` under each test light, all rendered exactly (render())
/// through the camera's sensors; the true map is the diagonal map between
/// the lights' white points, d_k = white_canonical,k / white_test,k → (d1/d3, d2/d3). With
/// broad-band sensors the diagonal model is only approximate, so scenes may have an empty
/// feasible set or one that misses the true map; the experiment counts both.
/// \param sensors a table with columns R, G, B; reflectances and lights on the same grid.
/// \param canonical_reflectances the surfaces whose colours under the canonical light make G_c.
/// \param scene_reflectances the surfaces scenes are drawn from (one column each).
/// \param lights the lights' spectral power distributions, one column per light.
/// \param canonical_light the column of `lights` that is the canonical light.
/// \param test_lights the columns of `lights` scenes are rendered under, in report order.
ExperimentSetup camera_setup(const SpectralTable& sensors, const SpectralTable& canonical_reflectances,
                             const SpectralTable& scene_reflectances, const SpectralTable& lights,
                             const std::string& canonical_light,
                             const std::vector<std::string>& test_lights);

}  // namespace gmcc
