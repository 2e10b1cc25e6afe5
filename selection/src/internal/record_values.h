#pragma once
// The record form's values (select_scene_record.h) from what the routes compute: an angle of the
// exact routes as an enclosure, and an x87 enclosure as a double one. Internal to gmcc::selection.

#include <gmcc/geometry/rational_enclosure.h>
#include <gmcc/numerics/internal_check.h>
#include <gmcc/selection/certified_rule_errors.h>

#include <cmath>

namespace gmcc::internal {

/// The exact routes' angles (angle_deg, worst_case_map_deg, worst_case_illuminant_deg) are within a
/// relative 2^-50 of the exact angle at the map they measure (about one ulp, certified_rule_errors.h).
inline constexpr double exact_route_accuracy = 0x1p-50;

/// An exact route's angle `deg`, measured at a map whose angles may differ from those at the
/// exact map by at most `shift` degrees, as an enclosure of the angle at the exact map.
/// \pre the result is within rule_errors_accuracy (checked: the shift is an enclosure's width).
inline Enclosure record_angle(double deg, double shift) {
  const Enclosure e{deg, Enclosure::round_up(std::fabs(deg) * exact_route_accuracy + shift)};
  GMCC_CHECK(e.rad <= rule_errors_accuracy * (1 + std::fabs(deg)),
             "record_angle: an exact route's angle within the record's accuracy");
  return e;
}

/// x as a double enclosure: its midpoint rounded, the radius covering that rounding.
inline Enclosure to_double(const Enclosure& x) { return x; }
inline Enclosure to_double(const LongEnclosure& x) {
  const double mid = static_cast<double>(x.mid);
  const long double moved = std::fabs(x.mid - static_cast<long double>(mid));  // exact: both near x.mid
  return {mid, Enclosure::round_up(static_cast<double>(x.rad + moved))};
}

}  // namespace gmcc::internal
