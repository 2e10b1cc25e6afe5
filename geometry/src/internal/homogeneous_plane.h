#pragma once
// The plane through three points given in homogeneous integer coordinates, in integers without a
// gcd (docs/derivations.md §2.4). Internal to gmcc::geometry.

#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <utility>

namespace gmcc::internal {

// det [a; b; c] of three integer rows, restricted to columns i, j, k.
inline mpz_class det3(const std::array<mpz_class, 4>& a, const std::array<mpz_class, 4>& b,
                      const std::array<mpz_class, 4>& c, std::size_t i, std::size_t j, std::size_t k) {
  mpz_class m, out;
  auto minor = [&](std::size_t u, std::size_t v) {  // b_u c_v − b_v c_u
    mpz_mul(m.get_mpz_t(), b[u].get_mpz_t(), c[v].get_mpz_t());
    mpz_submul(m.get_mpz_t(), b[v].get_mpz_t(), c[u].get_mpz_t());
  };
  minor(j, k);
  mpz_mul(out.get_mpz_t(), a[i].get_mpz_t(), m.get_mpz_t());
  minor(i, k);
  mpz_submul(out.get_mpz_t(), a[j].get_mpz_t(), m.get_mpz_t());
  minor(i, j);
  mpz_addmul(out.get_mpz_t(), a[k].get_mpz_t(), m.get_mpz_t());
  return out;
}

// The plane n·x = c through the points a = A/W_a, b, c given as (X, Y, Z, W), W > 0:
// det [A; B; C; (x, 1)] = −x·D_yzw + y·D_xzw − z·D_xyw + D_xyz, and it equals
// −W_a W_b W_c ((b − a) × (c − a))·(x − a); so n = (D_yzw, −D_xzw, D_xyw) = W_a W_b W_c (b − a) × (c − a)
// and c = D_xyz = n·a.
inline std::pair<std::array<mpz_class, 3>, mpz_class> plane_through(const std::array<mpz_class, 4>& a,
                                                                    const std::array<mpz_class, 4>& b,
                                                                    const std::array<mpz_class, 4>& c) {
  return {{det3(a, b, c, 1, 2, 3), mpz_class(-det3(a, b, c, 0, 2, 3)), det3(a, b, c, 0, 1, 3)}, det3(a, b, c, 0, 1, 2)};
}

}  // namespace gmcc::internal
