#pragma once
/// \file enclosure.h
/// Geometry's names for the enclosure family (numerics/enclosure.h): Enclosure in doubles,
/// LongEnclosure in x87 extended precision, and an exact rational as a double enclosure.

#include <gmcc/geometry/convex_set_3.h>
#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/enclosure.h>

#include <array>
#include <cmath>

namespace gmcc {

/// The midpoint–radius kind (numerics/enclosure.h), in gmcc's namespace.
using numerics::BasicEnclosure;
/// Doubles (u = 2^-53): the fast paths' first stage.
using Enclosure = BasicEnclosure<double>;
/// x87 extended precision (u = 2^-64): their second stage, for thin sets.
using LongEnclosure = BasicEnclosure<long double>;

/// An exact rational as a certified double enclosure: mpq_get_d truncates (relative error below
/// 2u) within [2^-138, 2^138]; outside that range an unbounded enclosure, which decides nothing.
inline Enclosure enclose_rational(const Rational& q) {
  if (sgn(q) == 0) return Enclosure::exact(0);
  const long bits = static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2)) -
                    static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 2));
  if (bits < -138 || bits > 138) return {0, Enclosure::unbounded};
  return Enclosure::relative(mpq_get_d(q.get_mpq_t()), 2 * Enclosure::u);
}

/// A point of space (a map d or a colour) as double enclosures of its exact coordinates, in the
/// order x, y, z: what the 3-D filters (CRULE's selections, containment) compute with.
using Enclosure3 = std::array<Enclosure, 3>;

/// enclose_rational of each coordinate of p.
inline Enclosure3 enclose_point(const Point3& p) {
  return {enclose_rational(p.x), enclose_rational(p.y), enclose_rational(p.z)};
}

}  // namespace gmcc
