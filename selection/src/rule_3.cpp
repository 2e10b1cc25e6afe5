// The 3-D rules' names and dispatch (rule_3.h).
#include <gmcc/selection/rule_3.h>

#include <gmcc/numerics/internal_check.h>
#include <gmcc/selection/max_trace.h>
#include <gmcc/selection/max_volume.h>

#include <algorithm>
#include <stdexcept>

namespace gmcc {

std::string to_string(Rule3 rule) {
  switch (rule) {
    case Rule3::max_volume: return "max_volume";
    case Rule3::centroid: return "centroid";
    case Rule3::max_trace: return "max_trace";
  }
  GMCC_CHECK(false, "to_string(Rule3): a rule without a key");
  return {};
}

std::string rule_3_label(Rule3 rule) {
  std::string label = to_string(rule);
  std::replace(label.begin(), label.end(), '_', '-');
  return label;
}

std::vector<std::string> rule_3_labels() {
  std::vector<std::string> out;
  for (Rule3 r : all_rules_3) out.push_back(rule_3_label(r));
  return out;
}

Rule3 rule_3_from_string(const std::string& text) {
  std::string valid;
  for (Rule3 r : all_rules_3) {
    if (text == to_string(r) || text == rule_3_label(r)) return r;
    valid += (valid.empty() ? "" : ", ") + rule_3_label(r);
  }
  throw std::invalid_argument("\"" + text + "\" is not one of " + valid);
}

MapEstimate3 select_rule_3(Rule3 rule, const LazyConvexSet3& F3, Crule3dRoute route) {
  switch (rule) {
    case Rule3::max_volume: return max_volume(F3);
    case Rule3::centroid: return centroid_3(F3, route);
    case Rule3::max_trace: return max_trace(F3);
  }
  GMCC_CHECK(false, "select_rule_3: a rule without an implementation");
  return {};
}

}  // namespace gmcc
