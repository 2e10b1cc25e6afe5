#pragma once
/// \file results.h
/// The library's result types as Python classes (docs/python.md "Results"): exact numbers are
/// converted to fractions.Fraction when a property is read, not before, so that a call costs
/// what the C++ call costs.

#include "convert.h"

#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/select_scene.h>
#include <gmcc/photo/image_pixels.h>

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
  ColourSet set = ColourSet::hull;  ///< pixel colours, or the chromaticity lifts of the 2-D hull
  PixelCounts counts;
};

/// What the pixel rules did, as a dict of counts (pixels, masked, saturated, dark, bright, kept,
/// colours, hull_vertices, no_chromaticity).
py::object pixel_counts(const PixelCounts& c);

/// A double with 10 significant digits, for __repr__.
std::string g10(double x);
/// A float, or None when absent.
py::object optional_double(const std::optional<double>& x);

/// Every rule's Selection keyed by its name (rule.h: 'max_area', 'mean_2d', 'mean_3d'); None
/// where absent.
py::dict selections_dict(const Selections& selections);
/// A colour or a 3-D point as a tuple of three Fractions.
///@{
py::object colour_tuple(const Colour& c);
py::object point3_tuple(const Point3& p);
///@}

/// ValueError unless `c` holds pixel colours (not chromaticity lifts); `what` names the use.
void require_pixel_colours(const PyImageColours& c, const char* what);

/// Colours from `x`: an ImageColours passes its pixel colours (chromaticity lifts are refused,
/// not taken as colours); anything else is read by colours_from. \throws ValueError, TypeError.
std::vector<Colour> colours_or_pixel_colours(py::handle x, const char* what);

/// Exact points as an (n, 2) array of the nearest doubles.
py::array_t<double> points_float(const std::vector<Point2>& points);

/// Exact colours as an (n, 3) array of the nearest doubles.
py::array_t<double> colours_array(const std::vector<Colour>& colours);

/// A ConvexSet's and a MapEstimate's text in __repr__ ("ConvexSet(polygon, 4 vertices, ...)",
/// "max_area (x, y) exact").
///@{
std::string convex_set_repr(const ConvexSet2& s);
std::string estimate_repr(const MapEstimate& e);
///@}

/// The Python classes of every result type, added to `m` in this order: the 2-D map classes
/// (results.cpp), a scene's reports and results (scene_results.cpp), CRULE's 3-D classes
/// (crule_results.cpp), ErrorStatistics (results.cpp).
void bind_results(py::module_& m);
/// Truth, RuleErrors, Constraint and Recovery (scene_results.cpp).
void bind_scene_report_classes(py::module_& m);
/// Canonical, SceneResult and ImageColours (scene_results.cpp).
void bind_scene_classes(py::module_& m);
/// ConvexSet3, Selection3 and Crule3d (crule_results.cpp).
void bind_crule_classes(py::module_& m);

}  // namespace gmcc::python
