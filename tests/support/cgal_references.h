#pragma once
// Routes gmcc replaced, kept as the oracles of the tests, fuzz targets and benchmarks that compare
// the library with them (never installed: gmcc_test_support, tests/support/CMakeLists.txt).
//
// - CGAL's 2-D hull (CGAL::convex_hull_2 over the lazy exact kernel Epeck), what convex_hull was
//   before issue 13's filtered monotone chain (docs/performance-history.md, "Many-vertex canonical gamuts
//   (issue 13)"): tests/geometry/test_convex_hull_filtered.cpp and bench/bench_hull.cpp.
// - Forsyth's CRULE feasible set F3 (Forsyth 1990, §3) by the route it took before the prepared
//   form of issue 16 (docs/math.md §1b "The exact LP"): the canonical gamut's hull per call, the
//   image hull's vertices by CGAL's exact 3-D hull, then the exact max-slack LP route of
//   gmcc::geometry (internal/crule_exact.h), with none of the prepared route's filters, clipping
//   or image-hull prefilter: tests/geometry/test_feasible_set_3d_prepared.cpp, fuzz/fuzz_crule.cpp
//   and bench/bench_crule.cpp.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/convex_set.h>
#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/feasible_set_3d.h>

#include <vector>

namespace gmcc::test {

/// The convex hull of `points` by CGAL::convex_hull_2 over Epeck, in canonical ConvexSet2 form:
/// the same contract as gmcc::convex_hull.
ConvexSet2 convex_hull_cgal(const std::vector<Point2>& points);

/// F3 by the LP route over the image hull's exact vertices: the same contract as
/// gmcc::feasible_set_3d(canonical, image, black), including its exceptions
/// (std::invalid_argument on empty or negative input, UnboundedFeasibleSet).
ConvexSet3 feasible_set_3d_reference(const std::vector<Colour>& canonical, const std::vector<Colour>& image,
                                     CanonicalBlack black);

}  // namespace gmcc::test
