/// \file crule_results.cpp
/// CRULE's 3-D result classes: ConvexSet3, Selection3 and Crule3d (results.h).

#include "docstrings.h"
#include "results.h"

#include <gmcc/geometry/convex_set_3.h>

#include <pybind11/stl.h>

#include <string>

namespace gmcc::python {
namespace {

// Forsyth's feasible set F3.
void bind_convex_set3(py::module_& m) {
  py::class_<ConvexSet3>(m, "ConvexSet3", R"doc(An exact convex set of 3-D diagonal maps: Forsyth's feasible set F3.

The maps d = (d1, d2, d3) taking every image colour into the canonical gamut (Forsyth 1990 §3;
docs/math.md §1b): a polytope, polygon, segment, point or empty, with rational vertices. Made
by crule_3d and estimate_3d, not constructed; ``len(s)`` is the number of vertices.

Attributes
----------
kind : str
    'polytope', 'polygon', 'segment', 'point' or 'empty'.
vertices : list of tuple of (Fraction, Fraction, Fraction)
    The exact vertices, sorted.
vertices_float : numpy.ndarray of float64, shape (k, 3)
    The vertices as the nearest doubles.
faces : list of list of int
    The facets as cycles of vertex indices.
volume : Fraction
    The exact volume (0 unless a polytope).
)doc")
      .def_property_readonly("kind", [](const ConvexSet3& s) { return to_string(s.kind); })
      .def_property_readonly("vertices", [](const ConvexSet3& s) {
        py::list l;
        for (const Point3& p : s.vertices) l.append(point3_tuple(p));
        return l;
      }, "Exact vertices, a list of (Fraction, Fraction, Fraction), sorted.")
      .def_property_readonly("vertices_float", [](const ConvexSet3& s) {
        std::vector<double> v;
        for (const Point3& p : s.vertices)
          for (const Rational* q : {&p.x, &p.y, &p.z}) v.push_back(to_double_nearest(*q));
        return float_array(v, s.vertices.size(), 3);
      })
      .def_readonly("faces", &ConvexSet3::faces, "Facets as cycles of vertex indices.")
      .def_property_readonly("volume", [](const ConvexSet3& s) { return to_fraction(volume(s)); })
      .def("__len__", [](const ConvexSet3& s) { return s.vertices.size(); })
      .def("__repr__", [](const ConvexSet3& s) {
        return "ConvexSet3(" + to_string(s.kind) + ", " + std::to_string(s.vertices.size()) +
               " vertices, volume≈" + g10(to_double_nearest(volume(s))) + ")";
      });
}

// A 3-D CRULE rule's map and its worst case.
void bind_selection3(py::module_& m) {
  py::class_<Selection3>(m, "Selection3", (std::string(R"doc(A 3-D CRULE rule's diagonal map and its worst case.

Max-volume (Forsyth 1990 §4, CRULE-MV; docs/derivations.md §2.4) or the centroid (Barnard,
Cardei & Funt 2002, CRULE-AVE) of F3, with the largest map-space angle to a map of F3. Part
of a Crule3d, not constructed.

Attributes
----------
rule : str
    'max_volume' or 'centroid'.
method : str
    'exact' (rational) or 'certified' (a quadratic irrational, enclosed).
)doc") + doc::map3_attributes + R"doc(enclosure : numpy.ndarray of float64, shape (3, 2)
    A certified enclosure, rows (lo, hi) per component.
worst_case_deg : float or None
    The largest angle from the map to a map of F3, degrees.
)doc").c_str())
      .def_property_readonly("rule", [](const Selection3& s) { return s.estimate.rule; })
      .def_property_readonly("method", [](const Selection3& s) { return s.estimate.method; },
                             "`exact` (rational) or `certified` (a quadratic irrational, enclosed).")
      .def_property_readonly("map", [](const Selection3& s) {
        return py::make_tuple(s.estimate.map[0], s.estimate.map[1], s.estimate.map[2]);
      })
      .def_property_readonly("exact", [](const Selection3& s) -> py::object {
        if (!s.estimate.exact) return py::none();
        return point3_tuple(*s.estimate.exact);
      })
      .def_property_readonly("error_bound", [](const Selection3& s) { return s.estimate.error_bound; })
      .def_property_readonly("enclosure", [](const Selection3& s) {
        const auto& q = s.estimate.enclosure;
        return float_array({q[0][0], q[0][1], q[1][0], q[1][1], q[2][0], q[2][1]}, 3, 2);
      })
      .def_property_readonly("worst_case_deg", [](const Selection3& s) { return optional_double(s.worst_case_deg); })
      .def("__repr__", [](const Selection3& s) {
        const auto& e = s.estimate;
        return "Selection3(" + e.rule + " (" + g10(e.map[0]) + ", " + g10(e.map[1]) + ", " + g10(e.map[2]) +
               ") " + e.method + ")";
      });
}

// The whole CRULE result.
void bind_crule3d(py::module_& m) {
  py::class_<Crule3d>(m, "Crule3d", R"doc(Forsyth's CRULE in 3-D on colours: F3, its volume and two selections.

The feasible set F3 of diagonal maps (Forsyth 1990 §3) with the max-volume map (CRULE-MV) and
the centroid (CRULE-AVE, Barnard, Cardei & Funt 2002). Made by crule_3d, not constructed.

Attributes
----------
feasible_set : ConvexSet3
    F3, exactly.
volume : Fraction
    F3's exact volume.
max_volume, centroid : Selection3 or None
    The two selections; None when F3 is empty.
)doc")
      .def_readonly("feasible_set", &Crule3d::feasible)
      .def_property_readonly("volume", [](const Crule3d& c) { return to_fraction(c.volume.value()); })
      .def_readonly("max_volume", &Crule3d::max_volume)
      .def_readonly("centroid", &Crule3d::centroid)
      .def("__repr__", [](const Crule3d& c) {
        return "Crule3d(" + to_string(c.feasible.kind) + ", " + std::to_string(c.feasible.vertices.size()) +
               " vertices, volume≈" + g10(to_double_nearest(c.volume.value())) + ")";
      });
}

}  // namespace

// CRULE in 3-D: F3, its selections and the whole result.
void bind_crule_classes(py::module_& m) {
  bind_convex_set3(m);
  bind_selection3(m);
  bind_crule3d(m);
}

}  // namespace gmcc::python
