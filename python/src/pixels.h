#pragma once
/// \file pixels.h
/// Images from Python: an H×W×3 numpy array (unsigned integers, or floats whose values are exact
/// rationals) through the library's pixel rules (gmcc/photo/image_pixels.h; docs/conventions.md
/// §8), with the Python argument names in every message.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "results.h"

#include <optional>

namespace gmcc::python {

namespace py = pybind11;

/// The pixel-rule arguments as Python passes them (checked when applied).
struct PixelArgs {
  py::object mask = py::none();          ///< None or a bool array (H, W): False excludes
  py::object black_level = py::int_(0);  ///< subtracted from every channel
  py::object saturation = py::none();    ///< None or a threshold on raw channels
  py::object dark = py::int_(0);         ///< drop pixels with a channel below this (after black)
  py::object dark_fraction = py::none();    ///< None or a fraction of M
  py::object bright_fraction = py::none();  ///< None or a fraction of M
  std::string pixel_rule = "none";          ///< none | gijsenij
  std::string colour_set = "hull";          ///< hull | distinct | hull-3d
  py::object prefilter = py::int_(0);       ///< Gaussian pre-filter sigma, 0 for none
  /// True when every argument but colour_set has its default (no pixel rule asked for).
  bool plain() const;
};

/// The colours of `image` under `args`, with the counts. \throws TypeError, ValueError.
PyImageColours image_colours_of(py::handle image, const PixelArgs& args);

/// Step 4's fractions from `args` (dark_fraction, bright_fraction, pixel_rule). \throws ValueError.
void pixel_fractions(const PixelArgs& args, std::optional<Rational>& dark, std::optional<Rational>& bright);

/// True when `x` is a numpy array with three dimensions (an image, not a list of colours).
bool is_image(py::handle x);

/// The `prefilter` argument: a sigma from 0 to 64 pixels. \throws ValueError.
double sigma_from(py::handle x);

/// The `colour_set` argument as the library's ColourSet. \throws ValueError.
ColourSet colour_set_from(const std::string& name);

}  // namespace gmcc::python
