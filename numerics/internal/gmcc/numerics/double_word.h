#pragma once
/// \file double_word.h
/// Double-word ("double-double") arithmetic: a real number approximated as the unevaluated sum
/// hi + lo of two doubles, |lo| <= ulp(hi)/2, about 106 bits. The algorithms are those of
/// Joldes, Muller and Popescu [Joldes2017DoubleWord], with their proven relative error bounds
/// (u = 2^-53, round to nearest, no underflow or overflow), as corrected and formally checked by
/// Muller and Rideau [Muller2022DoubleWordFormal]:
///
/// | operation | algorithm | relative error bound |
/// |---|---|---|
/// | dw_add_double (DW + double) | Alg. 4, DWPlusFP | 2u² |
/// | dw_mul_double_fma (DW × double) | Alg. 9, DWTimesFP3, with FMA | 2u² |
/// | dw_add (DW + DW) | Alg. 6, AccurateDWPlusDW | 3u² + 13u³ [Muller2022DoubleWordFormal] (the 2017 paper's 3u²/(1 − 4u) had a gap in its proof) |
/// | dw_mul (DW × DW) | Alg. 12, DWTimesDW3, with FMA | 5u² (4u² in [Muller2022DoubleWordFormal]) |
/// | dw_div (DW ÷ DW) | Alg. 17, DWDivDW2 | 15u² + 56u³ (9.8u² in [Muller2022DoubleWordFormal]) |
///
/// Every one of them is below 16u² = 2^-102 relative to the exact result. These functions give
/// the approximation only; the enclosure type DWEnclosure (dw_enclosure.h) adds a rigorous bound
/// for each operation's error. The error-free transformations TwoSum, Fast2Sum (|a| >= |b| or
/// a = 0) and TwoProd (by FMA) are exact [Muller2018Handbook, §4.3, §4.4] whenever nothing
/// overflows and, for TwoProd, the product does not underflow (|a·b| >= 2^-969).
///
/// The code relies on strict IEEE binary64 evaluation (no x87 excess precision, no
/// -ffast-math reassociation): x86-64's SSE2 doubles, and std::fma a true fused multiply-add.

#include <cmath>

namespace gmcc::numerics {

/// A double-word number hi + lo. The operations keep it normalised (hi = RN(hi + lo)).
struct DoubleWord {
  /// the leading and the trailing double; the value is their exact sum
  ///@{
  double hi = 0, lo = 0;
  ///@}
};

/// TwoSum (Knuth; Møller): s + e = a + b exactly, s = RN(a + b) [Muller2018Handbook, Alg. 4.4].
inline DoubleWord two_sum(double a, double b) {
  const double s = a + b;
  const double a1 = s - b, b1 = s - a1;
  return {s, (a - a1) + (b - b1)};
}

/// Fast2Sum (Dekker): s + e = a + b exactly when |a| >= |b| (or a = 0)
/// [Muller2018Handbook, Alg. 4.3].
inline DoubleWord fast_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

/// TwoProd with an FMA: p + e = a·b exactly, p = RN(a·b), when |a·b| >= 2^-969
/// [Muller2018Handbook, Alg. 4.8].
inline DoubleWord two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

/// x + y, [Joldes2017DoubleWord] Algorithm 6 (AccurateDWPlusDW): relative error <= 3u² + 13u³
/// [Muller2022DoubleWordFormal].
inline DoubleWord dw_add(const DoubleWord& x, const DoubleWord& y) {
  const DoubleWord s = two_sum(x.hi, y.hi), t = two_sum(x.lo, y.lo);
  const DoubleWord v = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(v.hi, t.lo + v.lo);
}

/// −x, exact.
inline DoubleWord dw_neg(const DoubleWord& x) { return {-x.hi, -x.lo}; }

/// x × y, [Joldes2017DoubleWord] Algorithm 12 (DWTimesDW3, with FMA): relative error <= 5u².
inline DoubleWord dw_mul(const DoubleWord& x, const DoubleWord& y) {
  const DoubleWord c = two_prod(x.hi, y.hi);
  const double tl0 = x.lo * y.lo;
  const double tl1 = std::fma(x.hi, y.lo, tl0);
  const double cl2 = std::fma(x.lo, y.hi, tl1);
  return fast_two_sum(c.hi, c.lo + cl2);
}

/// x + b for a double b, [Joldes2017DoubleWord] Algorithm 4 (DWPlusFP): relative error <= 2u².
inline DoubleWord dw_add_double(const DoubleWord& x, double b) {
  const DoubleWord s = two_sum(x.hi, b);
  return fast_two_sum(s.hi, x.lo + s.lo);
}

/// x × b for a double b, [Joldes2017DoubleWord] Algorithm 9 (DWTimesFP3, with FMA): relative
/// error <= 2u².
inline DoubleWord dw_mul_double_fma(const DoubleWord& x, double b) {
  const DoubleWord c = two_prod(x.hi, b);
  return fast_two_sum(c.hi, std::fma(x.lo, b, c.lo));
}

/// x × b for a double b, [Joldes2017DoubleWord] Algorithm 7 (DWTimesFP1), the step dw_div uses.
inline DoubleWord dw_mul_double(const DoubleWord& x, double b) {
  const DoubleWord c = two_prod(x.hi, b);
  const double cl2 = x.lo * b;
  const DoubleWord t = fast_two_sum(c.hi, cl2);
  return fast_two_sum(t.hi, t.lo + c.lo);
}

/// x ÷ y (y.hi != 0), [Joldes2017DoubleWord] Algorithm 17 (DWDivDW2): relative error
/// <= 15u² + 56u³.
inline DoubleWord dw_div(const DoubleWord& x, const DoubleWord& y) {
  const double th = x.hi / y.hi;
  const DoubleWord r = dw_mul_double(y, th);
  const double pi_h = x.hi - r.hi, delta_l = x.lo - r.lo;
  const double tl = (pi_h + delta_l) / y.hi;
  return fast_two_sum(th, tl);
}

/// An approximation of √x (x.hi > 0): one Newton step from the correctly rounded √x.hi
/// [Muller2018Handbook, §14.4]. No error bound is claimed for it here: DWEnclosure's sqrt bounds
/// its error a posteriori from the residual x − s², evaluated with the bounds above.
inline DoubleWord dw_sqrt_approx(const DoubleWord& x) {
  const double s = std::sqrt(x.hi);
  const DoubleWord p = two_prod(s, s);
  const double r = ((x.hi - p.hi) - p.lo + x.lo) / (2 * s);
  return fast_two_sum(s, r);
}

}  // namespace gmcc::numerics
