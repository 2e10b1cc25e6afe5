/// \file photo.cpp
/// gmcc._core's whole-image gamut mapping (gmcc/photo/; docs/photographs.md): 3-D canonical gamuts
/// prepared once, 3-D gamut mapping on an image with every 3-D rule, and the canonical gamuts
/// learned image by image. Conversions only; the work is the library's, with the GIL released.

#include "photo.h"

#include "docstrings.h"
#include "photo_bindings.h"

#include <gmcc/photo/estimate_3d.h>

#include <pybind11/stl.h>

#include <deque>
#include <memory>

namespace gmcc::python {

const std::string& learner_add_doc(const char* before, const char* more_parameters, const char* value_error) {
  static std::deque<std::string> docs;
  docs.push_back(std::string(before) + R"doc(light : sequence of 3 numbers
    The image's measured light e, every channel > 0.
)doc" + doc::pixel_rules + more_parameters + R"doc(
Returns
-------
None

Raises
------
ValueError
    )doc" + value_error + R"doc(
TypeError
    An argument of the wrong type.
)doc");
  return docs.back();
}

CanonicalBlack black_from(const std::string& black) {
  try {
    return canonical_black_from_string(black);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("black: ") + e.what());
  }
}
std::vector<Colour> pixel_colours_of(py::handle x, PixelArgs args, const char* what,
                                     std::optional<PixelCounts>* counts, ColourSet* set) {
  if (py::isinstance<PyImageColours>(x)) {
    if (counts) *counts = x.cast<const PyImageColours&>().counts;
    if (set) *set = x.cast<const PyImageColours&>().set;
    return colours_or_pixel_colours(x, what);
  }
  if (is_image(x)) {
    if (args.colour_set == "hull")
      throw py::value_error(std::string(what) + ": colour_set 'hull' gives chromaticity lifts, not pixel colours; "
                            "use 'hull-3d' or 'distinct'");
    PyImageColours c = image_colours_of(x, args);
    if (c.colours.empty()) throw py::value_error(std::string(what) + ": no usable pixel");
    if (counts) *counts = c.counts;
    if (set) *set = c.set;
    return std::move(c.colours);
  }
  if (!args.plain())
    throw py::value_error("mask, black_level, saturation and the dark and bright rules apply to an image of shape "
                          "(H, W, 3), not to colours");
  return colours_from(x, what);
}

Colour positive_light(py::handle x, const char* what) {
  const Colour e = light_from(x, what);
  if (sgn(e.r) <= 0 || sgn(e.g) <= 0 || sgn(e.b) <= 0)
    throw py::value_error(std::string(what) + ": every channel must be > 0");
  return e;
}

PixelArgs pixel_args(py::object mask, py::object black_level, py::object saturation, py::object dark,
                     py::object dark_fraction, py::object bright_fraction, std::string pixel_rule,
                     std::string colour_set) {
  return {std::move(mask), std::move(black_level), std::move(saturation), std::move(dark), std::move(dark_fraction),
          std::move(bright_fraction), std::move(pixel_rule), std::move(colour_set)};
}

namespace {

// A 3-D canonical gamut prepared once.
void bind_canonical3(py::module_& m) {
  py::class_<Canonical3>(m, "Canonical3", R"doc(A 3-D canonical gamut G_c3 prepared once for many images.

The exact half-spaces of the hull of the canonical colours (Forsyth 1990 §3;
feasible_set_3d.h), for estimate_3d. Made by prepare_canonical_3d and
CanonicalLearner3.prepare, not constructed. Immutable; thread-safe.

Attributes
----------
dimension : int
    The dimension of G_c3's affine hull, 0 to 3.
half_spaces : int
    How many half-spaces describe G_c3 (its facets when 3-dimensional).
colours : int
    How many colours it was prepared from.
black : str
    'include' (black joins the hull: F3 is never empty) or 'exclude'.
)doc")
      .def_property_readonly("dimension", [](const Canonical3& c) { return c.constraints->dimension(); },
                             "The dimension of G_c3's affine hull, 0 to 3.")
      .def_property_readonly("half_spaces", [](const Canonical3& c) { return c.constraints->half_spaces(); },
                             "How many half-spaces describe G_c3 (its facets when 3-dimensional).")
      .def_property_readonly("colours", [](const Canonical3& c) { return c.colours; },
                             "How many colours it was prepared from.")
      .def_property_readonly("black", [](const Canonical3& c) {
        return to_string(c.black);
      })
      .def("__repr__", [](const Canonical3& c) {
        return "Canonical3(" + std::to_string(c.colours) + " colours, " + std::to_string(c.constraints->half_spaces()) +
               " half-spaces, black " + (c.black == CanonicalBlack::include ? "included" : "excluded") + ")";
      });
}

// One 3-D rule's answer on an image.
void bind_image_selection3(py::module_& m) {
  py::class_<PySelection3>(m, "ImageSelection3", (std::string(R"doc(One 3-D rule's answer on an image: the map, its worst case and the light it implies.

Max-volume (Forsyth 1990 §4, CRULE-MV), the centroid (Barnard, Cardei & Funt 2002, CRULE-AVE)
or max-trace (Gijsenij, Gevers & van de Weijer 2010 §3) of F3 (estimate_3d.h;
docs/photographs.md §3): the map d, its worst case in F3, the light c ⊘ d it implies and, with
a truth, the recovery error. Part of an Estimate3, not constructed.

Attributes
----------
rule : str
    'max_volume', 'centroid' or 'max_trace'.
method : str
    'exact' (rational) or 'certified' (a double with a rigorous bound).
)doc") + doc::map3_attributes + R"doc(worst_case_deg : float or None
    The largest angle from the map to a map of F3, degrees.
light : tuple of (float, float, float) or None
    The light c ⊘ d with unit length; None when a component of d is 0.
recovery_error_deg : float or None
    With a truth: the angle between ``light`` and the true light, degrees; else None.
map_error_deg : float or None
    With a truth: the angle between the map and the true map c ⊘ e, degrees: the space of
    ``worst_case_deg``, which bounds it whenever ``Estimate3.truth_in_feasible``; else None.
)doc").c_str())
      .def_property_readonly("rule", [](const PySelection3& s) { return s.rule; })
      .def_property_readonly("method", [](const PySelection3& s) { return s.s.selection.estimate.method; },
                             "`exact` (rational) or `certified` (a double with a rigorous bound).")
      .def_property_readonly("map", [](const PySelection3& s) {
        const auto& d = s.s.selection.estimate.map;
        return py::make_tuple(d[0], d[1], d[2]);
      }, "The map (d1, d2, d3) as doubles.")
      .def_property_readonly("exact", [](const PySelection3& s) -> py::object {
        const auto& e = s.s.selection.estimate.exact;
        return e ? point3_tuple(*e) : py::object(py::none());
      }, "The exact map where it is rational, else None.")
      .def_property_readonly("error_bound", [](const PySelection3& s) { return s.s.selection.estimate.error_bound; })
      .def_property_readonly("worst_case_deg", [](const PySelection3& s) { return optional_double(s.s.selection.worst_case_deg); },
                             "The largest angle from the map to a map of F3, degrees.")
      .def_property_readonly("light", [](const PySelection3& s) -> py::object {
        if (!s.s.light) return py::none();
        return py::make_tuple((*s.s.light)[0], (*s.s.light)[1], (*s.s.light)[2]);
      }, "The light c ⊘ d with unit length; None when a component of d is 0.")
      .def_property_readonly("recovery_error_deg", [](const PySelection3& s) { return optional_double(s.s.recovery_error_deg); },
                             "With a truth: the angle between the light and the true light, degrees.")
      .def_property_readonly("map_error_deg", [](const PySelection3& s) { return optional_double(s.s.map_error_deg); },
                             "With a truth: the angle between the map and the true map, degrees.")
      .def("__repr__", [](const PySelection3& s) {
        const auto& d = s.s.selection.estimate.map;
        return "ImageSelection3(" + s.rule + " (" + g10(d[0]) + ", " + g10(d[1]) + ", " + g10(d[2]) + "))";
      });
}

// Estimate3's docstring: its attributes with one per 3-D rule, named by the rules' keys
// (rule_3.h), so that a new rule is documented where it is bound.
const char* estimate3_doc() {
  static const std::string doc = [] {
    std::string keys, quoted;
    for (Rule3 rule : all_rules_3) {
      keys += (keys.empty() ? "" : ", ") + to_string(rule);
      quoted += (quoted.empty() ? "'" : ", '") + to_string(rule) + "'";
    }
    return std::string(R"doc(3-D gamut mapping on one image: F3 and the rules' answers.

The exact feasible set F3 of diagonal maps taking the image's pixel colours into the canonical
gamut (Forsyth 1990 §3; Gijsenij, Gevers & van de Weijer 2010 §3) and the selections asked for
(docs/photographs.md §3). Made by estimate_3d, not constructed.

Attributes
----------
feasible_set : ConvexSet3
    F3, exactly (its vertices in lowest terms are made on the first read: the rules do not need
    them).
kind : str
    F3's kind: 'polytope', 'polygon', 'segment', 'point' or 'empty'.
)doc") + keys +
           R"doc( : ImageSelection3 or None
    Each rule's answer; None when not asked for or when F3 holds no map.
selections : dict of str to ImageSelection3 or None
    Every rule's answer, keyed )doc" + quoted + R"doc(.
truth_in_feasible : bool or None
    With a truth: whether some positive multiple of the true map c ⊘ e lies in F3, decided
    exactly (feasible_ray_3d.h); None without a truth.
colours : int
    How many image colours went in (after the pixel rules).
pixels : dict of str to int, or None
    For an image: what the pixel rules did (counts as ImageColours.counts); else None.
)doc";
  }();
  return doc.c_str();
}

// 3-D gamut mapping on one image.
void bind_estimate3(py::module_& m) {
  auto estimate3 = py::class_<PyEstimate3>(m, "Estimate3", estimate3_doc())
      .def_property_readonly("feasible_set", &PyEstimate3::feasible_set, py::return_value_policy::reference_internal)
      .def_property_readonly("kind", [](const PyEstimate3& e) { return to_string(e.feasible.kind()); })
      .def_property_readonly("selections", [](const PyEstimate3& e) {
        py::dict d;
        for (Rule3 rule : all_rules_3) d[py::str(to_string(rule))] = py::cast(e.selections[rule]);
        return d;
      })
      .def_property_readonly("truth_in_feasible", [](const PyEstimate3& e) -> py::object {
        return e.truth_in_feasible ? py::object(py::bool_(*e.truth_in_feasible)) : py::object(py::none());
      }, "With a truth: whether some positive multiple of the true map lies in F3; else None.")
      .def_property_readonly("colours", [](const PyEstimate3& e) { return e.colours; },
                             "How many image colours went in (after the pixel rules).")
      .def_property_readonly("pixels", [](const PyEstimate3& e) -> py::object {
        return e.pixels ? pixel_counts(*e.pixels) : py::object(py::none());
      }, "For an image: what the pixel rules did (dict of counts), else None.")
      .def("__repr__", [](const PyEstimate3& e) {
        return "Estimate3(" + to_string(e.feasible.kind()) + ", " + std::to_string(e.feasible.size()) + " vertices)";
      });
  // One attribute per 3-D rule, named by its key (rule_3.h): max_volume, centroid, max_trace.
  for (Rule3 rule : all_rules_3)
    estimate3.def_property_readonly(
        to_string(rule).c_str(), [rule](const PyEstimate3& e) { return e.selections[rule]; },
        "This rule's answer (ImageSelection3), or None when not asked for or when F3 holds no map.");
}

// The 3-D canonical side prepared once, and 3-D gamut mapping on an image.
void bind_functions(py::module_& m) {
  m.def(
      "prepare_canonical_3d",
      [](py::handle canonical, const std::string& black) {
        const CanonicalBlack b = black_from(black);
        const std::vector<Colour> c = pixel_colours_of(canonical, {}, "canonical");
        Canonical3 out;
        out.colours = c.size();
        out.black = b;
        try {
          out.constraints = without_gil([&] { return std::make_shared<const CanonicalConstraints3>(c, b); });
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("canonical: ") + e.what());
        }
        return out;
      },
      py::arg("canonical"), py::kw_only(), py::arg("black") = "include",
      doc::prepare_canonical_3d.c_str());

  m.def(
      "estimate_3d",
      [](const Canonical3& canonical, py::handle image, py::handle truth, py::object rules, const std::string& centroid,
         py::handle canonical_illuminant, py::object illuminants, py::object mask, py::object black_level, py::object saturation,
         py::object dark, py::object dark_fraction, py::object bright_fraction, const std::string& pixel_rule,
         const std::string& colour_set) {
        PyEstimate3 out;
        ColourSet set = ColourSet::distinct;  // hull_3d: the colours are their hull's vertices
        const std::vector<Colour> colours = pixel_colours_of(
            image, pixel_args(mask, black_level, saturation, dark, dark_fraction, bright_fraction, pixel_rule, colour_set),
            "image", &out.pixels, &set);
        out.colours = colours.size();
        Estimate3Options o;
        o.canonical_light = positive_light(canonical_illuminant, "canonical_illuminant");
        try {
          o.route = crule_3d_route_from_string(centroid);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("centroid: ") + e.what());
        }
        o.exact_feasible_set = false;  // made on the first read of feasible_set
        if (!rules.is_none()) {
          o.rules.clear();
          for (py::handle r : rules) {
            try {
              o.rules.push_back(rule_3_from_string(py::str(r)));
            } catch (const std::invalid_argument& e) {
              throw py::value_error(std::string("rules: ") + e.what());
            }
          }
        }
        if (!truth.is_none()) o.truth = positive_light(truth, "truth");
        if (!illuminants.is_none())
          for (py::handle l : illuminants) o.illuminants.push_back(positive_light(l, "illuminants"));
        ImageColours ic;
        ic.colours = colours;
        ic.set = set == ColourSet::hull_3d ? ColourSet::hull_3d : ColourSet::distinct;
        ImageEstimate3 r;
        try {
          r = without_gil([&] { return estimate_3d(*canonical.constraints, ic, o); });
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("image: ") + e.what());
        } catch (const std::domain_error& e) {
          throw py::value_error(std::string("image: ") + e.what());
        }
        out.feasible = std::move(r.lazy_feasible);
        out.truth_in_feasible = r.truth_in_feasible;
        auto wrap = [&](std::optional<ImageSelection3>& s, Rule3 rule) -> std::optional<PySelection3> {
          if (!s) return std::nullopt;
          return PySelection3{std::move(*s), to_string(rule)};
        };
        for (Rule3 rule : all_rules_3) out.selections[rule] = wrap(r[rule], rule);
        return out;
      },
      py::arg("canonical"), py::arg("image"), py::arg("truth") = py::none(), py::kw_only(), py::arg("rules") = py::none(),
      py::arg("centroid") = "certified", py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1),
      py::arg("illuminants") = py::none(), GMCC_PIXEL_ARGS,
      doc::estimate_3d.c_str());
}

}  // namespace

void bind_photo(py::module_& m) {
  bind_canonical3(m);
  bind_image_selection3(m);
  bind_estimate3(m);
  bind_functions(m);
  bind_learners(m);
  bind_benchmark(m);
}

}  // namespace gmcc::python
