#pragma once
/// \file rule.h
/// The selection rules on the 2-D feasible set F of perspective maps (Finlayson & Hordley 1999
/// §3), named once: the enum every result, report and front end iterates over, their names, and
/// a container with one value per rule. Adding a rule means a value here, its names and its
/// dispatch in rule.cpp, and its implementation file (docs/conventions.md §10).
///
/// "3-D mean" is the paper's name for a rule on the 2-D set: the mean of the cone of 3-D maps
/// over F, seen in perspective (docs/conventions.md §10). CRULE's rules on the 3-D set of
/// diagonal maps are Rule3 (rule_3.h).

#include <gmcc/geometry/convex_set.h>
#include <gmcc/selection/map_estimate.h>
#include <gmcc/selection/mean_3d.h>

#include <array>
#include <cstddef>
#include <string>

namespace gmcc {

/// The selection rules on the 2-D feasible set, in the order every report lists them.
enum class Rule {
  max_area,  ///< the map of largest m1·m2 (§3.1, max_area.h)
  mean_2d,   ///< the centroid of F (§3.2, mean_2d.h)
  mean_3d,   ///< the mean of F's cone of 3-D maps, in perspective (§3.2, mean_3d.h)
};

/// How many rules there are.
inline constexpr std::size_t rule_count = 3;
/// Every rule, in report order.
inline constexpr std::array<Rule, rule_count> all_rules = {Rule::max_area, Rule::mean_2d, Rule::mean_3d};

/// The rule's key: `max_area`, `mean_2d`, `mean_3d` (JSON members, CSV columns, Python names).
std::string to_string(Rule rule);
/// The rule as a person reads it in tables: `max-area`, `2-D mean`, `3-D mean`.
std::string rule_label(Rule rule);
/// The inverse of to_string; also accepts dashes for underscores (`max-area`).
/// \throws std::invalid_argument naming the valid keys.
Rule rule_from_string(const std::string& text);

/// The map `rule` selects from F: max_area(F), mean_2d(F) or mean_3d(F, mean3d) (the 3-D mean's
/// route from `mean3d`; the others ignore it). \pre F is not empty. Complexity: that rule's.
MapEstimate select_rule(Rule rule, const ConvexSet2& F, const Mean3dOptions& mean3d = {});

/// One value per rule, indexed by Rule, iterated in report order (an array: no allocation).
template <class T>
struct PerRule {
  std::array<T, rule_count> values{};  ///< in all_rules order

  /// The value of `rule`.
  ///@{
  T& operator[](Rule rule) { return values[static_cast<std::size_t>(rule)]; }
  const T& operator[](Rule rule) const { return values[static_cast<std::size_t>(rule)]; }
  ///@}
  /// Iteration in all_rules order.
  ///@{
  auto begin() { return values.begin(); }
  auto end() { return values.end(); }
  auto begin() const { return values.begin(); }
  auto end() const { return values.end(); }
  ///@}
};

}  // namespace gmcc
