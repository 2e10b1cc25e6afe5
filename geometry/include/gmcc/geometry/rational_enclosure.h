#pragma once
/// \file rational_enclosure.h
/// Geometry's names for the enclosure family (numerics/enclosure.h): Enclosure in doubles,
/// LongEnclosure in x87 extended precision, and an exact rational as a double enclosure.

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/enclosure.h>
#include <gmcc/numerics/rational_to_float.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace gmcc {

/// The midpoint–radius kind (numerics/enclosure.h), in gmcc's namespace.
using numerics::BasicEnclosure;
/// Doubles (u = 2^-53): the fast paths' first stage.
using Enclosure = BasicEnclosure<double>;
/// x87 extended precision (u = 2^-64): their second stage, for thin sets.
using LongEnclosure = BasicEnclosure<long double>;

/// An exact rational as a certified double enclosure: numerics::certified_double (relative error
/// below 2u) within the range policy of numerics/rational_to_float.h; outside it an unbounded
/// enclosure, which decides nothing.
inline Enclosure enclose_rational(const Rational& q) {
  if (sgn(q) == 0) return Enclosure::exact(0);
  const std::optional<double> d = numerics::certified_double(q.get_mpq_t());
  if (!d) return {0, Enclosure::unbounded};
  return Enclosure::relative(*d, 2 * Enclosure::u);
}

/// A point of space (a map d or a colour) as double enclosures of its exact coordinates, in the
/// order x, y, z: what the 3-D filters (CRULE's selections, containment) compute with.
using Enclosure3 = std::array<Enclosure, 3>;

/// enclose_rational of each coordinate of p.
inline Enclosure3 enclose_point(const Point3& p) {
  return {enclose_rational(p.x), enclose_rational(p.y), enclose_rational(p.z)};
}

/// \name Vector arithmetic on enclosed points
///@{
/// a − b.
inline Enclosure3 operator-(const Enclosure3& a, const Enclosure3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
/// a · b.
inline Enclosure dot(const Enclosure3& a, const Enclosure3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
/// a × b.
inline Enclosure3 cross(const Enclosure3& a, const Enclosure3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
///@}

/// A facet's plane n·d = k, enclosed: n = (v1 − v0) × (v2 − v0) from its first three vertices,
/// outward for a facet counter-clockwise seen from outside (ConvexSet3), and k = n·v0.
struct EnclosedPlane {
  Enclosure3 n;  ///< the outward normal
  Enclosure k;   ///< n·v0
};

/// The plane of `face` (indices into `vertices`, a ConvexSet3 facet) from enclosed vertices.
inline EnclosedPlane enclosed_facet_plane(const std::vector<Enclosure3>& vertices, const std::vector<std::size_t>& face) {
  const Enclosure3 n = cross(vertices[face[1]] - vertices[face[0]], vertices[face[2]] - vertices[face[0]]);
  return {n, dot(n, vertices[face[0]])};
}

/// n·p − k: certainly positive when p is strictly outside the facet's half-space.
inline Enclosure side(const EnclosedPlane& h, const Enclosure3& p) { return dot(h.n, p) - h.k; }

}  // namespace gmcc
