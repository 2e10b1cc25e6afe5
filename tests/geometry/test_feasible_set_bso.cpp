// Oracle: CGAL's Boolean set operations compute ⋂ (G_c ⊘ q) by an independent route.
// They are regularised (closure of interior), so lower-dimensional results come back empty:
// for those cases only the kind is compared (docs/derivations.md §4.2). This is the tests' one
// CGAL TU.
#include "../test_support.h"

#include <gmcc/geometry/feasible_set.h>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using gmcc::test::Rng;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

namespace {
// ⋂ (G ⊘ q) by CGAL::intersection, pairwise; nullopt when it is empty (or lower-dimensional).
std::optional<ConvexSet2> bso_feasible_set(const ConvexSet2& G, const std::vector<Point2>& image) {
  std::optional<Polygon> acc;
  for (const Point2& q : image) {
    Polygon scaled;
    for (const Point2& v : G.vertices)
      scaled.push_back(Kernel::Point_2(Kernel::FT(Rational(v.x / q.x)), Kernel::FT(Rational(v.y / q.y))));
    if (!acc) {
      acc = scaled;
      continue;
    }
    std::vector<PolygonWithHoles> out;
    CGAL::intersection(*acc, scaled, std::back_inserter(out));
    if (out.empty()) return std::nullopt;
    BOOST_REQUIRE(out.size() == 1u);  // convex ∩ convex is connected
    acc = out.front().outer_boundary();
  }
  std::vector<Point2> cycle;
  for (auto it = acc->vertices_begin(); it != acc->vertices_end(); ++it)
    cycle.push_back({CGAL::exact(it->x()), CGAL::exact(it->y())});
  return canonical_convex_set(cycle);
}
}  // namespace

BOOST_AUTO_TEST_SUITE(feasible_set_vs_boolean_set_operations)

BOOST_AUTO_TEST_CASE(clipping_equals_cgal_bso_exactly) {
  Rng rng(5284);
  int compared = 0, degenerate = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const auto canonical = test::random_points(rng, 4 + trial % 20, 1, 4, 5);
    const ConvexSet2 G = convex_hull(canonical);
    if (G.kind != ConvexKind::polygon) continue;
    const Point2 d = test::random_point(rng, 3, 10, 5);
    std::vector<Point2> image;
    for (int i = 0; i < 1 + trial % 7; ++i) {
      image.push_back(test::divided(canonical[static_cast<std::size_t>(i * 7 + trial) % canonical.size()], d));
    }
    if (trial % 4 == 0) image.push_back(test::random_points(rng, 1, 1, 2, 4)[0]);
    const ConvexSet2 F = feasible_set(G, image);
    const auto oracle = bso_feasible_set(G, convex_hull(image).vertices);
    if (oracle) {
      BOOST_TEST(F == *oracle);
      BOOST_TEST(area(F) == area(*oracle));
      ++compared;
    } else {
      BOOST_TEST(F.kind != ConvexKind::polygon);  // empty, or degenerate and regularised away
      degenerate += F.kind != ConvexKind::empty;
    }
  }
  BOOST_TEST(compared > 30);
}

BOOST_AUTO_TEST_CASE(degenerate_results_that_bso_regularises_away) {
  // G ⊘ (1,1) and G ⊘ (2,1) for the unit square [1,2]² touch along the segment m1 = 1.
  const ConvexSet2 G = convex_hull({{1, 1}, {2, 1}, {2, 2}, {1, 2}});
  const std::vector<Point2> image{{1, 1}, {2, 1}};
  BOOST_TEST(!bso_feasible_set(G, image).has_value());
  const ConvexSet2 F = feasible_set(G, image);
  BOOST_TEST(F.kind == ConvexKind::segment);
  BOOST_TEST((F.vertices == std::vector<Point2>{{1, 1}, {1, 2}}));
}

BOOST_AUTO_TEST_SUITE_END()
