#pragma once
/// \file dw_integer.h
/// An integer times a power of two as a DWEnclosure (dw_enclosure.h), from its leading 127 bits
/// without allocating: the double-word copy of an exact plane that the 3-D feasible set's lazy
/// vertices are computed from (docs/math.md §1b "The lazy form", docs/derivations.md §4.6).
///
/// Proof of the radius. |z| = X·2^s + r with X its leading 127 bits and 0 <= r < 2^s
/// (truncated_quotient.h's leading_bits; r = 0 when |z| has at most 127 bits). Split X = H·2^74 + R
/// with H its top 53 bits (a double exactly) and R < 2^74 = R1·2^64 + R0; R1·2^64 is exact,
/// RN(R0) errs by at most 2^10 and RN(R1·2^64 + RN(R0)) by at most 2^-53·2^74: below 2^22 in all.
/// So |z| − (H·2^74 + R~)·2^s is below 2^(s+22) + 2^s, and |z| >= 2^(s+126): a relative error
/// below 2^-104. Scaling by 2^(s−E) is exact while nothing underflows; the result
/// is used only when |z|·2^-E >= 2^-900 (a subnormal trailing part then errs by at most 2^-1075,
/// far below the radius's margin of 2^-104·2^-900). Fast2Sum normalises the pair exactly (|H·2^74| >= |RN(R)|).

#include <gmcc/numerics/dw_enclosure.h>
#include <gmcc/numerics/truncated_quotient.h>

#include <gmp.h>

#include <cmath>
#include <cstdint>
#include <optional>

namespace gmcc::numerics {

/// z·2^-E as a DWEnclosure with radius 2^-103·|hi| (over the proven 2^-104, file comment), or
/// nothing when |z|·2^-E is beyond 2^±900 (zero is exact).
inline std::optional<DWEnclosure> dw_integer(mpz_srcptr z, long E) {
  if (mpz_sgn(z) == 0) return DWEnclosure::exact(0.0);
  const long size = static_cast<long>(mpz_sizeinbase(z, 2));
  if (size - E > 900 || size - E < -900) return std::nullopt;
  const LeadingBits x = leading_bits(z, 127);
  const std::uint64_t top = x.bits.high >> 10;                                        // H: bits 74..126
  const std::uint64_t rest_high = x.bits.high & 0x3ff, rest_low = x.bits.low;  // R = rest_high·2^64 + rest_low
  const double r = std::ldexp(static_cast<double>(rest_high), 64) + static_cast<double>(rest_low);
  // Below 2^22 from R in all, a relative 2^-104 of |z| >= 2^126 (file comment).
  const int e = static_cast<int>(x.shift - E);
  const double hi = std::ldexp(static_cast<double>(top), 74 + e), lo = std::ldexp(r, e);
  const double sign = mpz_sgn(z) < 0 ? -1 : 1;
  DWEnclosure out{fast_two_sum(sign * hi, sign * lo), 0};
  out.rad = DWEnclosure::round_up(std::fabs(out.mid.hi) * 0x1p-103);
  return out;
}

}  // namespace gmcc::numerics
