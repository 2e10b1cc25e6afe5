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

namespace {

py::array_t<double> vertices_float(const ConvexSet2& s) {
  std::vector<double> v;
  for (const Point2& p : s.vertices) {
    const auto d = to_double_nearest(p);
    v.push_back(d[0]);
    v.push_back(d[1]);
  }
  return float_array(v, s.vertices.size(), 2);
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

// What a scene is scored and recovered with: truth errors, the illumination constraint, recovery.
// A rule's key as a name that outlives the binding (pybind11 keeps the pointer of a name).
const char* rule_key(Rule rule) {
  static const PerRule<std::string> keys = [] {
    PerRule<std::string> k;
    for (Rule r : all_rules) k[r] = to_string(r);
    return k;
  }();
  return keys[rule].c_str();
}

// An illuminant or reproduction error: None for a map with a component <= 0 (it implies no light).
py::object positive_only(const RuleErrors& e, double value) {
  return e.positive_map ? py::object(py::float_(value)) : py::object(py::none());
}

void bind_scene_reports(py::module_& m) {
  py::class_<RuleErrors>(m, "RuleErrors", R"doc(One rule's errors against the true light, in degrees.

The paper's map-space angular error and the rule's worst case over F (Finlayson & Hordley 1999
§4), the recovery error (Hordley & Finlayson 2006) and the reproduction error (Finlayson &
Zakizadeh 2014), as docs/math.md §3 defines them. Part of a Truth, not constructed.

Attributes
----------
map_error_deg : float
    The angle between the rule's map and the true map, lifted as (m1, m2, 1).
worst_case_deg : float
    The largest such angle from the rule's map to any map of F.
illuminant_error_deg : float or None
    The recovery (illuminant-space) angular error; None for a map with a component <= 0.
reproduction_error_deg : float or None
    The reproduction angular error; None likewise.
)doc")
      .def_readonly("map_error_deg", &RuleErrors::map_error_deg,
                    "The paper's map-space angular error (§4).")
      .def_readonly("worst_case_deg", &RuleErrors::worst_case_deg,
                    "The largest map-space angle from the rule's map to any map of F (§4).")
      .def_property_readonly("illuminant_error_deg",
                             [](const RuleErrors& e) { return positive_only(e, e.illuminant_error_deg); },
                             "Recovery (illuminant) angular error; None for a map with a component <= 0.")
      .def_property_readonly("reproduction_error_deg",
                             [](const RuleErrors& e) { return positive_only(e, e.reproduction_error_deg); },
                             "Reproduction angular error (Finlayson & Zakizadeh 2014); None likewise.")
      .def("__repr__", [](const RuleErrors& e) {
        std::string r = "RuleErrors(map " + g10(e.map_error_deg) + " deg";
        if (e.positive_map)
          r += ", illuminant " + g10(e.illuminant_error_deg) + " deg, reproduction " + g10(e.reproduction_error_deg) + " deg";
        return r + ")";
      });
  py::class_<TruthReport> truth(m, "Truth", R"doc(A scene scored against its true light: the true map and each rule's errors.

The true map c ⊘ e in perspective (Finlayson 1996 §5) and each rule's errors against it
(Finlayson & Hordley 1999 §4). A SceneResult's ``truth`` when select was given one, not
constructed.

Attributes
----------
light : tuple of (Fraction, Fraction, Fraction)
    The true light e, exact.
map : tuple of (Fraction, Fraction)
    The true perspective map c ⊘ e, exact.
map_float : tuple of (float, float)
    The true map as the nearest doubles.
in_feasible_set : bool
    Whether the true map lies in F (after the constraint and any recovery), exactly.
max_area, mean_2d, mean_3d : RuleErrors or None
    Each rule's errors (one attribute per rule, named as in gmcc.rules()); None when the rule
    gave no map.
)doc");
  truth.def_property_readonly("light", [](const TruthReport& t) { return colour_tuple(t.light); })
      .def_property_readonly("map", [](const TruthReport& t) { return to_fraction_pair(t.map); },
                             "The true perspective map c ⊘ e, exact.")
      .def_property_readonly("map_float", [](const TruthReport& t) {
        const auto d = to_double_nearest(t.map);
        return py::make_tuple(d[0], d[1]);
      })
      .def_readonly("in_feasible_set", &TruthReport::in_feasible_set)
      .def("__repr__", [](const TruthReport& t) {
        const auto d = to_double_nearest(t.map);
        return "Truth(map (" + g10(d[0]) + ", " + g10(d[1]) + "), " +
               (t.in_feasible_set ? "inside" : "outside") + " F)";
      });
  for (Rule rule : all_rules)
    truth.def_property_readonly(rule_key(rule), [rule](const TruthReport& t) { return t.errors[rule]; },
                                "This rule's errors (RuleErrors); None when it gave no map.");
  py::class_<ConstraintReport>(m, "Constraint", R"doc(Finlayson's illumination constraint as a scene applied it.

C, the hull of the plausible lights' perspective maps, intersected with F (Finlayson 1996 §5).
A SceneResult's ``constraint`` when the canonical side has ``illuminants``, not constructed.

Attributes
----------
illuminants : int
    How many plausible lights C is made of.
maps : ConvexSet
    C: the hull of the lights' perspective maps.
unconstrained : ConvexSet
    F before F ∩ C.
)doc")
      .def_readonly("illuminants", &ConstraintReport::illuminants)
      .def_readonly("maps", &ConstraintReport::maps, "C: the hull of the lights' perspective maps.")
      .def_readonly("unconstrained", &ConstraintReport::unconstrained, "F before F ∩ C.")
      .def("__repr__", [](const ConstraintReport& c) {
        return "Constraint(" + std::to_string(c.illuminants) + " illuminants, C " + convex_set_repr(c.maps) + ")";
      });
  py::class_<RecoveryReport>(m, "Recovery", R"doc(What the recovery policy did with an empty feasible set.

``on_empty='grow-canonical'`` grows G_c until a map fits, as Barnard, Cardei & Funt (2002) Part I
§3 enlarge the canonical gamut; ``'min-violation'`` takes the maps that violate Forsyth's (1990)
constraints least (docs/math.md §1). A SceneResult's ``recovery``, not constructed.

Attributes
----------
policy : str
    The policy asked for: 'none', 'grow-canonical' or 'min-violation'.
reason : str
    Why F was empty.
applied : bool
    True when the policy ran and recovered a non-empty F.
factor : Fraction or None
    grow-canonical: the expansion factor found, else None.
empty_below : Fraction or None
    grow-canonical: the bracket's lower end, a factor at which F is still empty (the least
    factor with a non-empty F lies above it, at most ``factor``); else None.
violation : Fraction or None
    min-violation: the least Chebyshev violation t*, else None.
canonical_gamut : ConvexSet or None
    The gamut the recovered F fits: grow-canonical, G_c grown by ``factor``; min-violation,
    G_c grown by t* in each direction (Chebyshev); else None.
)doc")
      .def_property_readonly("policy", [](const RecoveryReport& r) { return to_string(r.policy); })
      .def_readonly("reason", &RecoveryReport::reason)
      .def_readonly("applied", &RecoveryReport::applied)
      .def_property_readonly("factor", [](const RecoveryReport& r) -> py::object {
        if (!r.grown || !r.grown->found) return py::none();
        return to_fraction(r.grown->factor);
      }, "grow-canonical: the expansion factor found (Fraction), else None.")
      .def_property_readonly("empty_below", [](const RecoveryReport& r) -> py::object {
        if (!r.grown || !r.grown->empty_below) return py::none();
        return to_fraction(*r.grown->empty_below);
      })
      .def_property_readonly("violation", [](const RecoveryReport& r) -> py::object {
        if (!r.min_violation) return py::none();
        return to_fraction(r.min_violation->violation);
      }, "min-violation: the least Chebyshev violation t* (Fraction), else None.")
      .def_property_readonly("canonical_gamut", [](const RecoveryReport& r) -> py::object {
        if (r.grown && r.grown->found) return py::cast(r.grown->canonical);
        if (r.min_violation) return py::cast(r.min_violation->canonical);
        return py::none();
      })
      .def("__repr__", [](const RecoveryReport& r) {
        return "Recovery(" + to_string(r.policy) + (r.applied ? ", applied" : ", not applied") + ")";
      });
}

// A prepared canonical gamut, a scene's result and an image's colours.
void bind_scene(py::module_& m) {
  py::class_<PreparedCanonical, std::shared_ptr<PreparedCanonical>>(
      m, "Canonical", R"doc(The canonical side, prepared once for many images: G_c and the options.

The exact (expanded) canonical gamut G_c of perspective chromaticities (Finlayson & Hordley 1999
eq. 10) and Finlayson's illumination constraint C (Finlayson 1996 §5), with the options of
select. Made by prepare_canonical, not constructed. Immutable; one object may serve many calls,
also from several threads.

Attributes
----------
gamut : ConvexSet
    G_c after expansion.
colours : int
    The canonical colours given.
dropped : int
    Of those, the colours with b <= 0 (dropped).
constraint : ConvexSet or None
    C, when illuminants were given.
chromaticities : numpy.ndarray of float64, shape (n, 2)
    The canonical perspective chromaticities (r/b, g/b) as doubles.
)doc")
      .def_readonly("gamut", &PreparedCanonical::gamut, "G_c after expansion (ConvexSet).")
      .def_readonly("colours", &PreparedCanonical::colours, "Canonical colours given.")
      .def_readonly("dropped", &PreparedCanonical::dropped, "Of those, with b <= 0 (dropped).")
      .def_readonly("constraint", &PreparedCanonical::constraint, "C (ConvexSet) or None.")
      .def_property_readonly("chromaticities", [](const PreparedCanonical& c) {
        std::vector<double> v;
        for (const Point2& p : c.chromaticities) {
          const auto d = to_double_nearest(p);
          v.push_back(d[0]);
          v.push_back(d[1]);
        }
        return float_array(v, c.chromaticities.size(), 2);
      }, "The canonical perspective chromaticities (r/b, g/b) as doubles, shape (n, 2).")
      .def("__repr__", [](const PreparedCanonical& c) {
        return "Canonical(" + std::to_string(c.colours) + " colours, gamut " + convex_set_repr(c.gamut) +
               (c.constraint ? ", constrained" : "") + ")";
      });
  py::class_<Scene> scene(m, "SceneResult", R"doc(Everything select found for one image: F, the selections, their worst cases.

The feasible set F (Finlayson & Hordley 1999 eqs. 7–9, in perspective), the three selections
(§3) with their worst cases (§4), and the truth report when a true light was given. Made by
select, not constructed.

Attributes
----------
feasible_set : ConvexSet
    F (∩ C), or what a recovery policy recovered.
kind : str
    F's kind: 'polygon', 'segment', 'point' or 'empty'.
canonical : Canonical
    The canonical side the scene was selected against.
canonical_gamut : ConvexSet
    Its G_c.
image_colours : int
    The image colours given (after the pixel rules, for an image).
image_dropped : int
    Of those, the colours with b <= 0 (dropped).
empty_reason : str
    Why F is empty; '' when it is not.
constraint : Constraint or None
    The illumination constraint as applied, when there is one.
recovery : Recovery or None
    What the recovery policy did, when F was empty and a policy was asked for.
max_area, mean_2d, mean_3d : Selection or None
    Each rule's answer (one attribute per rule, named as in gmcc.rules()); None when F is empty.
selections : dict of str to Selection or None
    Every rule's answer, keyed by its name: 'max_area', 'mean_2d', 'mean_3d'.
truth : Truth or None
    The truth report, when a true light was given.
pixels : dict of str to int, or None
    For an image: what the pixel rules did (pixels, masked, saturated, dark, bright, kept,
    colours, hull_vertices, no_chromaticity); None for colours.
)doc");
  scene.def_property_readonly("feasible_set", [](const Scene& s) { return s.result.feasible; },
                             "F (∩ C), or what a recovery policy recovered (ConvexSet).")
      .def_property_readonly("kind", [](const Scene& s) { return to_string(s.result.feasible.kind); })
      .def_property_readonly("canonical", [](const Scene& s) { return std::const_pointer_cast<PreparedCanonical>(s.canonical); })
      .def_property_readonly("canonical_gamut", [](const Scene& s) { return s.canonical->gamut; })
      .def_property_readonly("image_colours", [](const Scene& s) { return s.result.image_colours; })
      .def_property_readonly("image_dropped", [](const Scene& s) { return s.result.image_dropped; })
      .def_property_readonly("empty_reason", [](const Scene& s) { return s.result.empty_reason; })
      .def_property_readonly("constraint", [](const Scene& s) { return s.result.constraint; })
      .def_property_readonly("recovery", [](const Scene& s) { return s.result.recovery; })
      .def_property_readonly("selections", [](const Scene& s) { return selections_dict(s.result.selections); },
                             "{'max_area': Selection, 'mean_2d': ..., 'mean_3d': ...}; values None when F is empty.")
      .def_property_readonly("truth", [](const Scene& s) { return s.result.truth; })
      .def_property_readonly("pixels", [](const Scene& s) -> py::object {
        return s.pixels ? pixel_counts(*s.pixels) : py::object(py::none());
      }, "For gmcc.select_image: what the pixel rules did (dict of counts), else None.")
      .def("__repr__", [](const Scene& s) {
        std::string r = "SceneResult(feasible set " + convex_set_repr(s.result.feasible);
        for (const std::optional<Selection>& sel : s.result.selections)
          if (sel) r += ",\n  " + estimate_repr(sel->estimate) +
                        (sel->worst_case_deg ? ", worst case " + g10(*sel->worst_case_deg) + " deg" : "");
        if (!s.result.empty_reason.empty()) r += ", " + s.result.empty_reason;
        return r + ")";
      });
  for (Rule rule : all_rules)
    scene.def_property_readonly(rule_key(rule), [rule](const Scene& s) { return s.result.selections[rule]; },
                                "This rule's answer (Selection); None when F is empty.");
  py::class_<PyImageColours>(m, "ImageColours", R"doc(The colours the pixel rules kept from an image, with the counts.

Pixel colours (colour_set 'distinct' or 'hull-3d': Forsyth 1990 §3, only the 3-D hull's
vertices constrain the diagonal maps) or, for the 2-D perspective route, the chromaticity lifts
(x, y, 1) of the chromaticity hull's vertices (colour_set 'hull': all Finlayson & Hordley 1999
eqs. 7–9 depend on); docs/conventions.md §8. Made by image_colours, not constructed;
``len(c)`` is the number of colours.

Attributes
----------
colour_set : str
    What the colours are: 'distinct', 'hull-3d' (pixel colours) or 'hull' (lifts).
colours : list of tuple of (Fraction, Fraction, Fraction)
    The exact pixel colours; reading it raises ValueError for chromaticity lifts.
colours_float : numpy.ndarray of float64, shape (n, 3)
    The pixel colours as the nearest doubles; ValueError for chromaticity lifts.
chromaticity_lifts : list of tuple of (Fraction, Fraction, Fraction)
    colour_set 'hull': the lifts (x, y, 1), exact, counter-clockwise; ValueError for pixel
    colours.
counts : dict of str to int
    What the pixel rules did: pixels, masked, saturated, dark, bright, kept, colours,
    hull_vertices, no_chromaticity.
)doc")
      .def_property_readonly("colour_set", [](const PyImageColours& c) { return to_string(c.set); },
                             "What the colours are: 'distinct', 'hull-3d' (pixel colours) or 'hull' (lifts).")
      .def_property_readonly("colours", [](const PyImageColours& c) {
        require_pixel_colours(c, "colours");
        py::list l;
        for (const Colour& x : c.colours) l.append(colour_tuple(x));
        return l;
      }, "Exact pixel colours, a list of (Fraction, Fraction, Fraction); ValueError for chromaticity lifts.")
      .def_property_readonly("colours_float", [](const PyImageColours& c) {
        require_pixel_colours(c, "colours_float");
        return colours_array(c.colours);
      }, "The pixel colours as the nearest doubles, shape (n, 3); ValueError for chromaticity lifts.")
      .def_property_readonly("chromaticity_lifts", [](const PyImageColours& c) {
        if (pixel_colours(c.set))
          throw py::value_error("chromaticity_lifts: these are pixel colours (colour_set '" + to_string(c.set) +
                                "'); use .colours");
        py::list l;
        for (const Colour& x : c.colours) l.append(colour_tuple(x));
        return l;
      }, "colour_set 'hull': the lifts (x, y, 1) of the chromaticity hull's vertices, exact, counter-clockwise.")
      .def_property_readonly("counts", [](const PyImageColours& c) { return pixel_counts(c.counts); })
      .def("__len__", [](const PyImageColours& c) { return c.colours.size(); })
      .def("__repr__", [](const PyImageColours& c) {
        return "ImageColours(" + std::to_string(c.colours.size()) + (pixel_colours(c.set) ? " colours" : " chromaticity lifts") +
               " of " + std::to_string(c.counts.pixels) + " pixels, " + std::to_string(c.counts.kept) + " kept)";
      });
}

// CRULE in 3-D: F3, its selections and the whole result.
void bind_crule(py::module_& m) {
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
  py::class_<Selection3>(m, "Selection3", R"doc(A 3-D CRULE rule's diagonal map and its worst case.

Max-volume (Forsyth 1990 §4, CRULE-MV; docs/derivations.md §2.4) or the centroid (Barnard,
Cardei & Funt 2002, CRULE-AVE) of F3, with the largest map-space angle to a map of F3. Part
of a Crule3d, not constructed.

Attributes
----------
rule : str
    'max_volume' or 'centroid'.
method : str
    'exact' (rational) or 'certified' (a quadratic irrational, enclosed).
map : tuple of (float, float, float)
    The map (d1, d2, d3) as doubles.
exact : tuple of (Fraction, Fraction, Fraction) or None
    The exact map where it is rational, else None.
error_bound : float
    A rigorous bound on the largest component's distance from the true value.
enclosure : numpy.ndarray of float64, shape (3, 2)
    A certified enclosure, rows (lo, hi) per component.
worst_case_deg : float or None
    The largest angle from the map to a map of F3, degrees.
)doc")
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
  bind_scene_reports(m);
  bind_scene(m);
  bind_crule(m);
  bind_statistics(m);
}

}  // namespace gmcc::python
