/// \file photo.cpp
/// gmcc._core's whole-image gamut mapping (gmcc/photo/; docs/photographs.md): 3-D canonical gamuts
/// prepared once, 3-D gamut mapping on an image with every 3-D rule, and the canonical gamuts
/// learned image by image. Conversions only; the work is the library's, with the GIL released.

#include "photo.h"

#include "interrupt.h"

#include "convert.h"
#include "pixels.h"
#include "results.h"

#include <gmcc/photo/estimate_3d.h>
#include <gmcc/photo/learn_canonical.h>
#include <gmcc/input/input_error.h>
#include <gmcc/input/truth_table.h>
#include <gmcc/validation/benchmark.h>

#include <pybind11/stl.h>

#include <deque>
#include <memory>

namespace gmcc::python {
namespace {

// A library call with the GIL released (its exceptions propagate once the GIL is back).
template <class F>
auto released(F f) {
  InterruptibleRelease nogil;
  return f();
}

// The docstring of a learner's add(): `before` (summary and the image parameter), the light and
// pixel-rule parameters both learners share, then `after`. Kept for the module's lifetime (pybind
// holds the pointer).
const std::string& learner_add_doc(const char* before, const char* after) {
  static std::deque<std::string> docs;
  docs.push_back(std::string(before) + R"doc(light : sequence of 3 numbers
    The image's measured light e, every channel > 0.
mask : numpy.ndarray of bool, shape (H, W), optional
    True for the pixels to use (default None: every pixel).
black_level : int or float, default 0
    Subtracted from every raw sample; negative results become 0.
saturation : int or float, optional
    A pixel with any raw channel >= it is dropped (default None: none is).
dark : int or float, default 0
    A pixel with a channel below it (after the black level) is dropped.
dark_fraction, bright_fraction : int, float, Fraction or str, optional
    A pixel with a channel below dark_fraction·M, or above bright_fraction·M, is dropped; M is
    the image's largest value after the black level. Default None: no such rule.
pixel_rule : {'none', 'gijsenij'}, default 'none'
    'gijsenij': Gijsenij et al. (2010)'s rule, the fractions 5/255 and 245/255.
)doc" + after);
  return docs.back();
}

// gmcc.Canonical3: a 3-D canonical gamut prepared once.
struct Canonical3 {
  std::shared_ptr<const CanonicalConstraints3> constraints;
  std::size_t colours = 0;
  CanonicalBlack black = CanonicalBlack::include;
};

// One 3-D rule's answer on an image, with its error against the truth when one was given.
struct PySelection3 {
  ImageSelection3 s;
  std::string rule;
  std::optional<double> recovery_error_deg;
};

// gmcc.Estimate3: F3 of one image and the rules' answers.
struct PyEstimate3 {
  LazyConvexSet3 feasible;                     // F3, its vertices made exact on request
  std::shared_ptr<const ConvexSet3> exact;     // F3 exactly, made on the first feasible_set read
  const ConvexSet3& feasible_set() {
    if (!exact) exact = std::make_shared<const ConvexSet3>(feasible.exact());
    return *exact;
  }
  std::optional<PySelection3> max_volume, centroid, max_trace;
  std::optional<PixelCounts> pixels;
  std::size_t colours = 0;
};

CanonicalBlack black_from(const std::string& black) {
  if (black == "include") return CanonicalBlack::include;
  if (black == "exclude") return CanonicalBlack::exclude;
  throw py::value_error("black: " + quoted_text(black) + " is not one of include, exclude");
}

// The pixel colours of `x`: an ImageColours of pixel colours, an H×W×3 image through the pixel
// rules (colour set hull-3d unless asked otherwise), or colours (n×3). Lifts are refused.
std::vector<Colour> pixel_colours_of(py::handle x, PixelArgs args, const char* what,
                                     std::optional<PixelCounts>* counts = nullptr, ColourSet* set = nullptr) {
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

#define GMCC_PIXEL_ARGS                                                                               \
  py::arg("mask") = py::none(), py::arg("black_level") = 0, py::arg("saturation") = py::none(),       \
  py::arg("dark") = 0, py::arg("dark_fraction") = py::none(), py::arg("bright_fraction") = py::none(), \
  py::arg("pixel_rule") = "none", py::arg("colour_set") = "hull-3d"

void bind_classes(py::module_& m) {
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
        return c.black == CanonicalBlack::include ? "include" : "exclude";
      })
      .def("__repr__", [](const Canonical3& c) {
        return "Canonical3(" + std::to_string(c.colours) + " colours, " + std::to_string(c.constraints->half_spaces()) +
               " half-spaces, black " + (c.black == CanonicalBlack::include ? "included" : "excluded") + ")";
      });

  py::class_<PySelection3>(m, "ImageSelection3", R"doc(One 3-D rule's answer on an image: the map, its worst case and the light it implies.

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
map : tuple of (float, float, float)
    The map (d1, d2, d3) as doubles.
exact : tuple of (Fraction, Fraction, Fraction) or None
    The exact map where it is rational, else None.
error_bound : float
    A rigorous bound on the largest component's distance from the true value.
worst_case_deg : float or None
    The largest angle from the map to a map of F3, degrees.
light : tuple of (float, float, float) or None
    The light c ⊘ d with unit length; None when a component of d is 0.
recovery_error_deg : float or None
    With a truth: the angle between ``light`` and the true light, degrees; else None.
)doc")
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
      .def_property_readonly("recovery_error_deg", [](const PySelection3& s) { return optional_double(s.recovery_error_deg); },
                             "With a truth: the angle between the light and the true light, degrees.")
      .def("__repr__", [](const PySelection3& s) {
        const auto& d = s.s.selection.estimate.map;
        return "ImageSelection3(" + s.rule + " (" + g10(d[0]) + ", " + g10(d[1]) + ", " + g10(d[2]) + "))";
      });

  py::class_<PyEstimate3>(m, "Estimate3", R"doc(3-D gamut mapping on one image: F3 and the rules' answers.

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
max_volume, centroid, max_trace : ImageSelection3 or None
    Each rule's answer; None when not asked for or when F3 holds no map.
selections : dict of str to ImageSelection3 or None
    The three, keyed 'max_volume', 'centroid', 'max_trace'.
colours : int
    How many image colours went in (after the pixel rules).
pixels : dict of str to int, or None
    For an image: what the pixel rules did (counts as ImageColours.counts); else None.
)doc")
      .def_property_readonly("feasible_set", &PyEstimate3::feasible_set, py::return_value_policy::reference_internal)
      .def_property_readonly("kind", [](const PyEstimate3& e) { return to_string(e.feasible.kind()); })
      .def_readonly("max_volume", &PyEstimate3::max_volume)
      .def_readonly("centroid", &PyEstimate3::centroid)
      .def_readonly("max_trace", &PyEstimate3::max_trace)
      .def_property_readonly("selections", [](const PyEstimate3& e) {
        py::dict d;
        d["max_volume"] = py::cast(e.max_volume);
        d["centroid"] = py::cast(e.centroid);
        d["max_trace"] = py::cast(e.max_trace);
        return d;
      })
      .def_property_readonly("colours", [](const PyEstimate3& e) { return e.colours; },
                             "How many image colours went in (after the pixel rules).")
      .def_property_readonly("pixels", [](const PyEstimate3& e) -> py::object {
        return e.pixels ? pixel_counts(*e.pixels) : py::object(py::none());
      }, "For an image: what the pixel rules did (dict of counts), else None.")
      .def("__repr__", [](const PyEstimate3& e) {
        return "Estimate3(" + to_string(e.feasible.kind()) + ", " + std::to_string(e.feasible.size()) + " vertices)";
      });
}

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
          out.constraints = released([&] { return std::make_shared<const CanonicalConstraints3>(c, b); });
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("canonical: ") + e.what());
        }
        return out;
      },
      py::arg("canonical"), py::kw_only(), py::arg("black") = "include",
      "CanonicalConstraints3 (feasible_set_3d.h). Public: gmcc.prepare_canonical_3d.");

  m.def(
      "estimate_3d",
      [](const Canonical3& canonical, py::handle image, py::handle truth, py::object rules, const std::string& centroid,
         py::handle canonical_illuminant, py::object mask, py::object black_level, py::object saturation,
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
        if (centroid != "certified" && centroid != "exact")
          throw py::value_error("centroid: " + quoted_text(centroid) + " is not one of certified, exact");
        o.route = centroid == "exact" ? Crule3dRoute::exact : Crule3dRoute::certified;
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
        std::optional<Colour> t;
        if (!truth.is_none()) t = positive_light(truth, "truth");
        ImageColours ic;
        ic.colours = colours;
        ic.set = set == ColourSet::hull_3d ? ColourSet::hull_3d : ColourSet::distinct;
        ImageEstimate3 r;
        try {
          r = released([&] { return estimate_3d(*canonical.constraints, ic, o); });
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("image: ") + e.what());
        } catch (const std::domain_error& e) {
          throw py::value_error(std::string("image: ") + e.what());
        }
        out.feasible = std::move(r.lazy_feasible);
        auto wrap = [&](std::optional<ImageSelection3>& s, Rule3 rule) -> std::optional<PySelection3> {
          if (!s) return std::nullopt;
          PySelection3 p{std::move(*s), to_string(rule), std::nullopt};
          if (t && p.s.light) p.recovery_error_deg = recovery_angular_error_deg(*p.s.light, *t);
          return p;
        };
        out.max_volume = wrap(r.max_volume, Rule3::max_volume);
        out.centroid = wrap(r.centroid, Rule3::centroid);
        out.max_trace = wrap(r.max_trace, Rule3::max_trace);
        return out;
      },
      py::arg("canonical"), py::arg("image"), py::arg("truth") = py::none(), py::kw_only(), py::arg("rules") = py::none(),
      py::arg("centroid") = "certified", py::arg("canonical_illuminant") = py::make_tuple(1, 1, 1), GMCC_PIXEL_ARGS,
      "estimate_3d (estimate_3d.h). Public: gmcc.estimate_3d.");

  py::class_<CanonicalLearner3>(m, "CanonicalLearner3", R"doc(A 3-D canonical gamut learned image by image from photographs with known lights.

Each training image's pixel colours p are divided by its light e, p ⊘ e, scaled as
``intensity`` says, and the canonical gamut is the hull of the union over the images (Forsyth
1990 §3; Gijsenij, Gevers & van de Weijer 2010 §3; learn_canonical.h, docs/photographs.md §2).
Only the running hull's vertices are kept.

Parameters
----------
intensity : {'max', 'none'}, default 'max'
    'max': each image is scaled so that its largest white-balanced channel is 1 (its brightest
    surface under the white light sets the scale); 'none': p ⊘ e as it is.

Attributes
----------
images : int
    How many images were added.
contributing : int
    Of those, how many added colours (an image with no colour, or only black, adds nothing).

Raises
------
ValueError
    An unknown ``intensity``.
)doc")
      .def(py::init([](const std::string& intensity) {
             try {
               return CanonicalLearner3(canonical_intensity_from_string(intensity));
             } catch (const std::invalid_argument& e) {
               throw py::value_error(std::string("intensity: ") + e.what());
             }
           }),
           py::kw_only(), py::arg("intensity") = "max")
      .def(
          "add",
          [](CanonicalLearner3& l, py::handle image, py::handle light, py::object mask, py::object black_level,
             py::object saturation, py::object dark, py::object dark_fraction, py::object bright_fraction,
             const std::string& pixel_rule, const std::string& colour_set) {
            const Colour e = positive_light(light, "light");
            const std::vector<Colour> c = pixel_colours_of(
                image, pixel_args(mask, black_level, saturation, dark, dark_fraction, bright_fraction, pixel_rule, colour_set),
                "image");
            released([&] {
              l.add(c, e);
              return 0;
            });
          },
          py::arg("image"), py::arg("light"), py::kw_only(), GMCC_PIXEL_ARGS, learner_add_doc(R"doc(Add one training image and its measured light to the gamut.

Its pixel colours p join the gamut as p ⊘ e, scaled (Forsyth 1990 §3; docs/photographs.md §2).

Parameters
----------
image : numpy.ndarray (H, W, 3), ImageColours, or array_like (n, 3)
    An image goes through the pixel rules below; an ImageColours must hold pixel colours;
    colours are taken as they are.
)doc", R"doc(colour_set : {'hull-3d', 'distinct'}, default 'hull-3d'
    The colours an image is reduced to ('hull' gives chromaticity lifts: refused).

Returns
-------
None

Raises
------
ValueError
    A bad image or light, chromaticity lifts, or no usable pixel.
TypeError
    An argument of the wrong type.
)doc").c_str())
      .def("gamut", [](const CanonicalLearner3& l) {
             const std::vector<Colour> g = released([&] { return l.gamut(); });
             py::list out;
             for (const Colour& c : g) out.append(colour_tuple(c));
             return out;
           }, R"doc(The learned gamut's vertices, exactly.

The hull of the union of the images' p ⊘ e (Forsyth 1990 §3; docs/photographs.md §2).

Returns
-------
list of tuple of (Fraction, Fraction, Fraction)
    The vertices, sorted; empty before any colour was added.
)doc")
      .def("gamut_float", [](const CanonicalLearner3& l) { return colours_array(l.gamut()); },
           R"doc(The learned gamut's vertices as the nearest doubles.

As gamut() (Forsyth 1990 §3; docs/photographs.md §2), in floating point.

Returns
-------
numpy.ndarray of float64, shape (n, 3)
    The vertices, in gamut()'s order.
)doc")
      .def("prepare", [](const CanonicalLearner3& l, const std::string& black) {
             Canonical3 out;
             out.black = black_from(black);
             const std::vector<Colour> g = l.gamut();
             if (g.empty()) throw py::value_error("prepare: no colour has been added");
             out.colours = g.size();
             out.constraints = released([&] { return std::make_shared<const CanonicalConstraints3>(g, out.black); });
             return out;
           }, py::kw_only(), py::arg("black") = "include", R"doc(The learned gamut prepared for estimate_3d.

Its exact half-spaces (Forsyth 1990 §3; feasible_set_3d.h), as prepare_canonical_3d.

Parameters
----------
black : {'include', 'exclude'}, default 'include'
    Whether black (0, 0, 0) joins the hull (with it F3 is never empty).

Returns
-------
Canonical3
    G_c3, immutable and thread-safe.

Raises
------
ValueError
    No colour has been added, or an unknown ``black``.
)doc")
      .def_property_readonly("images", &CanonicalLearner3::images)
      .def_property_readonly("contributing", &CanonicalLearner3::contributing);

  py::class_<CanonicalLearner2>(m, "CanonicalLearner2", R"doc(A 2-D (perspective) canonical gamut learned image by image.

The hull of the perspective chromaticities of each training image's colours divided by its
light (Finlayson & Hordley 1999 eq. 10; Finlayson 1996; learn_canonical.h,
docs/photographs.md §2); chromaticities need no intensity scaling. Takes no parameters.

Attributes
----------
images : int
    How many images were added.
)doc")
      .def(py::init<>())
      .def(
          "add",
          [](CanonicalLearner2& l, py::handle image, py::handle light, py::object mask, py::object black_level,
             py::object saturation, py::object dark, py::object dark_fraction, py::object bright_fraction,
             const std::string& pixel_rule) {
            const Colour e = positive_light(light, "light");
            std::vector<Colour> c;
            if (py::isinstance<PyImageColours>(image)) {
              c = image.cast<const PyImageColours&>().colours;  // lifts or pixel colours: both have chromaticities
            } else if (is_image(image)) {
              c = image_colours_of(image, pixel_args(mask, black_level, saturation, dark, dark_fraction, bright_fraction,
                                                     pixel_rule, "hull")).colours;
            } else {
              c = colours_from(image, "image");
            }
            released([&] {
              l.add(c, e);
              return 0;
            });
          },
          py::arg("image"), py::arg("light"), py::kw_only(), py::arg("mask") = py::none(), py::arg("black_level") = 0,
          py::arg("saturation") = py::none(), py::arg("dark") = 0, py::arg("dark_fraction") = py::none(),
          py::arg("bright_fraction") = py::none(), py::arg("pixel_rule") = "none",
          learner_add_doc(R"doc(Add one training image and its measured light to the 2-D gamut.

Its chromaticities, divided by the light, join the hull (Finlayson & Hordley 1999 eq. 10).

Parameters
----------
image : numpy.ndarray (H, W, 3), ImageColours, or array_like (n, 3)
    An image goes through the pixel rules below (colour set 'hull'); an ImageColours (lifts or
    pixel colours) and colours are taken as they are.
)doc", R"doc(
Returns
-------
None

Raises
------
ValueError
    A bad image or light.
TypeError
    An argument of the wrong type.
)doc").c_str())
      .def("gamut", [](const CanonicalLearner2& l) {
             py::list out;
             for (const Point2& p : l.gamut()) out.append(py::make_tuple(to_fraction(p.x), to_fraction(p.y), 1));
             return out;
           }, R"doc(The learned gamut as chromaticity lifts, a canonical gamut for prepare_canonical.

The hull's vertices (x, y) as colours (x, y, 1), whose perspective chromaticities they are
(Finlayson & Hordley 1999 eq. 10).

Returns
-------
list of tuple of (Fraction, Fraction, int)
    The lifts (x, y, 1), exact, counter-clockwise.
)doc")
      .def_property_readonly("images", &CanonicalLearner2::images);
}

py::object optional_light(const std::optional<std::array<double, 3>>& e) {
  return e ? py::object(py::make_tuple((*e)[0], (*e)[1], (*e)[2])) : py::object(py::none());
}

py::dict summary_dict(const BenchmarkSummary& s) {
  py::dict d;
  d["method"] = s.method;
  d["images"] = s.images;
  d["answered"] = s.answered;
  const bool any = s.errors.n > 0;
  auto stat = [&](double x) { return any ? py::object(py::float_(x)) : py::object(py::none()); };
  d["mean_deg"] = stat(s.errors.mean);
  d["median_deg"] = stat(s.errors.median);
  d["trimean_deg"] = stat(s.errors.trimean);
  d["best25_deg"] = stat(s.errors.best25);
  d["worst25_deg"] = stat(s.errors.worst25);
  d["p95_deg"] = stat(s.errors.p95);
  d["max_deg"] = stat(s.errors.max);
  const bool gamut = is_gamut_method(s.method);
  d["empty"] = gamut ? py::object(py::int_(s.empty)) : py::object(py::none());
  d["truth_in_feasible"] = gamut ? py::object(py::float_(double(s.truth_in_feasible) / double(s.images)))
                                 : py::object(py::none());
  d["worst_case_covers"] = optional_double(s.worst_case_covers);
  d["worst_case_correlation"] = optional_double(s.worst_case_correlation);
  return d;
}

void bind_benchmark(py::module_& m) {
  m.def(
      "benchmark",
      [](const std::string& images, const std::string& truths, py::object folds, py::object folds_file,
         py::object methods, const std::string& intensity, const std::string& black, unsigned threads,
         py::object black_level, py::object saturation, py::object dark, py::object dark_fraction,
         py::object bright_fraction, const std::string& pixel_rule, double edge_sigma) {
        BenchmarkOptions o;
        o.edge_sigma = edge_sigma;
        std::vector<BenchmarkImage> dataset;
        try {
          const std::vector<TruthRow> rows = read_truth_table(truths);
          if (!folds_file.is_none()) {
            if (!folds.is_none()) throw py::value_error("folds, folds_file: give one, not both");
            const std::string path = py::str(folds_file);
            const std::map<std::string, int> f = read_folds_file(path);
            dataset = benchmark_dataset(images, rows, &f, path, 0);
          } else {
            if (folds.is_none()) throw py::value_error("folds: give folds=K or folds_file=path");
            dataset = benchmark_dataset(images, rows, nullptr, "", integer_in<int>(folds, "folds", 2, 1000000));
          }
        } catch (const InputError& e) {
          throw py::value_error(e.what());
        }
        if (!methods.is_none()) {
          o.methods.clear();
          for (py::handle x : methods) {
            const std::string name = py::str(x);
            const auto& all = benchmark_methods();
            if (std::find(all.begin(), all.end(), name) == all.end())
              throw py::value_error("methods: " + quoted_text(name) + " is not a benchmark method");
            o.methods.push_back(name);
          }
        }
        try {
          o.intensity = canonical_intensity_from_string(intensity);
        } catch (const std::invalid_argument& e) {
          throw py::value_error(std::string("intensity: ") + e.what());
        }
        o.black = black_from(black);
        o.threads = threads;
        // The run's pixel rules, through the same checks as images (a 1×1 image is not needed:
        // the integer route's checks are the arguments').
        // Absent: 0 for PNG and TIFF, a raw file's own black levels (camera_image.h).
        o.black_level_given = !black_level.is_none();
        if (o.black_level_given) o.pixels.black_level = integer_in<std::uint32_t>(black_level, "black_level", 0, 65535);
        if (!saturation.is_none()) o.pixels.saturation = integer_in<std::uint32_t>(saturation, "saturation", 1, 65536);
        if (const auto d = integer_in<std::uint32_t>(dark, "dark", 0, 65535)) o.pixels.dark_below = d;
        PixelArgs args;
        args.dark_fraction = dark_fraction;
        args.bright_fraction = bright_fraction;
        args.pixel_rule = pixel_rule;
        pixel_fractions(args, o.pixels.dark_below_fraction, o.pixels.bright_above_fraction);
        BenchmarkResult r;
        try {
          InterruptibleRelease nogil;
          r = run_benchmark(dataset, o);
        } catch (const InputError& e) {
          throw py::value_error(e.what());
        } catch (const std::invalid_argument& e) {
          throw py::value_error(e.what());
        }
        py::list summaries, records;
        for (const BenchmarkSummary& s : r.summaries) summaries.append(summary_dict(s));
        for (const BenchmarkRecord& rec : r.records) {
          py::dict d;
          d["image"] = dataset[rec.image].name;
          d["fold"] = dataset[rec.image].fold;
          d["method"] = rec.method;
          d["light"] = optional_light(rec.light);
          d["error_deg"] = optional_double(rec.error_deg);
          d["answered"] = rec.answered;
          d["fallback"] = rec.fallback.empty() ? py::object(py::none()) : py::object(py::str(rec.fallback));
          d["feasible_kind"] = rec.feasible_kind.empty() ? py::object(py::none()) : py::object(py::str(rec.feasible_kind));
          d["feasible_vertices"] = rec.feasible_kind.empty() ? py::object(py::none()) : py::object(py::int_(rec.feasible_vertices));
          d["truth_in_feasible"] =
              rec.truth_in_feasible ? py::object(py::bool_(*rec.truth_in_feasible)) : py::object(py::none());
          d["worst_case_deg"] = optional_double(rec.worst_case_deg);
          records.append(d);
        }
        return py::make_tuple(summaries, records);
      },
      py::arg("images"), py::arg("truths"), py::kw_only(), py::arg("folds") = py::none(),
      py::arg("folds_file") = py::none(), py::arg("methods") = py::none(), py::arg("intensity") = "max",
      py::arg("black") = "include", py::arg("threads") = 0, py::arg("black_level") = py::none(),
      py::arg("saturation") = py::none(), py::arg("dark") = 0, py::arg("dark_fraction") = py::none(),
      py::arg("bright_fraction") = py::none(), py::arg("pixel_rule") = "none", py::arg("edge_sigma") = 1.0,
      "run_benchmark (benchmark.h). Public: gmcc.benchmark.");
}

}  // namespace

void bind_photo(py::module_& m) {
  bind_classes(m);
  bind_functions(m);
  bind_benchmark(m);
}

}  // namespace gmcc::python
