/// \file rules.cpp
/// gmcc._core's rules one by one: each selection rule, worst case and angular error, lights as
/// maps, the illumination constraint, CRULE in 3-D and the error statistics.

#include "bindings.h"
#include "docstrings.h"
#include "options.h"
#include "photo_bindings.h"
#include "results.h"

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

// Each rule, worst case and angular error on its own.
void bind_rules(py::module_& m) {
  m.def("rules", [] {
    py::list keys;
    for (Rule rule : all_rules) keys.append(to_string(rule));
    return keys;
  }, doc::rules.c_str());
  m.def("max_area", [](const ConvexSet2& F) {
    nonempty(F, "max_area");
    return released([&] { return max_area(F); });
  }, py::arg("feasible_set"),
        doc::max_area.c_str());
  m.def("mean_2d", [](const ConvexSet2& F) {
    nonempty(F, "mean_2d");
    return released([&] { return mean_2d(F); });
  }, py::arg("feasible_set"),
        doc::mean_2d.c_str());
  m.def(
      "mean_3d",
      [](const ConvexSet2& F, const std::string& method, py::handle precision, py::handle order, py::handle samples,
         py::handle seed) {
        nonempty(F, "mean_3d");
        const Mean3dOptions o = mean3d_from(py::str(method), precision, order, samples, seed);
        return released([&] { return mean_3d(F, o); });
      },
      py::arg("feasible_set"), py::kw_only(), py::arg("method") = to_string(Mean3dOptions{}.method),
      GMCC_MEAN3D_PARAMETER_ARGS,
      doc::mean_3d.c_str());

  m.def("worst_case_map_deg", [](const ConvexSet2& F, py::handle map) {
    nonempty(F, "worst_case_map_deg");
    const Point2 p = map_from(map, "map");
    return released([&] { return worst_case_map_deg(F, p); });
  }, py::arg("feasible_set"), py::arg("map"),
        doc::worst_case_map_deg.c_str());
  m.def("worst_case_illuminant_deg", [](const ConvexSet2& F, py::handle map, py::handle c) {
    nonempty(F, "worst_case_illuminant_deg");
    const Point2 p = map_from(map, "map");
    const Colour light = light_from(c, "canonical_illuminant");
    for (const Point2& v : F.vertices)
      if (sgn(v.x) <= 0 || sgn(v.y) <= 0)
        throw py::value_error("feasible_set: a vertex touches an axis (an illuminant needs maps > 0)");
    if (sgn(p.x) <= 0 || sgn(p.y) <= 0) throw py::value_error("map: both components must be > 0");
    return released([&] { return worst_case_illuminant_deg(F, p, light); });
  }, py::arg("feasible_set"), py::arg("map"), py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
        doc::worst_case_illuminant_deg.c_str());

  m.def("map_angular_error_deg", [](py::handle estimate, py::handle truth) {
    const Point2 e = map_from(estimate, "estimate"), t = map_from(truth, "truth");
    return map_angular_error_deg(e, t);
  }, py::arg("estimate"), py::arg("truth"),
        doc::map_angular_error_deg.c_str());
  m.def("illuminant_angular_error_deg", [](py::handle estimate, py::handle truth, py::handle c) {
    const Point2 e = map_from(estimate, "estimate"), t = map_from(truth, "truth");
    const Colour light = light_from(c, "canonical_illuminant");
    for (const Point2* p : {&e, &t})
      if (sgn(p->x) <= 0 || sgn(p->y) <= 0) throw py::value_error("estimate and truth: components must be > 0");
    return illuminant_angular_error_deg(e, t, light);
  }, py::arg("estimate"), py::arg("truth"), py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
        doc::illuminant_angular_error_deg.c_str());
  m.def("reproduction_angular_error_deg", [](py::handle estimate, py::handle truth) {
    const Point2 e = map_from(estimate, "estimate"), t = map_from(truth, "truth");
    for (const Point2* p : {&e, &t})
      if (sgn(p->x) <= 0 || sgn(p->y) <= 0) throw py::value_error("estimate and truth: components must be > 0");
    return reproduction_angular_error_deg(e, t);
  }, py::arg("estimate"), py::arg("truth"),
        doc::reproduction_angular_error_deg.c_str());

}

// Lights as maps, the illumination constraint and CRULE in 3-D.
void bind_lights_and_crule(py::module_& m) {
  m.def("illuminant_map", [](py::handle light, py::handle c) {
    return to_fraction_pair(illuminant_map(light_from(light, "light"), light_from(c, "canonical_illuminant")));
  }, py::arg("light"), py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
        doc::illuminant_map.c_str());
  m.def("illumination_constraint", [](py::handle illuminants, py::handle c) {
    const std::vector<Colour> lights = colours_from(illuminants, "illuminants");
    const Colour light = light_from(c, "canonical_illuminant");
    try {
      return illumination_constraint(lights, light);
    } catch (const NonPositiveIlluminant& e) {
      throw py::value_error("illuminants: row " + std::to_string(e.index) + ": " + e.what());
    }
  }, py::arg("illuminants"), py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
        doc::illumination_constraint.c_str());

  m.def("crule_3d", [](py::handle canonical, py::handle image, const std::string& black) {
    const std::vector<Colour> c = colours_or_pixel_colours(canonical, "canonical"),
                              i = colours_or_pixel_colours(image, "image");
    const CanonicalBlack b = black_from(black);
    try {
      return released([&] { return crule_3d(c, i, b); });
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string("crule_3d: ") + e.what());
    }
  }, py::arg("canonical"), py::arg("image"), py::kw_only(), py::arg("black") = "include",
        doc::crule_3d.c_str());
}

// Error statistics.
void bind_error_statistics(py::module_& m) {
  m.def("error_statistics", [](py::handle values) {
    const py::array_t<double, py::array::c_style | py::array::forcecast> a =
        py::module_::import("numpy").attr("asarray")(values, "float64").attr("ravel")();
    std::vector<double> v(a.data(), a.data() + a.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i]))
        throw py::value_error("values: element " + std::to_string(i) + " is not finite (NaN or infinity): drop "
                              "scenes without an error first");
    return error_statistics(std::move(v));
  }, py::arg("values"),
        doc::error_statistics.c_str());

}

}  // namespace gmcc::python
