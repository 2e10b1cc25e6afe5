#include <gmcc/selection/score_rules.h>

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/select_maps.h>

#include <gmcc/numerics/internal_check.h>

#include <stdexcept>

namespace gmcc {

ScoredRules score_rules(const FeasiblePolygon& F, const Point2& truth, const Colour& c, const ScoreOptions& options) {
  GMCC_CHECK(F.kind() != ConvexKind::empty, "score_rules: F is not empty (precondition)");
  for (const Rational* x : {&truth.x, &truth.y, &c.r, &c.g, &c.b})
    if (sgn(*x) <= 0) throw std::invalid_argument("score_rules: the true map and the illuminant must be > 0");
  ScoredRules out;
  const bool applies = options.certified_route && options.mean3d.method == Mean3dMethod::analytic &&
                       options.mean3d.precision_bits == 0;
  if (applies) {
    if (const auto fast = certified_rule_errors(F, truth, c)) {
      out.certified = true;
      // The area from the vertex enclosures' midpoints (shoelace): a description of F.
      const std::vector<EnclosedVertex>& v = F.vertices();
      double twice = 0;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const EnclosedVertex &p = v[i], &q = v[(i + 1) % v.size()];
        twice += static_cast<double>(p.x.mid) * static_cast<double>(q.y.mid) -
                 static_cast<double>(q.x.mid) * static_cast<double>(p.y.mid);
      }
      out.area = twice / 2;
      for (Rule r : all_rules) out.rules[r] = (*fast)[r];
      return out;
    }
  }
  out.area = to_double_nearest(area(F.exact()));
  SelectionOptions selection;
  selection.mean3d = options.mean3d;
  const Selections sel = select_maps(F.exact(), selection);
  for (Rule r : all_rules) out.rules[r] = exact_rule_errors(*sel[r], truth, c);
  return out;
}

}  // namespace gmcc
