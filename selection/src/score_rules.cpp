#include <gmcc/selection/score_rules.h>

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/select_maps.h>

#include <gmcc/numerics/internal_check.h>

#include <stdexcept>

namespace gmcc {

RuleErrors map_errors(const Point2& m, const Point2& truth, const Colour& c) {
  RuleErrors e{};
  e.map = {to_double_nearest(m.x), to_double_nearest(m.y)};
  e.map_error_deg = map_angular_error_deg(m, truth);
  e.positive_map = sgn(m.x) > 0 && sgn(m.y) > 0;
  if (e.positive_map) {
    e.illuminant_error_deg = illuminant_angular_error_deg(m, truth, c);
    e.reproduction_error_deg = reproduction_angular_error_deg(m, truth);
  }
  return e;
}

ScoredRules score_rules(const FeasiblePolygon& F, const Point2& truth, const Colour& c, const ScoreOptions& options) {
  GMCC_CHECK(F.kind() != ConvexKind::empty, "score_rules: F is not empty (precondition)");
  for (const Rational* x : {&truth.x, &truth.y, &c.r, &c.g, &c.b})
    if (sgn(*x) <= 0) throw std::invalid_argument("score_rules: the true map and the illuminant must be > 0");
  ScoredRules out;
  const bool applies = options.certified_route && options.mean3d.method == Mean3dMethod::analytic &&
                       options.mean3d.precision_bits == 0;
  if (applies) {
    if (const auto fast = rule_errors(F, truth, c)) {
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
      for (std::size_t r = 0; r < 3; ++r) out.rules[r] = (*fast)[r];
      return out;
    }
  }
  out.area = to_double_nearest(area(F.exact()));
  SelectionOptions selection;
  selection.mean3d = options.mean3d;
  const Selections sel = select_maps(F.exact(), selection);
  const std::array<const std::optional<Selection>*, 3> rules{&sel.max_area, &sel.mean_2d, &sel.mean_3d};
  for (std::size_t r = 0; r < 3; ++r) {
    const MapEstimate& e = (**rules[r]).estimate;
    if (!e.valid) continue;
    RuleErrors x = map_errors(measured_map(e), truth, c);
    x.worst_case_deg = *(**rules[r]).worst_case_deg;
    out.rules[r] = x;
  }
  return out;
}

}  // namespace gmcc
