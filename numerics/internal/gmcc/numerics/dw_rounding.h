#pragma once
/// \file dw_rounding.h
/// The rounding decision of the 3-D mean's double-word stage (docs/math.md "The double-word
/// stage"): whether every point of a DWEnclosure rounds to one and the same double under round
/// to nearest, ties to even (IEEE 754-2008 §4.3.1), and which.
///
/// Proof. Let x̃ = hi + lo be the normalised midpoint (hi = RN(x̃)) and d = hi. The reals that
/// round to d are those in [d − δ⁻, d + δ⁺], δ∓ half the gaps to d's neighbours, the ends
/// included when d's significand is even (a tie goes to the even neighbour) and excluded
/// otherwise. The enclosure is [d + (lo − r), d + (lo + r)]; lo ± r is formed exactly as s + e by
/// TwoSum [Muller2018Handbook, Alg. 4.4], and s = RN(lo ± r), so comparing s with ±δ and, when
/// they are equal, the sign of e compares the exact ends. δ∓ are exact: the difference of two
/// neighbouring normal doubles (Sterbenz's lemma) halved. Only d of magnitude in [2^-1000, 2^1000]
/// is decided (normal neighbours, no overflow); elsewhere, and for an unbounded enclosure, there
/// is no decision.

#include <gmcc/numerics/dw_enclosure.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

namespace gmcc::numerics {

/// A decided rounding: the double every point of the enclosure rounds to, a rigorous bound on
/// its distance to any of them, and the enclosure rounded outward to doubles.
struct DWRounding {
  double value = 0;  ///< the double every point rounds to (round to nearest, ties to even)
  double bound = 0;  ///< an upper bound for |value − x| over the enclosure
  double lo = 0;     ///< a double <= every point of the enclosure
  double hi = 0;     ///< a double >= every point of the enclosure
};

/// The double every point of x rounds to, with its bound and outward enclosure, or nothing when
/// the points do not all round to one double (or x is unbounded, or beyond 2^±1000). The proof
/// is the file comment.
inline std::optional<DWRounding> round_to_double(const DWEnclosure& x) {
  if (!x.finite() || !(x.rad >= 0)) return std::nullopt;
  const DoubleWord m = fast_two_sum(x.mid.hi, x.mid.lo);  // normalised: m.hi = RN(x̃)
  const double d = m.hi, a = std::fabs(d);
  if (!(a >= 0x1p-1000 && a <= 0x1p1000)) return std::nullopt;
  const double up = (std::nextafter(d, INFINITY) - d) / 2, down = (d - std::nextafter(d, -INFINITY)) / 2;
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof bits);
  const bool even = (bits & 1) == 0;
  const DoubleWord top = two_sum(m.lo, x.rad), bottom = two_sum(m.lo, -x.rad);  // exact ends − d
  const bool top_in = top.hi < up || (top.hi == up && (top.lo < 0 || (top.lo == 0 && even)));
  const bool bottom_in = bottom.hi > -down || (bottom.hi == -down && (bottom.lo > 0 || (bottom.lo == 0 && even)));
  if (!top_in || !bottom_in) return std::nullopt;
  DWRounding r;
  r.value = d;
  // |x − d| <= |lo| + r, rounded up by one ulp.
  r.bound = std::nextafter(std::fabs(m.lo) + x.rad, INFINITY);
  const bool above = top.hi > 0 || (top.hi == 0 && top.lo > 0);
  const bool below = bottom.hi < 0 || (bottom.hi == 0 && bottom.lo < 0);
  r.lo = below ? std::nextafter(d, -INFINITY) : d;
  r.hi = above ? std::nextafter(d, INFINITY) : d;
  return r;
}

/// The double every point of x truncates to (rounds toward zero to: what mpq_get_d gives for an
/// exact rational), or nothing when the points do not all truncate to one double, x may contain
/// 0 without being exactly 0, or the double is beyond 2^±1000 (x unbounded included).
///
/// Proof. For x > 0 the truncation is the largest double <= x, so every point of [A, B]
/// truncates to t iff t <= A and B < t⁺ (t's successor). With d = hi the normalised midpoint's
/// leading double and the ends A = d + bottom, B = d + top formed exactly by TwoSum of lo ∓ r (as
/// in round_to_double): when bottom >= 0, A >= d, and t = d if top < d⁺ − d; when top < 0, B < d,
/// and t = d⁻ if bottom >= d⁻ − d; otherwise [A, B] contains d, a truncation boundary, with
/// points on both sides (or A = d = B would have bottom = 0). The gaps d⁺ − d and d − d⁻ are exact
/// (Sterbenz's lemma) for normal d. For x < 0 the same holds for −x with t negated; x = 0 exactly
/// (a zero midpoint and radius) truncates to 0.
inline std::optional<double> truncate_to_double(const DWEnclosure& x) {
  if (!x.finite() || !(x.rad >= 0)) return std::nullopt;
  if (x.mid.hi == 0 && x.mid.lo == 0 && x.rad == 0) return 0.0;
  const bool negative = x.mid.hi < 0;
  const DoubleWord m = fast_two_sum(negative ? -x.mid.hi : x.mid.hi, negative ? -x.mid.lo : x.mid.lo);
  const double d = m.hi;
  if (!(d >= 0x1p-1000 && d <= 0x1p1000)) return std::nullopt;
  const DoubleWord top = two_sum(m.lo, x.rad), bottom = two_sum(m.lo, -x.rad);  // exact ends − d
  const bool bottom_nonnegative = bottom.hi > 0 || (bottom.hi == 0 && bottom.lo >= 0);
  const bool top_negative = top.hi < 0 || (top.hi == 0 && top.lo < 0);
  double t;
  if (bottom_nonnegative) {
    const double up = std::nextafter(d, INFINITY) - d;
    if (!(top.hi < up || (top.hi == up && top.lo < 0))) return std::nullopt;
    t = d;
  } else if (top_negative) {
    const double below = std::nextafter(d, 0.0), down = below - d;  // d⁻ − d < 0
    if (!(bottom.hi > down || (bottom.hi == down && bottom.lo >= 0))) return std::nullopt;
    t = below;
  } else {
    return std::nullopt;
  }
  return negative ? -t : t;
}

}  // namespace gmcc::numerics
