#pragma once
/// \file top_bits.h
/// An integer's leading 64 bits, read from GMP's limbs without allocating: what the
/// extended-precision filters turn into `long double` values (docs/math.md §1a′). The one limb
/// reader of gmcc, written for any limb width, with no compiler intrinsic.

#include <gmp.h>

#include <cstddef>
#include <cstdint>

namespace gmcc::numerics {

/// |z| = mantissa·2^shift + r with 0 <= r < 2^shift: the leading 64 bits of |z| (truncated).
/// Exact (shift = 0) when |z| < 2^64; otherwise mantissa >= 2^63, so the relative error of
/// mantissa·2^shift is below 2^-63.
struct TopBits {
  std::uint64_t mantissa = 0;  ///< the leading 64 bits of |z| (all of |z| below 2^64)
  long shift = 0;              ///< the power of two they stand for: max(0, bits(|z|) − 64)
};

/// The leading 64 bits of |z| (TopBits). O(1): at most three limbs are read.
inline TopBits top_bits(mpz_srcptr z) {
  if (mpz_sgn(z) == 0) return {};
  const std::size_t bits = mpz_sizeinbase(z, 2);
  const std::size_t low = bits > 64 ? bits - 64 : 0;  // the first bit kept
  std::uint64_t mantissa = 0;
  std::size_t limb = low / GMP_NUMB_BITS, offset = low % GMP_NUMB_BITS, filled = 0;
  const std::size_t limbs = mpz_size(z);
  while (filled < 64 && limb < limbs) {
    const auto part = static_cast<std::uint64_t>(mpz_getlimbn(z, static_cast<mp_size_t>(limb)) >> offset);
    mantissa |= part << filled;  // bits beyond the 64th fall off: they are below `low` + 64
    filled += GMP_NUMB_BITS - offset;
    offset = 0, ++limb;
  }
  return {mantissa, static_cast<long>(low)};
}

}  // namespace gmcc::numerics
