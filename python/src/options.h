#pragma once
/// \file options.h
/// gmcc._core's option checks (the command line's, with the Python argument names) and the
/// release of the GIL around a library call, shared by the scene, rule and experiment bindings.

#include "convert.h"
#include "python_interrupt.h"
#include "results.h"

#include <string>

namespace gmcc::python {

/// The expansion of the canonical gamut (`expand`, `expand_policy`), checked by the library.
Expansion expansion_from(py::handle expand, const std::string& expand_policy);

/// select_scene's options from the Python arguments, each checked as the command line checks it.
/// The 3-D mean's options from its Python arguments, read within the library's ranges and
/// checked by the library (check_options, mean_3d.h). \throws ValueError, TypeError naming them.
Mean3dOptions mean3d_from(py::handle mean3d, py::handle precision, py::handle order, py::handle samples,
                          py::handle seed);

SelectSceneOptions scene_options(py::handle expand, const std::string& expand_policy, py::handle illuminants,
                                 py::handle canonical_illuminant, const std::string& on_empty,
                                 const std::string& mean3d, py::handle precision, py::handle order,
                                 py::handle samples, py::handle seed, bool illuminant_worst_case,
                                 const std::string& nonpositive_blue);

/// A SceneInputError as ValueError, naming the Python argument and the row (0-based).
[[noreturn]] void raise_scene_error(const SceneInputError& e);

// Library calls with the GIL released; SceneInputError and std::invalid_argument as ValueError.
template <class F>
auto released(F f) {
  try {
    InterruptibleRelease nogil;
    return f();
  } catch (const SceneInputError& e) {
    raise_scene_error(e);
  }
}

// The 3-D mean's parameters with the library's defaults (Mean3dOptions).
#define GMCC_MEAN3D_PARAMETER_ARGS                                                                \
  py::arg("precision") = Mean3dOptions{}.precision_bits, py::arg("order") = Mean3dOptions{}.order, \
  py::arg("samples") = Mean3dOptions{}.samples, py::arg("seed") = Mean3dOptions{}.seed

#define GMCC_OPTION_ARGS                                                                          \
  py::arg("expand") = 0, py::arg("expand_policy") = "none", py::arg("illuminants") = py::none(),   \
  py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1), py::arg("on_empty") = "none",        \
  py::arg("mean3d") = to_string(Mean3dOptions{}.method), GMCC_MEAN3D_PARAMETER_ARGS,               \
  py::arg("illuminant_worst_case") = true,                                                         \
  py::arg("nonpositive_blue") = "drop"

/// `F`, or ValueError naming `what` when F is empty.
const ConvexSet2& nonempty(const ConvexSet2& F, const char* what);

}  // namespace gmcc::python
