#pragma once
// One exact rational coordinate as a reported double: what exact_map_estimate (2-D) and
// exact_map_estimate_3 (3-D) report per component. Internal to gmcc::selection.

#include <gmcc/geometry/rational.h>

namespace gmcc::internal {

struct RoundedComponent {
  double nearest;      // q rounded to the nearest double (ties to even)
  double error_bound;  // |nearest − q| rounded up to a double: a rigorous bound
  double lo, hi;       // q rounded down and up: the enclosure of an exact value
};

// q as RoundedComponent, each rounding directed by MPFR at 53 bits.
RoundedComponent rounded_component(const Rational& q);

}  // namespace gmcc::internal
