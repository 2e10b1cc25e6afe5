#pragma once
// Exact rationals enclosed in double-word enclosures (numerics/dw_enclosure.h), for the 3-D
// mean's double-word stage. Internal to gmcc::selection.

#include <gmcc/geometry/rational.h>
#include <gmcc/numerics/dw_enclosure.h>
#include <gmcc/numerics/top_bits.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace gmcc::internal {

using numerics::DWEnclosure;

namespace dw_detail {
// 64 bits of |z| from bit `low` up (bits beyond |z|'s top read as 0), from GMP's limbs.
inline std::uint64_t bits_from(mpz_srcptr z, std::size_t low) {
  std::uint64_t v = 0;
  std::size_t limb = low / GMP_NUMB_BITS, offset = low % GMP_NUMB_BITS, filled = 0;
  const std::size_t limbs = mpz_size(z);
  while (filled < 64 && limb < limbs) {
    v |= static_cast<std::uint64_t>(mpz_getlimbn(z, static_cast<mp_size_t>(limb)) >> offset) << filled;
    filled += GMP_NUMB_BITS - offset;
    offset = 0, ++limb;
  }
  return v;
}

// 2^e exactly, for |e| <= 1000, from its bits.
inline double power_of_two(int e) {
  const std::uint64_t bits = static_cast<std::uint64_t>(1023 + e) << 52;
  double p;
  std::memcpy(&p, &bits, sizeof p);
  return p;
}

// |z| > 0 as m·2^shift with m an enclosure in [2^63, 2^64) (or |z| itself, shift 0, below 2^64):
// the leading 64 bits M1 (numerics::top_bits) and the next w = min(64, shift) bits M0 at weight
// 2^-w, each split exactly into two doubles (its bits from the 12th up, at most 53, and its low
// 11 bits) and summed in DWEnclosure arithmetic; the bits below M0 (only when shift > 64) are
// below 2^-64 and are charged as the radius 2^-64.
inline DWEnclosure scaled_integer(mpz_srcptr z, long& shift) {
  constexpr std::uint64_t low11 = 0x7FF;
  if (mpz_size(z) == 1 && GMP_NUMB_BITS == 64) {  // one limb: |z| itself, exactly, shift 0
    const auto limb = static_cast<std::uint64_t>(mpz_getlimbn(z, 0));
    shift = 0;
    return DWEnclosure::exact(numerics::fast_two_sum(static_cast<double>(limb & ~low11), static_cast<double>(limb & low11)));
  }
  const numerics::TopBits t = numerics::top_bits(z);
  shift = t.shift;
  const DWEnclosure head = DWEnclosure::exact(numerics::fast_two_sum(
      static_cast<double>(t.mantissa & ~low11), static_cast<double>(t.mantissa & low11)));
  if (t.shift == 0) return head;
  const std::size_t w = t.shift < 64 ? static_cast<std::size_t>(t.shift) : 64;
  std::uint64_t m0 = bits_from(z, static_cast<std::size_t>(t.shift) - w);
  if (w < 64) m0 &= (std::uint64_t(1) << w) - 1;
  const double scale = power_of_two(-static_cast<int>(w));
  DWEnclosure e = head + DWEnclosure::exact(static_cast<double>(m0 & ~low11) * scale);
  e = e + DWEnclosure::exact(static_cast<double>(m0 & low11) * scale);
  if (t.shift > 64) e.rad = DWEnclosure::round_up(e.rad + 0x1p-64);
  return e;
}
}  // namespace dw_detail

/// num/den (den > 0, not necessarily coprime) as a DWEnclosure: both integers' leading 128 bits
/// enclosed (relative 2^-115), one enclosure division, the power of two applied exactly. An
/// unbounded enclosure when the quotient's binary exponent is beyond ±900.
inline DWEnclosure enclose_dw(mpz_srcptr num, mpz_srcptr den) {
  if (mpz_sgn(num) == 0) return DWEnclosure::exact(0.0);
  long sn = 0, sd = 0;
  const DWEnclosure n = dw_detail::scaled_integer(num, sn), d = dw_detail::scaled_integer(den, sd);
  const long e = sn - sd;
  if (e > 900 || e < -900) return DWEnclosure::unbounded();
  DWEnclosure q = n / d;
  if (e != 0) {  // exact scaling: q is within 2^±65
    const double p = dw_detail::power_of_two(static_cast<int>(e));
    q.mid.hi *= p, q.mid.lo *= p, q.rad = DWEnclosure::round_up(q.rad * p);
  }
  return mpz_sgn(num) < 0 ? -q : q;
}

/// An exact rational as a DWEnclosure (enclose_dw of its numerator and denominator).
inline DWEnclosure enclose_dw(const Rational& q) { return enclose_dw(q.get_num_mpz_t(), q.get_den_mpz_t()); }

}  // namespace gmcc::internal
