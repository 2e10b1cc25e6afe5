// Uses the installed library on the paper's toy example; exit 0 iff the answers are right.
#include <gmcc/geometry/convex_hull.h>
#include <gmcc/geometry/feasible_set.h>
#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>

#include <iostream>

int main() {
  using gmcc::Rational;
  const gmcc::ConvexSet2 G = gmcc::convex_hull({{3, 2}, {Rational(1, 3), Rational(2, 3)}});
  const gmcc::ConvexSet2 F = gmcc::feasible_set(G, {{1, 1}});
  const bool ok = F.kind == gmcc::ConvexKind::segment &&
                  gmcc::max_area_point(F) == gmcc::Point2{3, 2} &&
                  *gmcc::mean_2d(F).exact == gmcc::Point2{Rational(5, 3), Rational(4, 3)};
  std::cout << (ok ? "consumer: ok\n" : "consumer: WRONG\n");
  return ok ? 0 : 1;
}
