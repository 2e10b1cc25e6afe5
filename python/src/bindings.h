#pragma once
/// \file bindings.h
/// gmcc._core's function bindings, file by file, in the order module.cpp adds them to the module
/// (the result classes, results.h, come first: signatures name them).

#include <pybind11/pybind11.h>

namespace gmcc::python {

/// prepare_canonical, select_prepared, feasible_prepared, image_colours, read_image and
/// select_maps (scene.cpp).
void bind_scene_functions(pybind11::module_& m);
/// rules, max_area, mean_2d, mean_3d, the worst cases and the angular errors (rules.cpp).
void bind_rules(pybind11::module_& m);
/// illuminant_map, illumination_constraint and crule_3d (rules.cpp).
void bind_lights_and_crule(pybind11::module_& m);
/// error_statistics (rules.cpp).
void bind_error_statistics(pybind11::module_& m);
/// _time_select_scene, run_experiment and run_gehler_shi (experiments.cpp).
void bind_experiments(pybind11::module_& m);

}  // namespace gmcc::python
