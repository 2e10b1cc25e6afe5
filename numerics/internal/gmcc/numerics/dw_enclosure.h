#pragma once
/// \file dw_enclosure.h
/// A real number enclosed as mid ± rad with a double-word midpoint (double_word.h) and a double
/// radius: the enclosure kind of the 3-D mean's first stage (docs/math.md §2, "The double-word
/// stage"), about 2^-100 relative per operation where BasicEnclosure gives 2^-53.
///
/// Error analysis (u = 2^-53, round to nearest). Each operation forms the double-word result z
/// of the operation on the midpoints; its error against that exact result is at most 16u²
/// relative to the exact result ([Joldes2017DoubleWord] and [Muller2022DoubleWordFormal]: 3u² +
/// 13u³ for the sum, 5u² for the product, 15u² + 56u³ for the quotient, 2u² for a sum or product
/// with a double; see double_word.h), hence
/// at most 16u²/(1 − 16u²)·|z| < 2^-101·|z|: each operation charges op_error·|z| = 2^-100·|z|,
/// twice that. To it the radius adds the propagated radii (the first-order terms and their
/// product, exact bounds for +, −, ×, ÷ of sets: [Rump1999], §2). The radius itself is
/// evaluated in round to nearest on non-negative numbers, at most 64 operations per result, each
/// of which loses at most a factor (1 − u): round_up's factor (1 + 2^-45) exceeds (1 − u)^-65,
/// so it makes up for all of them. Underflow: the published bounds assume none; an operation
/// that underflows errs by at most 2^-1075 absolutely instead (the standard model with
/// underflow, [Higham2002Accuracy] §2.1), and round_up's added 2^-1000 exceeds 2^60 such errors
/// propagated by factors <= 2. Overflow is not bounded: a result beyond 2^1000 in magnitude, a
/// NaN, or a division or square root whose operand is not certainly away from zero gives an
/// unbounded radius (+inf), which finite() reports and which every later result inherits
/// (inf or NaN), so that a caller asks once, at the end.

#include <gmcc/numerics/double_word.h>
#include <gmcc/numerics/enclosure.h>

#include <cmath>
#include <limits>

/// Marks a function that runs double-word arithmetic: on x86-64 ELF with GCC, and a build not
/// already targeting FMA, it is compiled twice, with and without FMA instructions, and the loader
/// picks the one the processor supports (target_clones); `flatten` inlines every double-word
/// operation into both, so that std::fma is one instruction rather than a call into the C
/// library. std::fma gives the same value in both (exact, then rounded), but GCC also contracts
/// other products and sums (a·b + c) into fused multiply-adds in the FMA clone, which removes a
/// rounding: the enclosures stay enclosures (each error bound covers the unfused operations and
/// keeps its slack), yet an enclosure's last bits, and so which truncations a filter decides, can
/// differ between a processor with FMA and one without; exact results cannot. Elsewhere it marks
/// nothing: in the portable build, and under Clang (the fuzz build, scripts/fuzz), which
/// refuses target_clones together with flatten.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && !defined(__FMA__) && \
    !defined(GMCC_PORTABLE_NUMERICS)
#define GMCC_DW_FMA_CLONES __attribute__((target_clones("fma", "default"), flatten))
#else
#define GMCC_DW_FMA_CLONES
#endif

namespace gmcc::numerics {

/// A real number in [mid − rad, mid + rad], mid a double-word number.
struct DWEnclosure {
  DoubleWord mid;  ///< the midpoint, normalised
  double rad = 0;  ///< the radius, >= 0 (+inf or NaN: no bound)

  /// The relative charge per operation on the result's magnitude: 2^-100 (twice the proven
  /// 16u²/(1 − 16u²) < 2^-101, see the file comment).
  static constexpr double op_error = 0x1p-100;
  /// The largest midpoint magnitude kept (beyond: unbounded radius).
  static constexpr double magnitude_limit = 0x1p1000;

  /// The exact value of a double.
  static DWEnclosure exact(double x) { return {{x, 0}, 0}; }
  /// The exact value of a normalised double-word number.
  static DWEnclosure exact(const DoubleWord& x) { return {x, 0}; }
  /// An enclosure that bounds nothing.
  static DWEnclosure unbounded() { return {{0, 0}, std::numeric_limits<double>::infinity()}; }

  /// A radius evaluated in round to nearest from non-negative terms (at most 64 operations),
  /// made an upper bound for the exact expression (file comment).
  static double round_up(double r) { return r * (1 + 0x1p-45) + 0x1p-1000; }

  /// An upper bound for |mid|, up to the factor (1 + u) that round_up covers.
  double magnitude() const { return std::fabs(mid.hi) + std::fabs(mid.lo); }

  /// Whether the enclosure bounds its value: a finite radius and a midpoint within 2^±1000.
  bool finite() const { return std::fabs(mid.hi) <= magnitude_limit && rad <= std::numeric_limits<double>::max(); }

  /// A certain lower bound of |x| over the enclosure (0 or negative when it may contain 0):
  /// |mid| >= |hi|·(1 − 2^-53) for a normalised midpoint, and each rounded step is pushed down.
  double abs_lower() const {
    return (std::fabs(mid.hi) * (1 - 0x1p-50) - round_up(rad)) * (1 - 0x1p-50) - 0x1p-1000;
  }

  /// A certain upper bound of |x| over the enclosure (+inf when it bounds nothing): |mid| <=
  /// |hi| + |lo|, and each rounded step is pushed up as abs_lower's is pushed down.
  double abs_upper() const {
    if (!finite()) return std::numeric_limits<double>::infinity();
    return (magnitude() * (1 + 0x1p-50) + round_up(rad)) * (1 + 0x1p-50) + 0x1p-1000;
  }
};

/// \name The enclosure family's ends (enclosure.h), in double
/// With them the family's generic questions (sign, certainly_negative) take a DWEnclosure.
///@{
/// A certain lower end: abs_lower when the enclosure lies above 0, else −abs_upper (−inf when it
/// bounds nothing; 0 for the exact zero).
inline double lower(const DWEnclosure& x) {
  if (!x.finite()) return -std::numeric_limits<double>::infinity();
  if (x.rad == 0 && x.mid.hi == 0) return 0;
  if (x.mid.hi > 0) {
    const double a = x.abs_lower();
    if (a > 0) return a;
  }
  return -x.abs_upper();
}
/// A certain upper end, as lower.
inline double upper(const DWEnclosure& x) {
  if (!x.finite()) return std::numeric_limits<double>::infinity();
  if (x.rad == 0 && x.mid.hi == 0) return 0;
  if (x.mid.hi < 0) {
    const double a = x.abs_lower();
    if (a > 0) return -a;
  }
  return x.abs_upper();
}
///@}

/// The enclosure z = result with the charge for its own error and the propagated radius `prop`.
inline DWEnclosure dw_result(const DoubleWord& z, double prop) {
  DWEnclosure e{z, DWEnclosure::round_up(prop + DWEnclosure::op_error * (std::fabs(z.hi) + std::fabs(z.lo)))};
  if (!(std::fabs(z.hi) <= DWEnclosure::magnitude_limit)) e.rad = std::numeric_limits<double>::infinity();
  return e;
}

/// x + y: the radii add.
inline DWEnclosure operator+(const DWEnclosure& x, const DWEnclosure& y) {
  return dw_result(dw_add(x.mid, y.mid), x.rad + y.rad);
}

/// x + b for a double b (exact): the radius carries over.
inline DWEnclosure operator+(const DWEnclosure& x, double b) { return dw_result(dw_add_double(x.mid, b), x.rad); }

/// x × b for a double b (exact): the radius scales by |b|.
inline DWEnclosure operator*(const DWEnclosure& x, double b) {
  return dw_result(dw_mul_double_fma(x.mid, b), std::fabs(b) * x.rad);
}

/// −x, exact.
inline DWEnclosure operator-(const DWEnclosure& x) { return {dw_neg(x.mid), x.rad}; }

/// x − y: the radii add.
inline DWEnclosure operator-(const DWEnclosure& x, const DWEnclosure& y) {
  return dw_result(dw_add(x.mid, dw_neg(y.mid)), x.rad + y.rad);
}

/// x × y: |xy − x̃ỹ| <= |x̃|·r_y + |ỹ|·r_x + r_x·r_y.
inline DWEnclosure operator*(const DWEnclosure& x, const DWEnclosure& y) {
  return dw_result(dw_mul(x.mid, y.mid), x.magnitude() * y.rad + y.magnitude() * x.rad + x.rad * y.rad);
}

/// x², as x × x.
inline DWEnclosure sqr(const DWEnclosure& x) { return x * x; }

/// x ÷ y when |y| is certainly away from 0 (else unbounded): |x/y − x̃/ỹ| <= (r_x + |x̃/ỹ|·r_y)/|y|
/// with |y| >= abs_lower(y) > 0.
inline DWEnclosure operator/(const DWEnclosure& x, const DWEnclosure& y) {
  const double den = y.abs_lower();
  if (!(den > 0x1p-900)) return DWEnclosure::unbounded();
  const DoubleWord z = dw_div(x.mid, y.mid);
  if (x.rad == 0 && y.rad == 0) return dw_result(z, 0);  // exact operands: only the charge
  // |x̃/ỹ| <= |z|·(1 + 2^-101): the factor is one more that round_up's slack covers.
  return dw_result(z, (x.rad + (std::fabs(z.hi) + std::fabs(z.lo)) * y.rad) / den);
}

/// √x when x is certainly positive (else unbounded). The midpoint s = dw_sqrt_approx(x̃) has no
/// a priori bound; it gets one a posteriori: |√x̃ − s| = |x̃ − s²|/(√x̃ + s) <= |x̃ − s²|/s, with
/// x̃ − s² enclosed by the operations above. The radius: |√x − √x̃| = |x − x̃|/(√x + √x̃)
/// <= r_x/(2√L) for L <= x, x̃ the enclosure's certain lower bound.
inline DWEnclosure sqrt(const DWEnclosure& x) {
  const double low = x.abs_lower();
  if (!(x.mid.hi > 0) || !(low > 0x1p-900) || !x.finite()) return DWEnclosure::unbounded();
  const DoubleWord s = dw_sqrt_approx(x.mid);
  const DWEnclosure res = DWEnclosure::exact(x.mid) - sqr(DWEnclosure::exact(s));
  const double s_low = s.hi * (1 - 0x1p-50), root_low = std::sqrt(low) * (1 - 0x1p-50);
  const double r = (res.magnitude() + res.rad) / s_low + x.rad / (2 * root_low);
  return {s, DWEnclosure::round_up(r)};
}

/// Whether every point of x is > 0.
inline bool certainly_positive(const DWEnclosure& x) { return x.finite() && x.mid.hi > 0 && x.abs_lower() > 0; }

/// Whether every point of x is != 0.
inline bool certainly_nonzero(const DWEnclosure& x) { return x.finite() && x.abs_lower() > 0; }

}  // namespace gmcc::numerics
