#pragma once
/// \file truncated_quotient.h
/// The quotient x/w of two integers truncated to a double (rounded toward zero), the value
/// mpq_get_d gives for x/w, decided in most cases from the integers' leading bits by one 128-bit
/// by 64-bit division instead of GMP's long division of the whole numbers: what the lazy 3-D
/// feasible set's enclosures and vertex order read (geometry/lazy_convex_set_3.h, docs/math.md
/// §1b "The lazy form").
///
/// Proof. Let |x| = X·2^s + r_x with X in [2^126, 2^127) its leading 127 bits (s may be negative:
/// then X = |x|·2^-s exactly, r_x = 0) and 0 <= r_x < 2^s, and w = W·2^t + r_w likewise with W in
/// [2^63, 2^64). Then ρ = (|x|/w)·2^(t−s) lies in [X/(W+1), (X+1)/W] (the ends are the extreme
/// truncations), a range within [2^62, 2^64]. Truncating a real ρ >= 2^62 to 53 significant bits
/// keeps the top 53 bits of ⌊ρ⌋ (the bits dropped are at least the 9 lowest of ⌊ρ⌋ and all of its
/// fraction), and ⌊ρ⌋ is non-decreasing in ρ: so when ⌊X/(W+1)⌋ and ⌊(X+1)/W⌋ have the same bit
/// length L and the same top 53 bits m, every ρ in the range — the true one among them —
/// truncates to m·2^(L−53), and |x|/w to m·2^(L−53+s−t). That is a double exactly (m < 2^53)
/// when it is a normal number, which the caller's range check ensures (|x/w| within 2^±138,
/// numerics/rational_to_float.h). When the two floors' truncations differ, the range
/// (narrower than 3, as (X+1)/W − X/(W+1) = (X+W+1)/(W(W+1)) with X < 2^127, W >= 2^63) holds
/// exactly one truncation boundary c (⌊ρ⌋ >= 2^62 has at least 63 bits: boundaries are at least
/// 2^10 apart), the truncation of the upper floor,
/// and ρ truncates to it when ρ >= c, that is when |x|·2^(t−s) >= c·w, an exact integer
/// comparison; otherwise to the lower floor's. Only when a quotient would not fit in 64 bits is
/// nothing decided here, and the caller divides exactly.

#include <gmcc/numerics/rational_to_float.h>
#include <gmcc/numerics/wide_multiply.h>

#include <gmp.h>

#include <cmath>
#include <cstdlib>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace gmcc::numerics {

/// The leading `n` bits (n = 64 or 127) of |z| != 0 as high·2^64 + low, and the power of two
/// they stand for (|z| = that·2^shift + r, 0 <= r < 2^shift; shift < 0 when |z| has fewer bits:
/// then exact). Reads at most three limbs, allocates nothing.
struct LeadingBits {
  WideProduct bits;  ///< the leading bits, high·2^64 + low
  long shift;        ///< the power of two they stand for
};
/// The leading `n` bits of |z| (n = 64 or 127; z != 0), as LeadingBits.
inline LeadingBits leading_bits(mpz_srcptr z, int n) {
  const long size = static_cast<long>(mpz_sizeinbase(z, 2));
  const long shift = size - n;
  // Bit i of the result is bit i + shift of |z| (0 below bit 0).
  auto bit_block = [&](long from) -> std::uint64_t {  // bits from..from+63 of |z|
    std::uint64_t out = 0;
    for (long i = from < 0 ? 0 : from; i < from + 64 && i < size;) {
      const long limb = i / GMP_NUMB_BITS, offset = i % GMP_NUMB_BITS;
      const auto word = static_cast<std::uint64_t>(mpz_getlimbn(z, static_cast<mp_size_t>(limb)) >> offset);
      out |= word << (i - from);
      i += GMP_NUMB_BITS - offset;
    }
    return out;
  };
  return {{bit_block(shift + 64), bit_block(shift)}, shift};
}

/// q truncated to its leading 53 bits, as m·2^e (q >= 2^53).
struct Leading53 {
  std::uint64_t m;  ///< the leading 53 bits, 2^52 <= m < 2^53
  int e;            ///< the power of two they stand for
};
/// q's Leading53. \pre q >= 2^53.
inline Leading53 leading_53(std::uint64_t q) {
  int length = 64;
  while (!((q >> (length - 1)) & 1)) --length;
  return {q >> (length - 53), length - 53};
}

/// Two integers kept per thread for truncated_quotient's boundary decision, cleared with the thread
/// (a bare thread_local mpz_t would leak its limbs at every thread's exit).
struct BoundaryScratch {
  /// the two sides of the boundary comparison, |x|·2^(t−s) and c·w
  ///@{
  mpz_t left, right;
  ///@}
  BoundaryScratch() { mpz_init(left), mpz_init(right); }
  ~BoundaryScratch() { mpz_clear(left), mpz_clear(right); }
  BoundaryScratch(const BoundaryScratch&) = delete;
  BoundaryScratch& operator=(const BoundaryScratch&) = delete;
};

/// x/w truncated toward zero to a double, as mpq_get_d gives it (the file comment's proof), or
/// nothing in the two edge cases where a quotient of leading bits would not fit in 64 bits.
/// \pre x != 0, w > 0, and |x/w| within 2^±138.
inline std::optional<double> truncated_quotient(mpz_srcptr x, mpz_srcptr w) {
  static_assert(GMP_NUMB_BITS == 64, "leading_bits reads 64-bit limbs");
  const LeadingBits a = leading_bits(x, 127), b = leading_bits(w, 64);
  const std::uint64_t W = b.bits.low;
  if (W == UINT64_MAX) return std::nullopt;  // W + 1 would not fit
  WideProduct up = a.bits;  // X + 1
  if (++up.low == 0) ++up.high;
  if (!(up.high < W)) return std::nullopt;  // (X + 1)/W would not fit in 64 bits
  const Leading53 lo = leading_53(divide_wide(a.bits, W + 1)), hi = leading_53(divide_wide(up, W));
  Leading53 t = lo;
  if (lo.m != hi.m || lo.e != hi.e) {
    // The range is narrower than 3 and truncation boundaries are 2^e >= 2^10 apart: the one
    // boundary in it is c = m_hi·2^e_hi, and ρ >= c decides, exactly: |x|·2^(t−s) >= c·w.
    thread_local BoundaryScratch scratch;  // kept across calls, freed when the thread ends
    mpz_ptr left = scratch.left, right = scratch.right;
    mpz_abs(left, x);
    mpz_mul_ui(right, w, static_cast<unsigned long>(hi.m));
    const long scale = b.shift - a.shift, e = hi.e;  // t − s, and c's exponent
    if (scale >= 0) mpz_mul_2exp(left, left, static_cast<mp_bitcnt_t>(scale));
    else mpz_mul_2exp(right, right, static_cast<mp_bitcnt_t>(-scale));
    mpz_mul_2exp(right, right, static_cast<mp_bitcnt_t>(e));
    if (mpz_cmp(left, right) >= 0) t = hi;
  }
  const double value = std::ldexp(static_cast<double>(t.m), static_cast<int>(t.e + a.shift - b.shift));
  return mpz_sgn(x) < 0 ? -value : value;
}

/// x/w (w > 0, not necessarily in lowest terms) truncated toward zero to a double — 0 for x = 0 —
/// when its magnitude bits(|x|) − bits(w) is within the range policy's limit − 1 (then the double
/// and its ±2u enclosure are those of the reduced fraction: rational_to_float.h), else nothing:
/// from the leading bits when they decide it (truncated_quotient), else mpq_get_d on a read-only
/// view of (x, w), which truncates the quotient whatever its representation.
inline std::optional<double> truncated_double(mpz_srcptr x, mpz_srcptr w) {
  if (mpz_sgn(x) == 0) return 0.0;
  if (std::labs(binary_magnitude(x, w)) > double_magnitude_limit - 1) return std::nullopt;
  if (const std::optional<double> t = truncated_quotient(x, w)) return t;
  mpq_t q;
  *mpq_numref(q) = *x;
  *mpq_denref(q) = *w;
  return mpq_get_d(q);
}

}  // namespace gmcc::numerics
