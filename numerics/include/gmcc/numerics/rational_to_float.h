#pragma once
/// \file rational_to_float.h
/// Exact rationals and integers (GMP) as certified floating-point values, under one range policy:
/// the one conversion every filter and enclosure starts from (geometry's enclose_rational and
/// extended values, selection's x87 intervals, CRULE's scaled points; docs/math.md §1a′).
///
/// **The range policy.** A value is converted only when its binary magnitude
/// e = bits(|num|) − bits(den) (so 2^(e−1) < |q| < 2^(e+1)) satisfies |e| <= the kind's limit:
/// - double: 138. A product or quotient of up to seven converted values then lies within
///   2^±980, normal and finite (the double range is 2^-1022 to 2^1024), so the relative error
///   bounds the filters rely on hold with no underflow or overflow term.
/// - x87 long double: 16000 (its range is 2^±16382): integers of up to 250 64-bit limbs, and
///   quotients of them, with room for the scaling of their top bits.
/// Outside it the conversion gives nothing, and the caller decides exactly (or with an enclosure
/// that decides nothing). Zero is always converted, exactly.

#include <gmcc/numerics/top_bits.h>

#include <gmp.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <optional>

namespace gmcc::numerics {

/// The largest |binary magnitude| converted to double (the range policy above).
inline constexpr long double_magnitude_limit = 138;
/// The largest |binary magnitude| converted to x87 long double (the range policy above).
inline constexpr long extended_magnitude_limit = 16000;

/// bits(|num|) − bits(|den|) for num ≠ 0, den ≠ 0: within 1 of log2 |num/den|.
inline long binary_magnitude(mpz_srcptr num, mpz_srcptr den) {
  return static_cast<long>(mpz_sizeinbase(num, 2)) - static_cast<long>(mpz_sizeinbase(den, 2));
}

/// True when num/den ≠ 0 is within the double range policy.
inline bool in_double_range(mpz_srcptr num, mpz_srcptr den) {
  return std::labs(binary_magnitude(num, den)) <= double_magnitude_limit;
}

/// True when the double x is 0 or 2^-139 <= |x| < 2^139: the policy applied to a value
/// converted before (a rational of magnitude e lies in (2^(e−1), 2^(e+1)), so every double
/// certified_double gives passes; NaN and infinities do not).
inline bool in_double_range(double x) {
  if (x == 0) return true;
  if (!std::isfinite(x)) return false;
  int e;  // 2^(e−1) <= |x| < 2^e
  std::frexp(x, &e);
  return e >= -double_magnitude_limit && e <= double_magnitude_limit + 1;
}

/// q as a double within a relative 2u (u = 2^-53) of it: mpq_get_d truncates, below 2u in the
/// normal range the policy keeps it in. Nothing outside the double range policy; 0 exactly.
inline std::optional<double> certified_double(mpq_srcptr q) {
  if (mpq_sgn(q) == 0) return 0.0;
  if (!in_double_range(mpq_numref(q), mpq_denref(q))) return std::nullopt;
  return mpq_get_d(q);
}

/// 2^e as a double, exactly, for |e| < 1000 (built from its bits: cheaper than ldexp).
inline double exact_power_of_two(long e) {
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

/// x·2^e, exactly in x87 extended precision where the result stays in its range (|e| < 16100
/// with x a top-bits value); exact_power_of_two is called with |e| <= 900 only.
inline long double times_power_of_two(long double x, long e) {
  while (e > 900) x *= exact_power_of_two(900), e -= 900;
  while (e < -900) x *= exact_power_of_two(-900), e += 900;
  return x * exact_power_of_two(e);
}

/// num/den (den ≠ 0, not necessarily coprime) in x87 extended precision: numerator and
/// denominator truncated to their top 64 bits (2^-63 each; exact below 2^64) and one rounded
/// division (2^-64): relative error below 2^-61.6 (2^-64 when both fit in 64 bits). Nothing
/// outside the x87 range policy; 0 exactly. Meaningful where extended_precision_compiled
/// (platform.h).
inline std::optional<long double> certified_extended(mpz_srcptr num, mpz_srcptr den) {
  if (mpz_sgn(num) == 0) return 0.0L;
  if (std::labs(binary_magnitude(num, den)) > extended_magnitude_limit) return std::nullopt;
  const TopBits n = top_bits(num), d = top_bits(den);
  const long double v =
      times_power_of_two(static_cast<long double>(n.mantissa) / static_cast<long double>(d.mantissa), n.shift - d.shift);
  return mpz_sgn(num) * mpz_sgn(den) < 0 ? -v : v;
}

/// An integer in x87 extended precision (relative error below 2^-63; exact below 2^64), or
/// nothing outside the x87 range policy (beyond 2^16000: 250 64-bit limbs).
inline std::optional<long double> certified_extended(mpz_srcptr z) {
  if (mpz_sgn(z) == 0) return 0.0L;
  if (static_cast<long>(mpz_sizeinbase(z, 2)) > extended_magnitude_limit) return std::nullopt;
  const TopBits t = top_bits(z);
  const long double v = times_power_of_two(static_cast<long double>(t.mantissa), t.shift);
  return mpz_sgn(z) < 0 ? -v : v;
}

}  // namespace gmcc::numerics
