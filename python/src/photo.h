#pragma once
/// \file photo.h
/// gmcc._core's whole-image gamut mapping (photo.cpp).

#include <pybind11/pybind11.h>

namespace gmcc::python {

/// Adds Canonical3, Estimate3, ImageSelection3, CanonicalLearner2/3, prepare_canonical_3d and
/// estimate_3d to `m`.
void bind_photo(pybind11::module_& m);

}  // namespace gmcc::python
