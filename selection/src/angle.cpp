#include <gmcc/numerics/constants.h>

#include "internal/angle.h"

#include "internal/ld_interval.h"

#include <mpfr.h>

#include <cmath>
#include <optional>

namespace gmcc::internal {
namespace {

// 180/π as an enclosure (the nearest long double to π is within half an ulp, 2^-63, of it).
const LDInterval degrees_per_radian_ld =
    LDInterval{180.0L, 180.0L} / LDInterval{numerics::pi - 0x1p-62L, numerics::pi + 0x1p-62L};

double angle_mpfr(const std::array<Rational, 3>& u_exact, const std::array<Rational, 3>& v_exact) {
  constexpr mpfr_prec_t bits = 160;
  mpfr_t u[3], v[3], t, s, cross2, dot, a;
  for (int k = 0; k < 3; ++k) {
    mpfr_init2(u[k], bits);
    mpfr_init2(v[k], bits);
    mpfr_set_q(u[k], u_exact[k].get_mpq_t(), MPFR_RNDN);
    mpfr_set_q(v[k], v_exact[k].get_mpq_t(), MPFR_RNDN);
  }
  mpfr_inits2(bits, t, s, cross2, dot, a, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_zero(cross2, 1);
  for (int k = 0; k < 3; ++k) {  // (u×v)_k = u_i v_j − u_j v_i
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mpfr_mul(t, u[i], v[j], MPFR_RNDN);
    mpfr_mul(s, u[j], v[i], MPFR_RNDN);
    mpfr_sub(t, t, s, MPFR_RNDN);
    mpfr_fma(cross2, t, t, cross2, MPFR_RNDN);
  }
  mpfr_sqrt(cross2, cross2, MPFR_RNDN);
  mpfr_mul(dot, u[0], v[0], MPFR_RNDN);
  mpfr_fma(dot, u[1], v[1], dot, MPFR_RNDN);
  mpfr_fma(dot, u[2], v[2], dot, MPFR_RNDN);
  mpfr_atan2(a, cross2, dot, MPFR_RNDN);
  mpfr_const_pi(t, MPFR_RNDN);
  mpfr_mul_ui(a, a, 180, MPFR_RNDN);
  mpfr_div(a, a, t, MPFR_RNDN);
  const double deg = mpfr_get_d(a, MPFR_RNDN);
  mpfr_clears(t, s, cross2, dot, a, static_cast<mpfr_ptr>(nullptr));
  for (int k = 0; k < 3; ++k) mpfr_clear(u[k]), mpfr_clear(v[k]);
  return deg;
}

}  // namespace

namespace {
bool tight_degrees(const LDInterval& deg) { return deg.hi - deg.lo <= std::ldexp(deg.lo, -56); }
double midpoint(const LDInterval& deg) { return static_cast<double>(deg.lo + (deg.hi - deg.lo) / 2); }

// (u×v)_k = u_i v_j − u_j v_i enclosed from its exact value n/d, formed by integer
// cross-multiplication (no gcd): accurate however small the angle, unlike the difference of two
// enclosed products.
LDInterval exact_cross(const Rational& ui, const Rational& vj, const Rational& uj, const Rational& vi) {
  const mpz_class d1 = ui.get_den() * vj.get_den(), d2 = uj.get_den() * vi.get_den();
  const mpz_class n = ui.get_num() * vj.get_num() * d2 - uj.get_num() * vi.get_num() * d1;
  const mpz_class d = d1 * d2;
  return enclose_ld(n.get_mpz_t(), d.get_mpz_t());
}
}  // namespace

LDInterval angle_deg_enclosure(const std::array<Rational, 3>& u_exact, const std::array<Rational, 3>& v_exact) {
  std::array<LDInterval, 3> u, v;
  for (int k = 0; k < 3; ++k) u[k] = enclose_ld(u_exact[k]), v[k] = enclose_ld(v_exact[k]);
  return angle_deg_enclosure(u, v);
}

namespace {
// |u×v|², summed from its components c(k, i, j) = u_i v_j − u_j v_i, however they are enclosed.
template <class Component>
LDInterval cross2_from(Component c) {
  LDInterval cross2{0, 0};
  for (int k = 0; k < 3; ++k) {
    const LDInterval ck = c((k + 1) % 3, (k + 2) % 3);
    cross2 = cross2 + ck * ck;
  }
  return cross2;
}
LDInterval cross2(const std::array<LDInterval, 3>& u, const std::array<LDInterval, 3>& v) {
  return cross2_from([&](int i, int j) { return u[i] * v[j] - u[j] * v[i]; });
}
LDInterval dot(const std::array<LDInterval, 3>& u, const std::array<LDInterval, 3>& v) {
  return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
}
// The angle's midpoint when cross2 is bounded away from 0 and the enclosure pins it to 2^-56.
std::optional<double> tight_angle(const LDInterval& cross2, const LDInterval& dot) {
  if (!(cross2.lo > 0)) return std::nullopt;
  const LDInterval deg = atan2(sqrt(cross2), dot) * degrees_per_radian_ld;
  if (!tight_degrees(deg)) return std::nullopt;
  return midpoint(deg);
}
}  // namespace

LDInterval angle_deg_enclosure(const std::array<LDInterval, 3>& u, const std::array<LDInterval, 3>& v) {
  return atan2(sqrt(cross2(u, v)), dot(u, v)) * degrees_per_radian_ld;
}

// ray_angle_deg's proof. Let θ be the exact angle (degrees) between the rays, the same for any
// positive multiples, and deg an enclosure of θ from the multiples given. angle_deg(ray(u), ray(v))
// returns round(y), round the nearest double, where, for θ >= 2^-40:
// - on its x87 stages, y is the long double midpoint of an enclosure [lo', hi'] of θ with
//   hi' − lo' <= lo'·2^-56 (tight_degrees), so |y − θ| <= 2^-56·θ;
// - on its MPFR stage (x87 off, or neither x87 stage tight), y is θ within 2^-148 (the inputs
//   rounded to 160 bits move each cross product component by at most 2^-155|u||v| and the dot
//   product by 2^-157|u||v|, so atan2 moves by at most 2^-154 rad, as s² + d² = |u|²|v|²; the
//   later roundings are 2^-159 relative), below 2^-56·θ;
// - u = v, or parallel rays, give θ = 0 (excluded) or exactly 180.
// So y ∈ [θ(1 − 2^-56), θ(1 + 2^-56)] ⊂ [L, H] below; when L and H round to the same double,
// so does every number between them (rounding is monotone), y among them.
std::optional<double> ray_angle_deg(const std::array<const mpz_class*, 3>& u_int,
                                    const std::array<const mpz_class*, 3>& v_int) {
  if (!numerics::extended_precision_active()) return std::nullopt;
  static const mpz_class one = 1;
  std::array<LDInterval, 3> u, v;
  for (int k = 0; k < 3; ++k)
    u[k] = enclose_ld(u_int[k]->get_mpz_t(), one.get_mpz_t()), v[k] = enclose_ld(v_int[k]->get_mpz_t(), one.get_mpz_t());
  const LDInterval c2 = cross2(u, v);
  if (!(c2.lo > 0)) return std::nullopt;
  const LDInterval deg = atan2(sqrt(c2), dot(u, v)) * degrees_per_radian_ld;
  if (!(deg.lo >= 0x1p-40L) || !std::isfinite(deg.hi)) return std::nullopt;
  // Each subtraction or addition rounds by at most 2^-64 relative, and angle_deg's midpoint by
  // 2^-63: within the extra 2^-60.
  const long double lo = deg.lo - std::ldexp(deg.lo, -56) - std::ldexp(deg.lo, -60);
  const long double hi = deg.hi + std::ldexp(deg.hi, -56) + std::ldexp(deg.hi, -60);
  const double a = static_cast<double>(lo), b = static_cast<double>(hi);
  if (a != b) return std::nullopt;
  return a;
}

double angle_deg(const std::array<Rational, 3>& u_exact, const std::array<Rational, 3>& v_exact) {
  if (u_exact == v_exact) return 0;  // what the MPFR route returns for them, exactly
  if (numerics::extended_precision_active()) {
    std::array<LDInterval, 3> u, v;
    for (int k = 0; k < 3; ++k) u[k] = enclose_ld(u_exact[k]), v[k] = enclose_ld(v_exact[k]);
    const LDInterval d = dot(u, v);
    if (const auto deg = tight_angle(cross2(u, v), d)) return *deg;
    // Small angles: the cross product from its exact value.
    const LDInterval exact2 =
        cross2_from([&](int i, int j) { return exact_cross(u_exact[i], v_exact[j], u_exact[j], v_exact[i]); });
    if (const auto deg = tight_angle(exact2, d)) return *deg;
  }
  // Parallel vectors (u×v = 0 exactly): 0 or 180 degrees exactly, where the rounded 160-bit
  // inputs would leave a cross product of round-off.
  bool parallel = true;
  for (int k = 0; k < 3 && parallel; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    parallel = u_exact[i] * v_exact[j] == u_exact[j] * v_exact[i];
  }
  if (parallel) return u_exact[0] * v_exact[0] + u_exact[1] * v_exact[1] + u_exact[2] * v_exact[2] >= 0 ? 0.0 : 180.0;
  return angle_mpfr(u_exact, v_exact);
}

}  // namespace gmcc::internal
