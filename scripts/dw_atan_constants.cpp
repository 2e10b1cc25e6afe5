// Prints the double-word constants of numerics/dw_atan.h: atan(k/128), k = 0..128, 1/(2j+1),
// j = 1..6, and pi/2, each as (hi, lo) = (RN(v), RN(v - hi)) from MPFR at 400 bits.
#include <mpfr.h>
#include <cstdio>
static void split(mpfr_t v, double& hi, double& lo) {
  mpfr_t t; mpfr_init2(t, 400);
  hi = mpfr_get_d(v, MPFR_RNDN);
  mpfr_sub_d(t, v, hi, MPFR_RNDN);
  lo = mpfr_get_d(t, MPFR_RNDN);
  mpfr_clear(t);
}
int main() {
  mpfr_t v; mpfr_init2(v, 400);
  double hi, lo;
  std::printf("atan table\n");
  for (int k = 0; k <= 128; ++k) {
    mpfr_set_si(v, k, MPFR_RNDN); mpfr_div_si(v, v, 128, MPFR_RNDN); mpfr_atan(v, v, MPFR_RNDN);
    split(v, hi, lo); std::printf("    {%a, %a},\n", hi, lo);
  }
  std::printf("odd reciprocals\n");
  for (int j = 1; j <= 7; ++j) {
    mpfr_set_si(v, 1, MPFR_RNDN); mpfr_div_si(v, v, 2 * j + 1, MPFR_RNDN);
    split(v, hi, lo); std::printf("    {%a, %a},  // 1/%d\n", hi, lo, 2 * j + 1);
  }
  mpfr_const_pi(v, MPFR_RNDN); mpfr_div_2ui(v, v, 1, MPFR_RNDN);
  split(v, hi, lo); std::printf("pi/2 {%a, %a}\n", hi, lo);
}
