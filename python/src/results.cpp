/// \file results.cpp
/// The 2-D map classes (ConvexSet, MapEstimate, Selection), ErrorStatistics and the helpers the
/// result classes share; bind_results adds every result class in order (results.h).

#include "results.h"

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/validation/error_statistics.h>

#include <pybind11/stl.h>

#include <cstdio>

namespace gmcc::python {

py::object pixel_counts(const PixelCounts& c) {
  py::dict d;
  d["pixels"] = c.pixels;
  d["masked"] = c.masked;
  d["saturated"] = c.saturated;
  d["dark"] = c.dark;
  d["bright"] = c.bright;
  d["kept"] = c.kept;
  d["colours"] = c.colours;
  d["hull_vertices"] = c.hull_vertices;
  d["no_chromaticity"] = c.no_chromaticity;
  return std::move(d);
}

std::string g10(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

py::dict selections_dict(const Selections& selections) {
  py::dict d;
  for (Rule rule : all_rules) d[py::str(to_string(rule))] = py::cast(selections[rule]);
  return d;
}

py::object optional_double(const std::optional<double>& x) {
  return x ? py::object(py::float_(*x)) : py::object(py::none());
}

py::object colour_tuple(const Colour& c) {
  return py::make_tuple(to_fraction(c.r), to_fraction(c.g), to_fraction(c.b));
}

py::object point3_tuple(const Point3& p) {
  return py::make_tuple(to_fraction(p.x), to_fraction(p.y), to_fraction(p.z));
}

std::string convex_set_repr(const ConvexSet2& s) {
  std::string r = "ConvexSet(" + to_string(s.kind);
  if (s.kind != ConvexKind::empty) r += ", " + std::to_string(s.vertices.size()) + " vertices";
  if (s.kind == ConvexKind::polygon) r += ", area≈" + g10(to_double_nearest(area(s)));
  if (s.kind == ConvexKind::point) {
    const auto d = to_double_nearest(s.vertices[0]);
    r += " at (" + g10(d[0]) + ", " + g10(d[1]) + ")";
  }
  return r + ")";
}

std::string estimate_repr(const MapEstimate& e) {
  if (!e.valid) return e.rule + ": no map (" + e.method + ": " + e.note + ")";
  std::string r = e.rule + " (" + g10(e.map[0]) + ", " + g10(e.map[1]) + ") ";
  if (e.exact) return r + "exact";
  return r + e.method + " ± " + g10(e.error_bound);
}

py::array_t<double> points_float(const std::vector<Point2>& points) {
  std::vector<double> v;
  for (const Point2& p : points) {
    const auto d = to_double_nearest(p);
    v.push_back(d[0]);
    v.push_back(d[1]);
  }
  return float_array(v, points.size(), 2);
}

namespace {

py::array_t<double> vertices_float(const ConvexSet2& s) { return points_float(s.vertices); }

// The MapEstimate's properties, on MapEstimate itself and (forwarded) on Selection.
template <class Class, class Get>
void estimate_properties(Class& c, Get get) {
  c.def_property_readonly("rule", [get](const typename Class::type& s) { return get(s).rule; },
                          "`max_area`, `mean_2d` or `mean_3d`.")
      .def_property_readonly("method", [get](const typename Class::type& s) { return get(s).method; },
                             "`exact` (a rational rule), `analytic`, `quadrature` or `monte-carlo`.")
      .def_property_readonly("valid", [get](const typename Class::type& s) { return get(s).valid; },
                             "False when the route could not produce a map (see `note`).")
      .def_property_readonly("note", [get](const typename Class::type& s) { return get(s).note; })
      .def_property_readonly(
          "map",
          [get](const typename Class::type& s) -> py::object {
            const MapEstimate& e = get(s);
            if (!e.valid) return py::none();
            return py::make_tuple(e.map[0], e.map[1]);
          },
          "The perspective map (d1/d3, d2/d3) as the nearest doubles; None when not valid.")
      .def_property_readonly(
          "exact",
          [get](const typename Class::type& s) -> py::object {
            const MapEstimate& e = get(s);
            if (!e.exact) return py::none();
            return to_fraction_pair(*e.exact);
          },
          "The exact map as (Fraction, Fraction) where the rule's answer is rational, else None.")
      .def_property_readonly("error_bound", [get](const typename Class::type& s) { return get(s).error_bound; },
                             "max of error_bounds.")
      .def_property_readonly(
          "error_bounds",
          [get](const typename Class::type& s) {
            const MapEstimate& e = get(s);
            return py::make_tuple(e.error_bounds[0], e.error_bounds[1]);
          },
          "Per component: a rigorous bound on |map - true map| (exact, analytic), the truncation "
          "estimate plus rounding bound (quadrature), the standard error (monte-carlo).")
      .def_property_readonly(
          "correctly_rounded",
          [get](const typename Class::type& s) {
            const MapEstimate& e = get(s);
            return py::make_tuple(e.correctly_rounded[0], e.correctly_rounded[1]);
          },
          "Per component: map is the double nearest the true value.")
      .def_property_readonly(
          "enclosure",
          [get](const typename Class::type& s) -> py::object {
            const MapEstimate& e = get(s);
            if (!e.enclosure) return py::none();
            const auto& q = *e.enclosure;
            return float_array({q[0][0], q[0][1], q[1][0], q[1][1]}, 2, 2);
          },
          "exact and analytic: a certified enclosure, rows (lo, hi) per component; else None.")
      .def_property_readonly("precision_bits", [get](const typename Class::type& s) { return get(s).precision_bits; })
      .def_property_readonly("order", [get](const typename Class::type& s) { return get(s).quadrature_order; })
      .def_property_readonly("samples", [get](const typename Class::type& s) { return get(s).samples; })
      .def_property_readonly("samples_kept", [get](const typename Class::type& s) { return get(s).samples_kept; })
      .def_property_readonly("seed", [get](const typename Class::type& s) { return get(s).seed; })
      .def_property_readonly("standard_error", [get](const typename Class::type& s) {
        const MapEstimate& e = get(s);
        return py::make_tuple(e.standard_error[0], e.standard_error[1]);
      });
}

// The 2-D feasible set and gamut type.
void bind_convex_set(py::module_& m) {
  py::class_<ConvexSet2>(m, "ConvexSet", R"doc(An exact closed convex set of the plane: polygon, segment, point or empty.

A feasible set of perspective maps F (Finlayson & Hordley 1999 eqs. 7–9, in perspective) or a
gamut of chromaticities G_c (eq. 10), with rational vertices. Degenerate kinds are results, not
errors (docs/conventions.md §6). Made by gmcc (canonical_gamut, feasible_set, select, ...), not
constructed; ``len(s)`` is the number of vertices, ``bool(s)`` whether it is not empty, and ``==``
compares exactly.

Attributes
----------
kind : str
    'polygon', 'segment', 'point' or 'empty'.
vertices : list of tuple of (Fraction, Fraction)
    The exact vertices: a polygon counter-clockwise from its lexicographically smallest
    vertex, a segment's two ends, a point's one.
vertices_float : numpy.ndarray of float64, shape (k, 2)
    The vertices as the nearest doubles.
area : Fraction
    The exact area (0 unless a polygon).
area_float : float
    The area as the nearest double.
centroid : tuple of (Fraction, Fraction) or None
    The exact centroid in the set's own dimension (the 2-D mean's map); None when empty.
)doc")
      .def_property_readonly("kind", [](const ConvexSet2& s) { return to_string(s.kind); },
                             "`polygon`, `segment`, `point` or `empty`.")
      .def_property_readonly(
          "vertices",
          [](const ConvexSet2& s) {
            py::list l;
            for (const Point2& p : s.vertices) l.append(to_fraction_pair(p));
            return l;
          },
          "The exact vertices, a list of (Fraction, Fraction).")
      .def_property_readonly("vertices_float", &vertices_float,
                             "The vertices as the nearest doubles, a float array of shape (k, 2).")
      .def_property_readonly("area", [](const ConvexSet2& s) { return to_fraction(area(s)); },
                             "The exact area, a Fraction (0 unless a polygon).")
      .def_property_readonly("area_float", [](const ConvexSet2& s) { return to_double_nearest(area(s)); },
                             "The area as the nearest double.")
      .def_property_readonly(
          "centroid",
          [](const ConvexSet2& s) -> py::object {
            if (s.kind == ConvexKind::empty) return py::none();
            return to_fraction_pair(centroid(s));
          },
          "The exact centroid of the set in its own dimension (the 2-D mean's map), or None.")
      .def(
          "contains",
          [](const ConvexSet2& s, py::handle p) { return contains(s, map_from(p, "point")); },
          py::arg("point"), R"doc(Whether a point lies in the closed set, decided exactly.

For F, whether a map is feasible (Finlayson & Hordley 1999 eqs. 7–9).

Parameters
----------
point : sequence of 2 numbers
    The point (x, y), taken exactly (a float is the rational of its value).

Returns
-------
bool
    True on the boundary too.

Raises
------
ValueError
    The point is not two finite numbers.
)doc")
      .def("__len__", [](const ConvexSet2& s) { return s.vertices.size(); })
      .def("__bool__", [](const ConvexSet2& s) { return s.kind != ConvexKind::empty; })
      .def("__eq__", [](const ConvexSet2& a, const ConvexSet2& b) { return a == b; })
      .def("__repr__", &convex_set_repr);
}

// A rule's map with its provenance and error statement.
void bind_map_estimate(py::module_& m) {
  auto estimate = py::class_<MapEstimate>(
      m, "MapEstimate", R"doc(A selection rule's perspective map with its provenance and error statement.

The map (d1/d3, d2/d3) one of the rules of Finlayson & Hordley (1999) §3 selects: exact where
the rule's answer is rational (max-area, 2-D mean), else the double map with its error
statement (3-D mean; docs/math.md §2). Made by max_area, mean_2d and mean_3d, not constructed.

Attributes
----------
rule : str
    'max_area', 'mean_2d' or 'mean_3d'.
method : str
    'exact' (a rational rule), 'analytic', 'quadrature' or 'monte-carlo'.
valid : bool
    False when the route could not produce a map (see ``note``).
note : str
    Why the map is not valid, or a caveat on a valid one; '' otherwise.
map : tuple of (float, float) or None
    The map as the nearest doubles; None when not valid.
exact : tuple of (Fraction, Fraction) or None
    The exact map where the rule's answer is rational, else None.
error_bound : float
    The larger of ``error_bounds``.
error_bounds : tuple of (float, float)
    Per component: a rigorous bound on abs(map - true map) (exact, analytic), the truncation
    estimate plus rounding bound (quadrature), the standard error (monte-carlo).
correctly_rounded : tuple of (bool, bool)
    Per component: ``map`` is the double nearest the true value.
enclosure : numpy.ndarray of float64, shape (2, 2), or None
    exact and analytic: a certified enclosure, rows (lo, hi) per component; else None.
precision_bits : int
    analytic: the working precision, bits (64: the x87 extended fast path); else 0.
order : int
    quadrature: Gauss–Legendre points per direction; else 0.
samples : int
    monte-carlo: the points drawn in the unit cube; else 0.
samples_kept : int
    monte-carlo: of those, the points inside cone ∩ ball.
seed : int
    monte-carlo: the seed of its mt19937_64 generator.
standard_error : tuple of (float, float)
    monte-carlo: the standard error per component; else zeros.
)doc");
  estimate_properties(estimate, [](const MapEstimate& e) -> const MapEstimate& { return e; });
  estimate.def("__repr__", [](const MapEstimate& e) { return "MapEstimate(" + estimate_repr(e) + ")"; });
}

// A rule's map with its worst cases.
void bind_selection(py::module_& m) {
  auto selection = py::class_<Selection>(
      m, "Selection", R"doc(One rule's answer on F and the largest error it can make within F.

A selection rule's map (Finlayson & Hordley 1999 §3) with its worst cases (§4): the angle to
the farthest map of F, in map space and in illuminant space (docs/derivations.md §3). It has
every attribute of its ``estimate`` (a MapEstimate), forwarded; it is not a subclass of
MapEstimate. Made by select and select_maps, not constructed.

Attributes
----------
estimate : MapEstimate
    The rule's map and error statement.
rule, method, valid, note, map, exact, error_bound, error_bounds, correctly_rounded, enclosure, precision_bits, order, samples, samples_kept, seed, standard_error
    As MapEstimate, forwarded from ``estimate``.
worst_case_deg : float or None
    The largest map-space angular error within F, degrees (None if not valid).
worst_case_illuminant_deg : float or None
    The same in illuminant space (docs/derivations.md §3.2); None when not computed.
)doc");
  estimate_properties(selection, [](const Selection& s) -> const MapEstimate& { return s.estimate; });
  selection
      .def_property_readonly("estimate", [](const Selection& s) { return s.estimate; })
      .def_property_readonly("worst_case_deg", [](const Selection& s) { return optional_double(s.worst_case_deg); },
                             "The largest map-space angular error within F, degrees (None if not valid).")
      .def_property_readonly(
          "worst_case_illuminant_deg",
          [](const Selection& s) { return optional_double(s.worst_case_illuminant_deg); },
          "The same in illuminant space (docs/derivations.md §3.2); None when not computed.")
      .def("__repr__", [](const Selection& s) {
        std::string r = "Selection(" + estimate_repr(s.estimate);
        if (s.worst_case_deg) r += ", worst case " + g10(*s.worst_case_deg) + " deg";
        return r + ")";
      });
}

// Error statistics over scenes.
void bind_statistics(py::module_& m) {
  py::class_<ErrorStatistics>(m, "ErrorStatistics", R"doc(The statistics the field reports for a list of angular errors.

Mean and standard error (Finlayson & Hordley 1999 §4 report the mean), median (Hordley &
Finlayson 2006), trimean, best and worst 25%, 95th percentile and maximum, each defined in
docs/reproduction.md "Statistics". Made by error_statistics and summarise, not constructed.

Attributes
----------
n : int
    How many values the statistics are over (with n = 0 every statistic is NaN, undefined).
mean : float
    The sum over n, summed in the order given.
standard_error : float
    s / sqrt(n), s the sample standard deviation; NaN for n = 1.
median : float
    The 0.5 quantile (Hyndman & Fan type 7, numpy's default).
trimean : float
    (Q(0.25) + 2 median + Q(0.75)) / 4.
best25 : float
    The mean of the ceil(n/4) smallest values.
worst25 : float
    The mean of the ceil(n/4) largest values.
p95 : float
    The 0.95 quantile.
max : float
    The largest value.
)doc")
      .def_readonly("n", &ErrorStatistics::n)
      .def_readonly("mean", &ErrorStatistics::mean)
      .def_readonly("standard_error", &ErrorStatistics::standard_error)
      .def_readonly("median", &ErrorStatistics::median)
      .def_readonly("trimean", &ErrorStatistics::trimean)
      .def_readonly("best25", &ErrorStatistics::best25)
      .def_readonly("worst25", &ErrorStatistics::worst25)
      .def_readonly("p95", &ErrorStatistics::p95)
      .def_readonly("max", &ErrorStatistics::max)
      .def("as_dict", [](const ErrorStatistics& s) {
        py::dict d;
        d["n"] = s.n; d["mean"] = s.mean; d["standard_error"] = s.standard_error; d["median"] = s.median;
        d["trimean"] = s.trimean; d["best25"] = s.best25; d["worst25"] = s.worst25; d["p95"] = s.p95;
        d["max"] = s.max;
        return d;
      }, R"doc(The statistics as a dict, for a table row or JSON.

The statistics of docs/reproduction.md "Statistics": the mean Finlayson & Hordley (1999) §4
report, the median Hordley & Finlayson (2006) recommend, and the rest.

Returns
-------
dict of str to float
    n, mean, standard_error, median, trimean, best25, worst25, p95 and max.
)doc")
      .def("__repr__", [](const ErrorStatistics& s) {
        return "ErrorStatistics(n=" + std::to_string(s.n) + ", mean=" + g10(s.mean) + ", median=" +
               g10(s.median) + ", trimean=" + g10(s.trimean) + ", best25=" + g10(s.best25) +
               ", worst25=" + g10(s.worst25) + ", max=" + g10(s.max) + ")";
      });
}

}  // namespace

void require_pixel_colours(const PyImageColours& c, const char* what) {
  if (!pixel_colours(c.set))
    throw py::value_error(std::string(what) + ": these are chromaticity lifts (x, y, 1) of the 2-D hull colour set, "
                          "not pixel colours; a 3-D method given them returns a meaningless feasible set. Use "
                          ".chromaticity_lifts for the 2-D route, or colour_set='distinct' or 'hull-3d' for pixel colours");
}

std::vector<Colour> colours_or_pixel_colours(py::handle x, const char* what) {
  if (!py::isinstance<PyImageColours>(x)) return colours_from(x, what);
  const PyImageColours& c = x.cast<const PyImageColours&>();
  require_pixel_colours(c, what);
  return c.colours;
}

py::array_t<double> colours_array(const std::vector<Colour>& colours) {
  std::vector<double> v;
  for (const Colour& x : colours)
    for (const Rational* q : {&x.r, &x.g, &x.b}) v.push_back(to_double_nearest(*q));
  return float_array(v, colours.size(), 3);
}


void bind_results(py::module_& m) {
  bind_convex_set(m);
  bind_map_estimate(m);
  bind_selection(m);
  bind_scene_report_classes(m);
  bind_scene_classes(m);
  bind_crule_classes(m);
  bind_statistics(m);
}

}  // namespace gmcc::python
