#include <gmcc/selection/max_area.h>
#include <gmcc/selection/mean_2d.h>
#include <gmcc/selection/rule.h>

#include <stdexcept>

namespace gmcc {

std::string to_string(Rule rule) {
  switch (rule) {
    case Rule::max_area: return "max_area";
    case Rule::mean_2d: return "mean_2d";
    case Rule::mean_3d: break;
  }
  return "mean_3d";
}

std::string rule_label(Rule rule) {
  switch (rule) {
    case Rule::max_area: return "max-area";
    case Rule::mean_2d: return "2-D mean";
    case Rule::mean_3d: break;
  }
  return "3-D mean";
}

Rule rule_from_string(const std::string& text) {
  std::string key = text;
  for (char& ch : key)
    if (ch == '-') ch = '_';
  std::string valid;
  for (Rule r : all_rules) {
    if (to_string(r) == key) return r;
    valid += (valid.empty() ? "" : ", ") + to_string(r);
  }
  throw std::invalid_argument("unknown rule '" + text + "' (expected " + valid + ")");
}

MapEstimate select_rule(Rule rule, const ConvexSet2& F, const Mean3dOptions& mean3d) {
  switch (rule) {
    case Rule::max_area: return max_area(F);
    case Rule::mean_2d: return mean_2d(F);
    case Rule::mean_3d: break;
  }
  return mean_3d(F, mean3d);
}

}  // namespace gmcc
