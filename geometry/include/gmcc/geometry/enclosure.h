#pragma once
/// \file enclosure.h
/// Geometry's names for the enclosure family (numerics/enclosure.h): Enclosure in doubles,
/// LongEnclosure in x87 extended precision, and an exact rational as a double enclosure.

#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/enclosure.h>

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

}  // namespace gmcc
