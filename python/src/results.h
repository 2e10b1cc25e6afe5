#pragma once
/// \file results.h
/// The library's result types as Python classes (docs/python.md "Results"): exact numbers are
/// converted to fractions.Fraction when a property is read, not before, so that a call costs
/// what the C++ call costs.

#include "convert.h"

#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/select_scene.h>
#include <gmcc/input/image_pixels.h>

#include <memory>

namespace gmcc::python {

/// gmcc.Canonical: a prepared canonical side, shared by the results made from it.
using CanonicalPtr = std::shared_ptr<const PreparedCanonical>;

/// gmcc.SceneResult: select_scene's result with the canonical side it was run against.
struct Scene {
  CanonicalPtr canonical;
  SceneResult result;
  std::optional<PixelCounts> pixels;  ///< for images: what the pixel rules did
};

/// gmcc.ImageColours: the colours the pixel rules kept, with their counts.
struct PyImageColours {
  std::vector<Colour> colours;
  PixelCounts counts;
};

/// The Python classes of every result type, added to `m`.
void bind_results(py::module_& m);

}  // namespace gmcc::python
