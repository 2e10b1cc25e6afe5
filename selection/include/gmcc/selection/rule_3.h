#pragma once
/// \file rule_3.h
/// The selection rules on the 3-D feasible set F3 of diagonal maps (Forsyth 1990's CRULE;
/// Gijsenij, Gevers & van de Weijer 2010), named once, as rule.h names the 2-D rules: the enum
/// every estimate, benchmark and front end iterates over, their keys and labels, a container with
/// one value per rule, and the one dispatch. Adding a rule means a value here, its key and label
/// and its dispatch in rule_3.cpp, and its implementation file; the front ends take the names
/// from rule_3_keys().

#include <gmcc/geometry/lazy_convex_set_3.h>
#include <gmcc/selection/centroid_3.h>
#include <gmcc/selection/map_estimate_3.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace gmcc {

/// The 3-D rules, in the order every report lists them.
enum class Rule3 {
  max_volume,  ///< argmax d1·d2·d3, CRULE-MV (Forsyth 1990; max_volume.h)
  centroid,    ///< F3's centroid, CRULE-AVE (Barnard et al. 2002 Part I; centroid_3.h)
  max_trace,   ///< argmax d1 + d2 + d3 (Gijsenij, Gevers & van de Weijer 2010; max_trace.h)
};

/// How many 3-D rules there are.
inline constexpr std::size_t rule_3_count = 3;
/// Every 3-D rule, in report order.
inline constexpr std::array<Rule3, rule_3_count> all_rules_3 = {Rule3::max_volume, Rule3::centroid,
                                                                Rule3::max_trace};

/// The rule's key: `max_volume`, `centroid`, `max_trace` (JSON members, Python names).
std::string to_string(Rule3 rule);
/// The rule as the command line and tables write it: `max-volume`, `centroid`, `max-trace`.
std::string rule_3_label(Rule3 rule);
/// Every rule's label, in report order: what a front end offers as choices.
std::vector<std::string> rule_3_labels();
/// The inverse of to_string, also from the label. \throws std::invalid_argument naming the labels.
Rule3 rule_3_from_string(const std::string& text);

/// The map `rule` selects from F3 (the centroid on `route`; the others are exact either way).
/// \pre F3 is not empty. Complexity: that rule's.
MapEstimate3 select_rule_3(Rule3 rule, const LazyConvexSet3& F3, Crule3dRoute route);

/// One value per 3-D rule, indexed by Rule3, iterated in report order.
template <class T>
struct PerRule3 {
  std::array<T, rule_3_count> values{};  ///< in all_rules_3 order

  /// The value of `rule`.
  ///@{
  T& operator[](Rule3 rule) { return values[static_cast<std::size_t>(rule)]; }
  const T& operator[](Rule3 rule) const { return values[static_cast<std::size_t>(rule)]; }
  ///@}
  /// Iteration in all_rules_3 order.
  ///@{
  auto begin() { return values.begin(); }
  auto end() { return values.end(); }
  auto begin() const { return values.begin(); }
  auto end() const { return values.end(); }
  ///@}
};

}  // namespace gmcc
