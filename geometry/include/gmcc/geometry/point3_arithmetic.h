#pragma once
/// \file point3_arithmetic.h
/// Exact 3-vector arithmetic on Point3 (rationals): the differences, products and tests that
/// Forsyth's CRULE is built from — F3's half-spaces and their normals, polytope facets, max-volume's
/// edge candidates, the worst case's cos² (docs/math.md §1b). Each result is exact and canonical.
/// O(1) rational operations each.

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/integers_over_lcm.h>

#include <array>

namespace gmcc {

/// a − b.
inline Point3 sub(const Point3& a, const Point3& b) {
  return {Rational(a.x - b.x), Rational(a.y - b.y), Rational(a.z - b.z)};
}
/// a + b.
inline Point3 add(const Point3& a, const Point3& b) {
  return {Rational(a.x + b.x), Rational(a.y + b.y), Rational(a.z + b.z)};
}
/// s·a.
inline Point3 scale(const Point3& a, const Rational& s) {
  return {Rational(a.x * s), Rational(a.y * s), Rational(a.z * s)};
}
/// a ⊙ b, the componentwise product (a diagonal map applied to a colour).
inline Point3 hadamard(const Point3& a, const Point3& b) {
  return {Rational(a.x * b.x), Rational(a.y * b.y), Rational(a.z * b.z)};
}
/// a × b.
inline Point3 cross(const Point3& a, const Point3& b) {
  return {Rational(a.y * b.z - a.z * b.y), Rational(a.z * b.x - a.x * b.z), Rational(a.x * b.y - a.y * b.x)};
}
/// a · b.
inline Rational dot(const Point3& a, const Point3& b) { return Rational(a.x * b.x + a.y * b.y + a.z * b.z); }
/// a = 0 (every coordinate zero).
inline bool is_zero(const Point3& a) { return sgn(a.x) == 0 && sgn(a.y) == 0 && sgn(a.z) == 0; }
/// Coordinate k of p: x, y, z for k = 0, 1, 2.
inline const Rational& coord(const Point3& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }
/// Coordinate k of p, writable: x, y, z for k = 0, 1, 2.
inline Rational& coord(Point3& p, int k) { return k == 0 ? p.x : k == 1 ? p.y : p.z; }
/// p in homogeneous integer coordinates (p·L, L), L ≥ 1 the lcm of its denominators:
/// (X/L, Y/L, Z/L) = p, without a gcd (integers_over_lcm.h).
inline std::array<mpz_class, 4> homogeneous_integers(const Point3& p) {
  const mpz_class l = lcm_of_denominators_of(p.x, p.y, p.z);
  return {times_lcm(p.x, l), times_lcm(p.y, l), times_lcm(p.z, l), l};
}
/// The coordinate (0, 1, 2) where |n| is largest, the first on ties: the axis to drop when a plane
/// with normal n is projected to 2-D.
inline int largest_coordinate(const Point3& n) {
  const Rational ax = abs(n.x), ay = abs(n.y), az = abs(n.z);
  return ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
}

}  // namespace gmcc
