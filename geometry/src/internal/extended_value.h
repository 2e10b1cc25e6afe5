#pragma once
// Rationals and integers in x87 extended precision and as filtered doubles, with the error
// bounds the feasible polygon's filters and enclosures rely on (docs/math.md §1a′). Where the
// platform lacks the 64-bit significand the extended values are not used (numerics/platform.h).
// Internal to gmcc::geometry.

#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/platform.h>
#include <gmcc/numerics/top_bits.h>

#include <cstdint>
#include <cstring>
#include <optional>

namespace gmcc::internal {

// 2^e, exactly, for |e| < 1000 (built from its bits: cheaper than ldexp).
inline double pow2(long e) {
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}
// x·2^e exactly in extended precision (no overflow or underflow there for |e| < 16000); pow2 is
// called with |e| <= 900 only.
inline long double scale(long double x, long e) {
  while (e > 900) x *= pow2(900), e -= 900;
  while (e < -900) x *= pow2(-900), e += 900;
  return x * pow2(e);
}

// An integer in extended precision (relative error below 2^-63), or nothing beyond 2^16000.
inline std::optional<long double> top_bits(mpz_srcptr z) {
  if (mpz_size(z) > 250) return std::nullopt;
  const numerics::TopBits t = numerics::top_bits(z);
  const long double v = scale(static_cast<long double>(t.mantissa), t.shift);
  return mpz_sgn(z) < 0 ? -v : v;
}

// A rational in extended precision: numerator and denominator truncated (2^-63 each) and one
// rounded division (2^-64): relative error below 2^-61.6. Nothing beyond 2^±16000.
inline std::optional<long double> top_bits(const Rational& q) {
  if (mpz_size(q.get_num_mpz_t()) > 250 || mpz_size(q.get_den_mpz_t()) > 250) return std::nullopt;
  const numerics::TopBits n = numerics::top_bits(q.get_num_mpz_t()), d = numerics::top_bits(q.get_den_mpz_t());
  const long double v =
      scale(static_cast<long double>(n.mantissa) / static_cast<long double>(d.mantissa), n.shift - d.shift);
  return sgn(q) < 0 ? -v : v;
}

// Extended-precision values are computed where the platform has the 64-bit significand this
// analysis assumes (numerics::extended_precision_compiled); the enclosures built from them are used
// only where the thread's x87 is at its full precision (numerics::extended_precision_active()),
// checked where they are used.

// A rational as a double within a relative 2u (u = 2^-53) of it, or nothing when it is outside
// [2^-140, 2^140] (checked from its size). From the extended-precision quotient (2^-61.6) rounded
// to double (u) where available, else mpq_get_d (truncation: below 2u in the normal range).
inline std::optional<double> approx(const Rational& q, const std::optional<long double>& extended) {
  if (sgn(q) == 0) return 0.0;
  const long bits = static_cast<long>(mpz_sizeinbase(q.get_num_mpz_t(), 2)) -
                    static_cast<long>(mpz_sizeinbase(q.get_den_mpz_t(), 2));
  if (bits < -138 || bits > 138) return std::nullopt;
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
