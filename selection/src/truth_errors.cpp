#include <gmcc/selection/score_rules.h>
#include <gmcc/selection/truth_errors.h>

#include <stdexcept>

namespace gmcc {

std::optional<TruthErrors> truth_errors(const Selection& s, const Point2& truth, const Colour& c) {
  if (sgn(truth.x) <= 0 || sgn(truth.y) <= 0 || sgn(c.r) <= 0 || sgn(c.g) <= 0 || sgn(c.b) <= 0)
    throw std::invalid_argument("truth_errors: the true map and c must be > 0");
  const MapEstimate& e = s.estimate;
  if (!e.valid) return std::nullopt;
  const Point2 m = measured_map(e);
  const RuleErrors x = map_errors(m, truth, c);
  TruthErrors t;
  t.map_error_deg = x.map_error_deg;
  if (x.positive_map) t.illuminant_error_deg = x.illuminant_error_deg, t.reproduction_error_deg = x.reproduction_error_deg;
  return t;
}

}  // namespace gmcc
