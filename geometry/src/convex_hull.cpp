// The library's only CGAL translation unit: keep heavy includes here (MATH §3e).
#include <gmcc/geometry/convex_hull.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <type_traits>

namespace gmcc {
namespace {
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using KPoint = Kernel::Point_2;
// With CGAL::CGAL's -DCGAL_USE_GMPXX=1 the exact type is mpq_class (MATH §3d), so values cross
// this boundary without conversion.
static_assert(std::is_same<Kernel::FT::Exact_type, mpq_class>::value,
              "gmcc expects CGAL built with CGAL_USE_GMPXX (link CGAL::CGAL)");
}  // namespace

ConvexSet2 convex_hull(const std::vector<Point2>& points) {
  std::vector<KPoint> in;
  in.reserve(points.size());
  for (const Point2& p : points) in.emplace_back(Kernel::FT(p.x), Kernel::FT(p.y));
  std::vector<KPoint> hull;
  // Extreme points only (collinear boundary points dropped), counter-clockwise.
  CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(hull));
  std::vector<Point2> cycle;
  cycle.reserve(hull.size());
  for (const KPoint& p : hull) cycle.push_back({CGAL::exact(p.x()), CGAL::exact(p.y())});
  return canonical_convex_set(std::move(cycle));
}

}  // namespace gmcc
