#pragma once
// What the CRULE route tests share: two 3-D map estimates equal member by member (map, enclosure,
// bound, exact map, edge root), as two routes must give bit for bit, and the worst case's oracle.

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/selection/crule_3d.h>
#include <gmcc/selection/map_estimate_3.h>

#include <boost/test/unit_test.hpp>

namespace gmcc::test {

inline void same_estimate(const MapEstimate3& a, const MapEstimate3& b) {
  BOOST_TEST(a.rule == b.rule);
  BOOST_TEST(a.method == b.method);
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(a.map[k] == b.map[k]);
    BOOST_TEST(a.enclosure[k][0] == b.enclosure[k][0]);
    BOOST_TEST(a.enclosure[k][1] == b.enclosure[k][1]);
  }
  BOOST_TEST(a.error_bound == b.error_bound);
  BOOST_TEST(a.exact.has_value() == b.exact.has_value());
  if (a.exact && b.exact) BOOST_TEST((*a.exact == *b.exact));
  BOOST_TEST(a.edge_root.has_value() == b.edge_root.has_value());
  if (a.edge_root && b.edge_root) {
    BOOST_TEST((a.edge_root->from == b.edge_root->from));
    BOOST_TEST((a.edge_root->to == b.edge_root->to));
    BOOST_TEST(a.edge_root->sign == b.edge_root->sign);
  }
}

// The oracle of the 3-D worst case: the first non-zero vertex of least cos²(m, v) =
// (m·v)²/(|m|²|v|²), in ℚ, and its angle to m.
inline double worst_case_oracle(const ConvexSet3& F, const Point3& m) {
  auto dot = [](const Point3& a, const Point3& b) { return Rational(a.x * b.x + a.y * b.y + a.z * b.z); };
  const Point3* worst = nullptr;
  Rational least;
  for (const Point3& v : F.vertices) {
    if (sgn(v.x) == 0 && sgn(v.y) == 0 && sgn(v.z) == 0) continue;
    const Rational mv = dot(m, v);
    const Rational cos2 = Rational(mv * mv / (dot(m, m) * dot(v, v)));
    if (!worst || cos2 < least) worst = &v, least = cos2;
  }
  return diagonal_map_angular_error_deg(m, *worst);
}

}  // namespace gmcc::test
