// The image-hull prefilter's facet test over the colours (internal/shifted_sieve.h).
#include "internal/shifted_sieve.h"

#include <gmcc/numerics/rational_to_float.h>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define GMCC_SHIFTED_SIEVE_AVX2 1
#endif

namespace gmcc::internal {
namespace {

// Channels >= 0 and in the range where the certificate's relative bounds hold.
bool in_range(const std::array<double, 3>& c) {
  for (double x : c)
    if (!(numerics::in_double_range(x) && x >= 0)) return false;
  return true;
}

std::vector<std::size_t> scalar_route(const std::vector<std::array<double, 4>>& shifted,
                                      const std::vector<std::array<double, 3>>& d) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < d.size(); ++i) {
    bool inside = !shifted.empty() && in_range(d[i]);
    for (std::size_t j = 0; j < shifted.size() && inside; ++j) {
      const std::array<double, 4>& g = shifted[j];
      inside = g[0] * d[i][0] + g[1] * d[i][1] + g[2] * d[i][2] - g[3] < 0;
    }
    if (!inside) out.push_back(i);
  }
  return out;
}

#if GMCC_SHIFTED_SIEVE_AVX2
// The facets as four columns of m values (m a multiple of 4), the padding (0, 0, 0, 1): 0·p − 1 < 0
// for every colour in range, so it certifies nothing and refuses nothing.
__attribute__((target("avx2"))) std::vector<std::size_t> avx2_route(const std::vector<std::array<double, 4>>& shifted,
                                                                    const std::vector<std::array<double, 3>>& d) {
  const std::size_t m = (shifted.size() + 3) / 4 * 4;
  std::vector<double> g(4 * m, 0.0);
  for (std::size_t j = 0; j < m; ++j)
    for (std::size_t k = 0; k < 4; ++k) g[k * m + j] = j < shifted.size() ? shifted[j][k] : k == 3 ? 1.0 : 0.0;
  const double *g0 = g.data(), *g1 = g0 + m, *g2 = g1 + m, *g3 = g2 + m;
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < d.size(); ++i) {
    bool inside = in_range(d[i]);
    const __m256d p0 = _mm256_set1_pd(d[i][0]), p1 = _mm256_set1_pd(d[i][1]), p2 = _mm256_set1_pd(d[i][2]);
    for (std::size_t j = 0; j < m && inside; j += 4) {
      __m256d v = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(g0 + j), p0), _mm256_mul_pd(_mm256_loadu_pd(g1 + j), p1));
      v = _mm256_sub_pd(_mm256_add_pd(v, _mm256_mul_pd(_mm256_loadu_pd(g2 + j), p2)), _mm256_loadu_pd(g3 + j));
      inside = _mm256_movemask_pd(_mm256_cmp_pd(v, _mm256_setzero_pd(), _CMP_LT_OQ)) == 0xF;
    }
    if (!inside) out.push_back(i);
  }
  return out;
}
#endif

}  // namespace

std::vector<std::size_t> not_certified_inside(const std::vector<std::array<double, 4>>& shifted,
                                              const std::vector<std::array<double, 3>>& d, bool simd) {
#if GMCC_SHIFTED_SIEVE_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (simd && avx2 && !shifted.empty()) return avx2_route(shifted, d);
#endif
  (void)simd;
  return scalar_route(shifted, d);
}

}  // namespace gmcc::internal
