#pragma once
// The filter step that CRULE's vertex rules share (max_trace's largest trace, the worst case's
// least cos²): which candidates may still be the best, from enclosures of their values.
// Internal to gmcc::selection.

#include <gmcc/geometry/enclosure.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace gmcc::internal {

/// The indices, in order, of the values whose upper end reaches the largest lower end among the
/// finite ones: the largest value is among them, and so is every value tied with it. A value
/// whose enclosure is not finite is always kept. O(n).
inline std::vector<std::size_t> may_be_largest(const std::vector<Enclosure>& values) {
  double floor = -std::numeric_limits<double>::infinity();
  for (const Enclosure& x : values)
    if (x.finite()) floor = std::max(floor, x.lo());
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!values[i].finite() || values[i].hi() >= floor) out.push_back(i);
  return out;
}

}  // namespace gmcc::internal
