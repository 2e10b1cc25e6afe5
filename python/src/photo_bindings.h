#pragma once
/// \file photo_bindings.h
/// What gmcc._core's whole-image bindings share (photo.cpp, photo_learners.cpp,
/// photo_benchmark.cpp): the 3-D result holders, the pixel arguments and the GIL's release.

#include "convert.h"
#include "python_interrupt.h"
#include "pixels.h"
#include "results.h"

#include <gmcc/photo/estimate_3d.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gmcc::python {

/// A library call with the GIL released (its exceptions propagate once the GIL is back).
template <class F>
auto without_gil(F f) {
  InterruptibleRelease nogil;
  return f();
}

/// The docstring of a learner's add(): `before` (summary and the image parameter), the light and
/// pixel-rule parameters both learners share, `more_parameters`, then the returns (None) and the
/// errors both share, `value_error` the ValueError's cases. Kept for the module's lifetime (pybind
/// holds the pointer).
const std::string& learner_add_doc(const char* before, const char* more_parameters, const char* value_error);

// gmcc.Canonical3: a 3-D canonical gamut prepared once.
struct Canonical3 {
  std::shared_ptr<const CanonicalConstraints3> constraints;
  std::size_t colours = 0;
  CanonicalBlack black = CanonicalBlack::include;
};

// One 3-D rule's answer on an image, with its error against the truth when one was given.
struct PySelection3 {
  ImageSelection3 s;  // with its errors against a truth (estimate_3d.h)
  std::string rule;
};

// gmcc.Estimate3: F3 of one image and the rules' answers.
struct PyEstimate3 {
  LazyConvexSet3 feasible;                     // F3, its vertices made exact on request
  std::shared_ptr<const ConvexSet3> exact;     // F3 exactly, made on the first feasible_set read
  const ConvexSet3& feasible_set() {
    if (!exact) exact = std::make_shared<const ConvexSet3>(feasible.exact());
    return *exact;
  }
  PerRule3<std::optional<PySelection3>> selections;  // by rule (rule_3.h)
  std::optional<bool> truth_in_feasible;  // with a truth (ImageEstimate3::truth_in_feasible)
  std::optional<PixelCounts> pixels;
  std::size_t colours = 0;
};

/// `black` ('include' or 'exclude') as CanonicalBlack. \throws ValueError.
CanonicalBlack black_from(const std::string& black);

/// The pixel colours of `x`: an ImageColours of pixel colours, an H×W×3 image through the pixel
/// rules (colour set hull-3d unless asked otherwise), or colours (n×3). Lifts are refused.
std::vector<Colour> pixel_colours_of(py::handle x, PixelArgs args, const char* what,
                                     std::optional<PixelCounts>* counts = nullptr, ColourSet* set = nullptr);

/// A light with every channel > 0. \throws ValueError naming `what`.
Colour positive_light(py::handle x, const char* what);

/// The pixel rules' Python arguments as PixelArgs.
PixelArgs pixel_args(py::object mask, py::object black_level, py::object saturation, py::object dark,
                     py::object dark_fraction, py::object bright_fraction, std::string pixel_rule,
                     std::string colour_set);

/// The pixel rules' keyword arguments with their defaults (colour set hull-3d).
#define GMCC_PIXEL_ARGS                                                                               \
  py::arg("mask") = py::none(), py::arg("black_level") = 0, py::arg("saturation") = py::none(),       \
  py::arg("dark") = 0, py::arg("dark_fraction") = py::none(), py::arg("bright_fraction") = py::none(), \
  py::arg("pixel_rule") = "none", py::arg("colour_set") = "hull-3d"

/// CanonicalLearner3 and CanonicalLearner2 (photo_learners.cpp).
void bind_learners(py::module_& m);
/// benchmark (photo_benchmark.cpp).
void bind_benchmark(py::module_& m);

}  // namespace gmcc::python
