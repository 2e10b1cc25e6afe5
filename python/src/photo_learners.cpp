/// \file photo_learners.cpp
/// gmcc._core's canonical gamuts learned image by image from photographs with known lights
/// (learn_canonical.h; docs/photographs.md §2): CanonicalLearner3 and CanonicalLearner2.

#include "docstrings.h"
#include "photo_bindings.h"

#include <gmcc/photo/learn_canonical.h>

#include <pybind11/stl.h>

#include <memory>
#include <mutex>

namespace gmcc::python {
namespace {

// CanonicalLearner3.prepare's docstring: its summary, then prepare_canonical_3d's black and result.
const std::string learner_prepare_doc = std::string(R"doc(The learned gamut prepared for estimate_3d.

Its exact half-spaces (Forsyth 1990 §3; feasible_set_3d.h), as prepare_canonical_3d.

Parameters
----------
)doc") + doc::black_3d_returns + R"doc(    No colour has been added, or an unknown ``black``.
)doc";

}  // namespace
namespace {

// A learner with its own mutex: add() and gamut() run with the GIL released, so Python threads
// sharing one learner would otherwise change its hull at once (a double free, issue 42). Every
// method takes the mutex, with the GIL released while it waits and works, so threads on different
// learners still run in parallel.
template <class Learner>
struct Locked : Learner {
  using Learner::Learner;
  mutable std::mutex mutex;
  // f(learner) under the mutex, without the GIL.
  template <class F>
  auto with(F f) const {
    return without_gil([&] {
      std::lock_guard<std::mutex> lock(mutex);
      return f(static_cast<const Learner&>(*this));
    });
  }
  template <class F>
  auto with(F f) {
    return without_gil([&] {
      std::lock_guard<std::mutex> lock(mutex);
      return f(static_cast<Learner&>(*this));
    });
  }
};
using Learner3 = Locked<CanonicalLearner3>;
using Learner2 = Locked<CanonicalLearner2>;

// CanonicalLearner3: its constructor and add().
py::class_<Learner3> bind_learner3(py::module_& m) {
  py::class_<Learner3> learner(m, "CanonicalLearner3", R"doc(A 3-D canonical gamut learned image by image from photographs with known lights.

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
)doc");
  learner.def(py::init([](const std::string& intensity) {
             try {
               return std::make_unique<Learner3>(canonical_intensity_from_string(intensity));
             } catch (const std::invalid_argument& e) {
               throw py::value_error(std::string("intensity: ") + e.what());
             }
           }),
           py::kw_only(), py::arg("intensity") = "max")
      .def(
          "add",
          [](Learner3& l, py::handle image, py::handle light, py::object mask, py::object black_level,
             py::object saturation, py::object dark, py::object dark_fraction, py::object bright_fraction,
             const std::string& pixel_rule, const std::string& colour_set) {
            const Colour e = positive_light(light, "light");
            const std::vector<Colour> c = pixel_colours_of(
                image, pixel_args(mask, black_level, saturation, dark, dark_fraction, bright_fraction, pixel_rule, colour_set),
                "image");
            l.with([&](auto& learner) {
              learner.add(c, e);
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
)doc", "A bad image or light, chromaticity lifts, or no usable pixel.").c_str());
  return learner;
}

// CanonicalLearner3's gamut, exact and in floating point, prepared, and its counts.
void bind_learner3_results(py::class_<Learner3>& learner) {
  learner.def("gamut", [](const Learner3& l) {
             const std::vector<Colour> g = l.with([](const CanonicalLearner3& x) { return x.gamut(); });
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
      .def("gamut_float", [](const Learner3& l) { return colours_array(l.with([](const CanonicalLearner3& x) { return x.gamut(); })); },
           R"doc(The learned gamut's vertices as the nearest doubles.

As gamut() (Forsyth 1990 §3; docs/photographs.md §2), in floating point.

Returns
-------
numpy.ndarray of float64, shape (n, 3)
    The vertices, in gamut()'s order.
)doc")
      .def("prepare", [](const Learner3& l, const std::string& black) {
             Canonical3 out;
             out.black = black_from(black);
             const std::vector<Colour> g = l.with([](const CanonicalLearner3& x) { return x.gamut(); });
             if (g.empty()) throw py::value_error("prepare: no colour has been added");
             out.colours = g.size();
             out.constraints = without_gil([&] { return std::make_shared<const CanonicalConstraints3>(g, out.black); });
             return out;
           }, py::kw_only(), py::arg("black") = "include", learner_prepare_doc.c_str())
      .def_property_readonly("images", [](const Learner3& l) { return l.with([](const CanonicalLearner3& x) { return x.images(); }); })
      .def_property_readonly("contributing", [](const Learner3& l) { return l.with([](const CanonicalLearner3& x) { return x.contributing(); }); });
}

// CanonicalLearner2.
void bind_learner2(py::module_& m) {
  py::class_<Learner2>(m, "CanonicalLearner2", R"doc(A 2-D (perspective) canonical gamut learned image by image.

The hull of the perspective chromaticities of each training image's colours divided by its
light (Finlayson & Hordley 1999 eq. 10; Finlayson 1996; learn_canonical.h,
docs/photographs.md §2); chromaticities need no intensity scaling. Takes no parameters.

Attributes
----------
images : int
    How many images were added.
)doc")
      .def(py::init([] { return std::make_unique<Learner2>(); }))
      .def(
          "add",
          [](Learner2& l, py::handle image, py::handle light, py::object mask, py::object black_level,
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
            l.with([&](auto& learner) {
              learner.add(c, e);
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
)doc", "", "A bad image or light.").c_str())
      .def("gamut", [](const Learner2& l) {
             py::list out;
             for (const Point2& p : l.with([](const CanonicalLearner2& x) { return x.gamut(); })) out.append(py::make_tuple(to_fraction(p.x), to_fraction(p.y), 1));
             return out;
           }, R"doc(The learned gamut as chromaticity lifts, a canonical gamut for prepare_canonical.

The hull's vertices (x, y) as colours (x, y, 1), whose perspective chromaticities they are
(Finlayson & Hordley 1999 eq. 10).

Returns
-------
list of tuple of (Fraction, Fraction, int)
    The lifts (x, y, 1), exact, counter-clockwise.
)doc")
      .def_property_readonly("images", [](const Learner2& l) { return l.with([](const CanonicalLearner2& x) { return x.images(); }); });
}

}  // namespace

void bind_learners(py::module_& m) {
  py::class_<Learner3> learner3 = bind_learner3(m);
  bind_learner3_results(learner3);
  bind_learner2(m);
}

}  // namespace gmcc::python
