#pragma once
// A point's filter copy, as the clip makes a row's (polytope_clip.cpp, add_point) and the lazy
// rows test theirs (lazy_rows.cpp). Internal to gmcc::geometry.

#include <gmcc/geometry/point3_arithmetic.h>
#include <gmcc/numerics/rational_to_float.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace gmcc::internal {

// p·2^-e (e the largest binary exponent of p's channels) truncated to doubles (mpq_get_d:
// relative error below 2u), and 2^-e; not usable outside the double range policy
// (numerics/rational_to_float.h).
struct ScaledPoint {
  double c[3] = {0, 0, 0};
  double scale = 0;
  bool usable = false;
};

inline ScaledPoint scaled_point(const Point3& p) {
  ScaledPoint s;
  double d[3], top = 0;
  for (int k = 0; k < 3; ++k) {
    const std::optional<double> x = numerics::certified_double(coord(p, k).get_mpq_t());
    if (!x) return s;
    d[k] = *x, top = std::max(top, std::fabs(*x));
  }
  if (top == 0) return s;
  int e;
  std::frexp(top, &e);
  for (int k = 0; k < 3; ++k) s.c[k] = std::ldexp(d[k], -e);
  s.scale = std::ldexp(1.0, -e);
  s.usable = true;
  return s;
}

// A row's filter copy (a facet's copy times a ScaledPoint) is used only when every non-zero
// coefficient is in [2^-200, 2^200]: its products with vertex bounds (box_range, clip_filter.h)
// are then normal, so each rounding is within u relative.
inline bool filter_range(double x) { return x == 0 || (std::fabs(x) >= 0x1p-200 && std::fabs(x) <= 0x1p200); }

}  // namespace gmcc::internal
