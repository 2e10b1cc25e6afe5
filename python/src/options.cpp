/// \file options.cpp
/// gmcc._core's option checks (options.h).

#include "options.h"

#include <gmcc/geometry/illumination_constraint.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/selection/worst_case.h>
#include <gmcc/selection/worst_case_illuminant.h>
#include <gmcc/input/build_info.h>
#include <gmcc/input/camera_image.h>
#include <gmcc/input/raw_file.h>
#include <gmcc/validation/camera_experiment.h>
#include <gmcc/validation/error_statistics.h>
#include <gmcc/validation/gamut_experiment.h>
#include <gmcc/input/gehler_shi.h>
#include <gmcc/validation/gehler_shi_experiment.h>
#include <gmcc/input/spectral_table.h>
#include <gmcc/validation/synthetic_experiment.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace gmcc::python {

// ---- options (the command line's checks, with the Python argument names) ----

// The expansion of the canonical gamut (`expand`, `expand_policy`), checked by the library.
Expansion expansion_from(py::handle expand, const std::string& expand_policy) {
  Expansion x;
  try {
    x.policy = expansion_policy_from_string(expand_policy);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("expand_policy: ") + e.what());
  }
  x.factor = number_from(expand, "expand");
  try {
    check_options(x);
  } catch (const OptionError& e) {
    throw py::value_error(e.option + ": " + e.what());
  }
  return x;
}

SelectSceneOptions scene_options(py::handle expand, const std::string& expand_policy, py::handle illuminants,
                                 py::handle canonical_illuminant, const std::string& on_empty,
                                 const std::string& mean3d, py::handle precision, py::handle order,
                                 py::handle samples, py::handle seed, bool illuminant_worst_case,
                                 const std::string& nonpositive_blue) {
  SelectSceneOptions o;
  try {
    o.on_empty = recovery_policy_from_string(on_empty);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("on_empty: ") + e.what());
  }
  try {
    o.nonpositive_blue = nonpositive_blue_policy_from_string(nonpositive_blue);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("nonpositive_blue: ") + e.what());
  }
  o.expansion = expansion_from(expand, expand_policy);
  if (o.on_empty == RecoveryPolicy::grow_canonical && o.expansion.policy == ExpansionPolicy::centroid_clip)
    throw py::value_error("on_empty: grow-canonical grows the gamut by the multiplicative policy; it cannot "
                          "continue a centroid-clip expansion (use expand_policy='multiplicative')");
  o.illuminant_worst_case = illuminant_worst_case;
  o.canonical_illuminant = light_from(canonical_illuminant, "canonical_illuminant");
  if (!illuminants.is_none()) o.illuminants = colours_from(illuminants, "illuminants");
  o.mean3d = mean3d_from(py::str(mean3d), precision, order, samples, seed);
  return o;
}

Mean3dOptions mean3d_from(py::handle mean3d, py::handle precision, py::handle order, py::handle samples,
                          py::handle seed) {
  Mean3dOptions m;
  try {
    m.method = mean3d_method_from_string(mean3d.cast<std::string>());
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("mean3d: ") + e.what());
  }
  // Read within the library's ranges (mean_3d.h), then the library's own check; only the names
  // are Python's.
  m.precision_bits = integer_in<unsigned>(precision, "precision", mean3d_precision_range);
  m.order = integer_in<unsigned>(order, "order", mean3d_order_range);
  m.samples = integer_in<std::uint64_t>(samples, "samples", mean3d_samples_range);
  m.seed = integer_in<std::uint64_t>(seed, "seed", mean3d_seed_range);
  try {
    check_options(m);
  } catch (const OptionError& e) {
    throw py::value_error(e.option + ": " + e.what());
  }
  return m;
}

// A SceneInputError as ValueError, naming the Python argument and the row (0-based).
[[noreturn]] void raise_scene_error(const SceneInputError& e) {
  static const char* names[] = {"canonical", "image", "illuminants", "truth",
                                "canonical_illuminant", "expand", "on_empty"};
  std::string m = names[static_cast<int>(e.input)];
  if (e.index) m += ": row " + std::to_string(*e.index);
  m += std::string(": ") + e.what();
  if (e.problem == SceneProblem::nonpositive_blue) m += "; use nonpositive_blue='drop' to skip such colours";
  throw py::value_error(m);
}

const ConvexSet2& nonempty(const ConvexSet2& F, const char* what) {
  if (F.kind == ConvexKind::empty) throw py::value_error(std::string(what) + ": the feasible set is empty");
  return F;
}

}  // namespace gmcc::python
