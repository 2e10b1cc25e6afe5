#include <gmcc/selection/angular_error.h>
#include <gmcc/selection/rule_errors.h>

#include <stdexcept>

namespace gmcc {

RuleErrors exact_rule_errors(const Point2& m, const Point2& truth, const Colour& c) {
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

std::optional<RuleErrors> exact_rule_errors(const Selection& s, const Point2& truth, const Colour& c) {
  if (sgn(truth.x) <= 0 || sgn(truth.y) <= 0 || sgn(c.r) <= 0 || sgn(c.g) <= 0 || sgn(c.b) <= 0)
    throw std::invalid_argument("exact_rule_errors: the true map and c must be > 0");
  if (!s.estimate.valid) return std::nullopt;
  RuleErrors e = exact_rule_errors(measured_map(s.estimate), truth, c);
  e.worst_case_deg = s.worst_case_deg.value_or(0);
  return e;
}

}  // namespace gmcc
