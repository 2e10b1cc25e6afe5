#include <gmcc/selection/select_scene_options.h>

namespace gmcc {

std::string to_string(RecoveryPolicy policy) {
  switch (policy) {
    case RecoveryPolicy::grow_canonical: return "grow-canonical";
    case RecoveryPolicy::min_violation: return "min-violation";
    case RecoveryPolicy::none: break;
  }
  return "none";
}

namespace {
constexpr RecoveryPolicy all_recovery_policies[] = {RecoveryPolicy::none, RecoveryPolicy::grow_canonical,
                                                    RecoveryPolicy::min_violation};
}  // namespace

RecoveryPolicy recovery_policy_from_string(const std::string& name) {
  for (RecoveryPolicy p : all_recovery_policies)
    if (to_string(p) == name) return p;
  throw std::invalid_argument("unknown recovery policy '" + name +
                              "' (expected none, grow-canonical or min-violation)");
}

std::vector<std::string> recovery_policy_names() {
  std::vector<std::string> names;
  for (RecoveryPolicy p : all_recovery_policies) names.push_back(to_string(p));
  return names;
}

const Rational& max_scene_coordinate() {
  static const Rational limit = parse_rational("1e150");
  return limit;
}

}  // namespace gmcc
