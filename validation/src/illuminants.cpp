#include <gmcc/validation/illuminants.h>

#include <mpfr.h>

#include <stdexcept>

namespace gmcc {
namespace {

Rational q(const char* decimal) { return parse_rational(decimal); }

// x rounded to three decimals, ties away from zero (CIE 15 rounds M1 and M2 this way).
Rational round_3dp(const Rational& x) {
  const Rational scaled = x * 1000;
  mpz_class n = abs(scaled.get_num()), d = scaled.get_den();
  mpz_class r = (2 * n + d) / (2 * d);  // floor(|x|·1000 + 1/2)
  if (sgn(scaled) < 0) r = -r;
  Rational out(r, 1000);
  out.canonicalize();
  return out;
}

}  // namespace

Rational cie_daylight_cct(const Rational& nominal_kelvin) {
  return Rational(nominal_kelvin * q("1.4388") / q("1.438"));
}

Spectrum cie_daylight(const Rational& T, const SpectralTable& basis) {
  if (T < 4000 || T > 25000)
    throw std::domain_error("CIE daylight is defined for 4000 K to 25000 K, not " +
                            to_string(T) + " K");
  const Rational t1 = 1 / T, t2 = t1 * t1, t3 = t2 * t1;
  const Rational x = T <= 7000
      ? Rational(q("-4.6070e9") * t3 + q("2.9678e6") * t2 + q("0.09911e3") * t1 + q("0.244063"))
      : Rational(q("-2.0064e9") * t3 + q("1.9018e6") * t2 + q("0.24748e3") * t1 + q("0.237040"));
  const Rational y = -3 * x * x + q("2.870") * x - q("0.275");
  const Rational M = q("0.0241") + q("0.2562") * x - q("0.7341") * y;
  const Rational M1 = round_3dp((q("-1.3515") - q("1.7703") * x + q("5.9114") * y) / M);
  const Rational M2 = round_3dp((q("0.0300") - q("31.4424") * x + q("30.0717") * y) / M);
  const Spectrum& S0 = basis.spectrum("S0");
  const Spectrum& S1 = basis.spectrum("S1");
  const Spectrum& S2 = basis.spectrum("S2");
  Spectrum out{"CIE daylight " + to_string(T) + " K", basis.wavelengths, {}};
  for (std::size_t i = 0; i < basis.wavelengths.size(); ++i)
    out.values.push_back(Rational(S0.values[i] + M1 * S1.values[i] + M2 * S2.values[i]));
  return out;
}

Spectrum planckian(const Rational& kelvin, const std::vector<Rational>& wavelengths) {
  constexpr mpfr_prec_t bits = 256;
  mpfr_t c2, t, arg, num, den, value;
  mpfr_inits2(bits, c2, t, arg, num, den, value, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_q(c2, q("1.4388e-2").get_mpq_t(), MPFR_RNDN);
  mpfr_set_q(t, kelvin.get_mpq_t(), MPFR_RNDN);
  // exp(c2 / (λ·T)) − 1 with λ in metres, by expm1 for accuracy at high T.
  auto planck_denominator = [&](const Rational& lambda_nm, mpfr_t out) {
    mpfr_set_q(arg, Rational(lambda_nm / 1000000000).get_mpq_t(), MPFR_RNDN);
    mpfr_mul(arg, arg, t, MPFR_RNDN);
    mpfr_div(arg, c2, arg, MPFR_RNDN);
    mpfr_expm1(out, arg, MPFR_RNDN);
  };
  Spectrum out{"Planckian " + to_string(kelvin) + " K", wavelengths, {}};
  planck_denominator(Rational(560), num);
  for (const Rational& l : wavelengths) {
    // 100 · (560/λ)^5 · (exp(c2/(560 nm·T)) − 1) / (exp(c2/(λT)) − 1)
    planck_denominator(l, den);
    mpfr_div(value, num, den, MPFR_RNDN);
    mpfr_set_q(arg, Rational(Rational(560) / l).get_mpq_t(), MPFR_RNDN);
    mpfr_pow_ui(arg, arg, 5, MPFR_RNDN);
    mpfr_mul(value, value, arg, MPFR_RNDN);
    mpfr_mul_ui(value, value, 100, MPFR_RNDN);
    Rational exact;
    mpfr_get_q(exact.get_mpq_t(), value);  // the 256-bit value, exactly
    out.values.push_back(exact);
  }
  mpfr_clears(c2, t, arg, num, den, value, static_cast<mpfr_ptr>(nullptr));
  return out;
}

}  // namespace gmcc
