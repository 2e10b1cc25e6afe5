/// \file scene_results.cpp
/// A scene's result classes: its reports (Truth and RuleErrors, Constraint, Recovery), the
/// prepared canonical side, SceneResult and ImageColours (results.h).

#include "results.h"

#include <pybind11/stl.h>

#include <string>

namespace gmcc::python {
namespace {

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

// One rule's errors against the true light, and the truth report holding each rule's.
void bind_truth(py::module_& m) {
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
}

// Finlayson's illumination constraint and the recovery policy, as a scene applied them.
void bind_constraint_and_recovery(py::module_& m) {
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

// The prepared canonical side (gmcc.Canonical).
void bind_canonical(py::module_& m) {
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
        return points_float(c.chromaticities);
      }, "The canonical perspective chromaticities (r/b, g/b) as doubles, shape (n, 2).")
      .def("__repr__", [](const PreparedCanonical& c) {
        return "Canonical(" + std::to_string(c.colours) + " colours, gamut " + convex_set_repr(c.gamut) +
               (c.constraint ? ", constrained" : "") + ")";
      });
}

// Everything select found for one image.
void bind_scene_result(py::module_& m) {
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
}

// The colours the pixel rules kept from an image.
void bind_image_colours(py::module_& m) {
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

}  // namespace

// What a scene is scored and recovered with: truth errors, the illumination constraint, recovery.
void bind_scene_report_classes(py::module_& m) {
  bind_truth(m);
  bind_constraint_and_recovery(m);
}

// A prepared canonical gamut, a scene's result and an image's colours.
void bind_scene_classes(py::module_& m) {
  bind_canonical(m);
  bind_scene_result(m);
  bind_image_colours(m);
}

}  // namespace gmcc::python
