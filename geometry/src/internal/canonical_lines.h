#pragma once
// CanonicalConstraints' prepared state (its lines_): G_c's half-planes (and the map constraint's) as exact
// integer lines with their filters, built once and shared read-only by every clipping run.
// Internal to gmcc::geometry.

#include <gmcc/geometry/feasible_set.h>

#include "internal/extended_value.h"
#include "internal/integer_line.h"

#include <vector>

namespace gmcc::internal {

// G_c's half-planes as exact integer lines and their filters, and the bounds the box needs.
struct CanonicalLines {
  std::vector<Line> lines;
  std::vector<ApproximateLine> approx;
  std::vector<LongLine> long_lines;  // empty when not available
  bool polygon = false;  // lines[i] carries the edge from vertex i to vertex i+1 of G_c
  // The map constraint C (F ∩ C is computed): its half-planes as exact lines and approximations.
  std::vector<Line> extra_lines;
  std::vector<ApproximateLine> extra_approx;
  bool extra_filtered = true, extra_empty = false;
  bool filtered = true;  // every approximation is in the filter's range
  Rational x_max, y_max;
};

}  // namespace gmcc::internal
