#pragma once
// An independent high-precision reference for the 3-D mean (Finlayson & Hordley 1999 §3.2; the
// closed form of docs/math.md §2, also docs/math.md §2 "The 3-D mean, three independent routes"):
// plain MPFR at a chosen precision, written from the formula alone (it shares no code with
// selection/src), for the honesty test (tests/selection/test_mean_3d_honesty.cpp) and
// bench/accuracy_sweep.cpp. docs/math.md §2's rule is followed: exact rationals before any rounding,
// and a precision (2048 bits) far beyond the 53 + 2·log2(1/ε) + 20 a width ε needs.
//
// Polygon: p_i = (a_i, b_i, 1), c_i = p_i × p_{i+1}, θ_i = atan2(|c_i|, p_i·p_{i+1}),
// τ = Σ θ_i c_i/|c_i|, map = (τ1/τ3, τ2/τ3). c_i, p_i·p_{i+1} and |c_i|² are formed exactly in
// GMP rationals and only then rounded. Segment [u1, u2]: the perspective of û1 + û2 (docs/math.md §2, degenerate F).
// Point: itself.

#include <gmcc/geometry/convex_set.h>

#include <mpfr.h>

#include <array>

namespace gmcc::test {

/// An owned mpfr_t (RAII; copies keep the precision).
class Mpfr {
 public:
  explicit Mpfr(mpfr_prec_t precision = 53);
  Mpfr(const Mpfr& other);
  Mpfr(Mpfr&& other) noexcept;
  Mpfr& operator=(const Mpfr& other);
  Mpfr& operator=(Mpfr&& other) noexcept;
  ~Mpfr();
  mpfr_ptr get() { return value_; }
  mpfr_srcptr get() const { return value_; }

 private:
  mpfr_t value_;
};

/// Whether |x − ref| ≤ bound, decided with the reference's own uncertainty.
enum class Coverage {
  covered,    ///< |x − ref| + uncertainty ≤ bound
  exceeded,   ///< |x − ref| − uncertainty > bound
  undecided,  ///< within the reference's uncertainty of the bound (never seen; reported)
};

/// The 3-D mean of one convex set at `precision_bits`, per coordinate.
struct Mean3dReference {
  std::array<Mpfr, 2> map;       ///< the two map coordinates (τ1/τ3, τ2/τ3)
  unsigned precision_bits = 0;   ///< P, the precision of the evaluation that was checked
  /// map[k] is the exact value (a point whose coordinate is representable at P bits).
  std::array<bool, 2> exact{};
  /// Relative uncertainty claimed for an inexact map[k]: 2^-(P-200), the tolerance of the
  /// P-vs-2P check (mean_3d_reference_checked). Unchecked references claim the same.
  long uncertainty_log2() const { return -static_cast<long>(precision_bits) + 200; }
  /// The absolute uncertainty of map[k], rounded up: 0 when exact, else 2^-(P-200)·|map[k]|.
  Mpfr uncertainty(int k) const;

  /// The double nearest map[k] (MPFR round to nearest, ties to even).
  double nearest_double(int k) const;
  /// True iff map[k] ± its uncertainty round to the same double (so nearest_double(k) is the
  /// double nearest the true value, not an artefact of the reference's own error).
  bool nearest_is_certain(int k) const;
  /// |x − map[k]| with x taken exactly, subtracted at the reference's precision, rounded up.
  Mpfr abs_error(double x, int k) const;
  /// |x − map[k]| / bound as a double (for reports); +inf when bound is 0 and the error is not.
  double error_ratio(double x, double bound, int k) const;
  /// |x − map[k]| ≤ bound? Exact comparison in MPFR, the reference's uncertainty accounted.
  Coverage covers(double x, double bound, int k) const;
  /// lo ≤ map[k] ≤ hi? `covered` when certainly inside, `exceeded` when certainly outside.
  Coverage inside(double lo, double hi, int k) const;
};

/// One evaluation of the closed form at `precision_bits` (every operation rounded to nearest
/// at that precision). \pre F not empty; F in the closed positive quadrant for polygons (so
/// p_i·p_{i+1} > 0). \throws std::invalid_argument for an empty F.
Mean3dReference mean_3d_reference(const ConvexSet2& F, unsigned precision_bits = 2048);

/// The self-checked reference: evaluated at P and at 2P bits, which must agree within
/// 2^-(P-200) relative per coordinate; returns the 2P evaluation with precision_bits = P (its
/// claimed uncertainty stays 2^-(P-200)). The P-bit error is about 2^-(P-L) for L bits lost to
/// cancellation (L ≈ log2 of edge terms over τ, docs/accuracy.md "Reading"), so the check passes while L < 200
/// whatever P is: about 150 bits for the generator's hardest sets, 233 for a relative width 1e-70.
/// \throws std::runtime_error naming the coordinate and the discrepancy when they do not agree.
Mean3dReference mean_3d_reference_checked(const ConvexSet2& F, unsigned precision_bits = 2048);

}  // namespace gmcc::test
