#pragma once
// Two 3-D map estimates equal member by member (map, enclosure, bound, exact map, edge root): what
// the CRULE route tests assert when two routes must give the same answer bit for bit.

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

}  // namespace gmcc::test
