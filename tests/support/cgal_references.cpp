// The routes gmcc replaced, kept as oracles (cgal_references.h): the one CGAL translation unit of
// gmcc_test_support.
#include "cgal_references.h"

#include <gmcc/geometry/point3_arithmetic.h>

#include "internal/crule_exact.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <iterator>
#include <type_traits>

namespace gmcc::test {
namespace {
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
// With CGAL::CGAL's -DCGAL_USE_GMPXX=1 the exact type is mpq_class (docs/derivations.md §4.1), so
// values cross this boundary without conversion.
static_assert(std::is_same<Kernel::FT::Exact_type, mpq_class>::value,
              "gmcc expects CGAL built with CGAL_USE_GMPXX (link CGAL::CGAL)");

std::vector<Point3> points(const std::vector<Colour>& colours) {
  std::vector<Point3> p;
  p.reserve(colours.size());
  for (const Colour& c : colours) p.push_back({c.r, c.g, c.b});
  return p;
}

// The vertices of conv(pts) by CGAL::convex_hull_3 over Epeck, sorted; all of `pts` when they are
// flat. \pre pts sorted, without repeats.
std::vector<Point3> exact_hull_vertices(const std::vector<Point3>& pts) {
  if (internal::affine_dimension(pts) < 3) return pts;
  std::vector<Kernel::Point_3> in;
  in.reserve(pts.size());
  for (const Point3& p : pts) in.emplace_back(Kernel::FT(p.x), Kernel::FT(p.y), Kernel::FT(p.z));
  CGAL::Polyhedron_3<Kernel> poly;
  CGAL::convex_hull_3(in.begin(), in.end(), poly);
  std::vector<Point3> out;
  for (auto v = poly.vertices_begin(); v != poly.vertices_end(); ++v)
    out.push_back({CGAL::exact(v->point().x()), CGAL::exact(v->point().y()), CGAL::exact(v->point().z())});
  return internal::sorted_unique(out);
}
}  // namespace

ConvexSet2 convex_hull_cgal(const std::vector<Point2>& points) {
  std::vector<Kernel::Point_2> in;
  in.reserve(points.size());
  for (const Point2& p : points) in.emplace_back(Kernel::FT(p.x), Kernel::FT(p.y));
  std::vector<Kernel::Point_2> hull;
  // Extreme points only (collinear boundary points dropped), counter-clockwise.
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(hull));
  std::vector<Point2> cycle;
  cycle.reserve(hull.size());
  for (const Kernel::Point_2& p : hull) cycle.push_back({CGAL::exact(p.x()), CGAL::exact(p.y())});
  return canonical_convex_set(std::move(cycle));
}

ConvexSet3 feasible_set_3d_reference(const std::vector<Colour>& canonical_colours,
                                     const std::vector<Colour>& image_colours, CanonicalBlack black) {
  internal::check_colours(canonical_colours, "canonical");
  std::vector<Point3> canonical = points(canonical_colours);
  if (black == CanonicalBlack::include) canonical.push_back({0, 0, 0});
  canonical = internal::sorted_unique(canonical);
  internal::check_colours(image_colours, "image");
  const std::vector<Point3> image = exact_hull_vertices(internal::sorted_unique(points(image_colours)));
  Point3 X{0, 0, 0};  // the largest canonical channels
  for (const Point3& c : canonical)
    for (int k = 0; k < 3; ++k) coord(X, k) = std::max(coord(X, k), coord(c, k));
  const std::vector<internal::HalfSpace3> half_spaces = internal::hull_half_spaces_3(canonical);
  return internal::feasible_set_3d_lp({internal::LpPart{&half_spaces, &X, &image}});
}

}  // namespace gmcc::test
