#pragma once
// Exact 3-vector arithmetic on Point3 (rationals). Internal to gmcc::geometry.

#include <gmcc/geometry/convex_set_3.h>

namespace gmcc::internal {

inline Point3 sub(const Point3& a, const Point3& b) {
  return {Rational(a.x - b.x), Rational(a.y - b.y), Rational(a.z - b.z)};
}
inline Point3 add(const Point3& a, const Point3& b) {
  return {Rational(a.x + b.x), Rational(a.y + b.y), Rational(a.z + b.z)};
}
inline Point3 scale(const Point3& a, const Rational& s) {
  return {Rational(a.x * s), Rational(a.y * s), Rational(a.z * s)};
}
inline Point3 hadamard(const Point3& a, const Point3& b) {
  return {Rational(a.x * b.x), Rational(a.y * b.y), Rational(a.z * b.z)};
}
inline Point3 cross(const Point3& a, const Point3& b) {
  return {Rational(a.y * b.z - a.z * b.y), Rational(a.z * b.x - a.x * b.z),
          Rational(a.x * b.y - a.y * b.x)};
}
inline Rational dot(const Point3& a, const Point3& b) {
  return Rational(a.x * b.x + a.y * b.y + a.z * b.z);
}
inline bool is_zero(const Point3& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }
inline const Rational& coord(const Point3& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }
inline Rational& coord(Point3& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }
/// The coordinate where |n| is largest (the first on ties).
inline int largest_coordinate(const Point3& n) {
  const Rational ax = abs(n.x), ay = abs(n.y), az = abs(n.z);
  return ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
}

}  // namespace gmcc::internal
