#pragma once
/// \file may_be_largest.h
/// The one filter step of every rule that picks a largest value from enclosures (numerics/
/// enclosure.h): which candidates may still be the largest. Max-area's unique maximum (selection's
/// max_area_candidates.h, both routes), CRULE's max-trace and 3-D worst case, the map-space worst
/// case's x87 pruning (docs/architecture.md "Exactness, routes and failures"). NaN-safe: a value
/// a NaN touched decides nothing and is always kept.

#include <gmcc/numerics/enclosure.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace gmcc::numerics {

/// The positions, in order, of the items whose value (`value(item)`, an enclosure of any kind with
/// lower() and upper()) may be the largest: every one whose upper end is not below the floor, the
/// largest lower end among the values whose ends are both numbers, lowered by a relative `slack`
/// (0: none; the floor f becomes f·(1 − slack) for f >= 0, f·(1 + slack) below). The largest value
/// is among them, and so is every value tied with it or within the slack of it. A value with a NaN
/// end sets no floor and is kept; an unbounded one (ends ±inf) sets none that matters and is kept.
/// O(n).
template <class Items, class Value>
std::vector<std::size_t> may_be_largest(const Items& items, Value value, double slack = 0) {
  using End = decltype(lower(value(items[0])));
  End floor = -std::numeric_limits<End>::infinity();
  for (const auto& item : items) {
    const auto& x = value(item);
    const End l = lower(x), h = upper(x);
    if (l <= h && l > floor) floor = l;  // false when either end is NaN
  }
  if (slack != 0 && std::isfinite(floor)) floor *= floor >= 0 ? 1 - End(slack) : 1 + End(slack);
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (!(upper(value(items[i])) < floor)) out.push_back(i);
  return out;
}

/// may_be_largest over the enclosures themselves.
template <class X>
std::vector<std::size_t> may_be_largest(const std::vector<X>& values, double slack = 0) {
  return may_be_largest(values, [](const X& x) -> const X& { return x; }, slack);
}

}  // namespace gmcc::numerics
