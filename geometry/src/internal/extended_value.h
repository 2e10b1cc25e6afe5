#pragma once
// Rationals and integers in x87 extended precision and as filtered doubles, with the error
// bounds the feasible polygon's filters and enclosures rely on (docs/math.md §1a′). Where the
// platform lacks the 64-bit significand the extended values are not used (numerics/platform.h).
// Internal to gmcc::geometry.

#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/platform.h>
#include <gmcc/numerics/rational_to_float.h>

#include <cstdint>
#include <cstring>
#include <optional>

namespace gmcc::internal {

// An integer in extended precision (relative error below 2^-63), or nothing outside the range
// policy (numerics/rational_to_float.h: beyond 2^16000).
inline std::optional<long double> top_bits(mpz_srcptr z) { return numerics::certified_extended(z); }

// A rational in extended precision (relative error below 2^-61.6), or nothing outside the range
// policy (beyond 2^±16000).
inline std::optional<long double> top_bits(const Rational& q) {
  return numerics::certified_extended(q.get_num_mpz_t(), q.get_den_mpz_t());
}

// Extended-precision values are computed where the platform has the 64-bit significand this
// analysis assumes (numerics::extended_precision_compiled); the enclosures built from them are used
// only where the thread's x87 is at its full precision (numerics::extended_precision_active()),
// checked where they are used.

// A rational as a double within a relative 2u (u = 2^-53) of it, or nothing outside the double
// range policy (numerics/rational_to_float.h). From the extended-precision quotient (2^-61.6)
// rounded to double (u) where available, else numerics::certified_double (truncation: below 2u).
inline std::optional<double> approx(const Rational& q, const std::optional<long double>& extended) {
  if (sgn(q) == 0) return 0.0;
  if (!numerics::in_double_range(q.get_num_mpz_t(), q.get_den_mpz_t())) return std::nullopt;
  return extended ? static_cast<double>(*extended) : mpq_get_d(q.get_mpq_t());
}
// The same, where q's extended-precision value is not at hand.
inline std::optional<double> approx(const Rational& q) {
  return approx(q, numerics::extended_precision_compiled ? top_bits(q) : std::nullopt);
}

// A line in extended precision: each coefficient within a relative 2^-61 of the same positive
// multiple of the exact line (for vertex enclosures).
struct LongLine {
  long double a, b, c;
};


}  // namespace gmcc::internal
