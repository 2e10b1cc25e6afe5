// The library's 3-D CGAL translation unit (MATH §3c, §3e): exact LP (CGAL QP solver), exact 3-D
// hulls and half-space intersection. Heavy includes stay here, behind plain interfaces.
#include "internal/linear_program.h"

#include <CGAL/Gmpz.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <stdexcept>

namespace gmcc {
namespace internal {
namespace {
mpz_class to_mpz(const CGAL::Gmpz& z) { return mpz_class(z.mpz()); }
CGAL::Gmpz to_gmpz(const mpz_class& z) { return CGAL::Gmpz(z.get_mpz_t()); }

// The integer row k·(a, b) for k the lcm of the denominators: same half-space, integer data.
std::vector<mpz_class> integer_row(const std::vector<Rational>& a, const Rational* b) {
  mpz_class l = 1;
  for (const Rational& x : a) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), x.get_den_mpz_t());
  if (b) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), b->get_den_mpz_t());
  std::vector<mpz_class> out;
  for (const Rational& x : a) out.push_back(mpz_class(x.get_num() * (l / x.get_den())));
  if (b) out.push_back(mpz_class(b->get_num() * (l / b->get_den())));
  return out;
}
}  // namespace

LpSolution solve_linear_program(const LinearProgram& lp) {
  using Program = CGAL::Quadratic_program<CGAL::Gmpz>;
  const int n = static_cast<int>(lp.variables);
  if (lp.objective.size() != lp.variables || lp.rows.size() != lp.rhs.size())
    throw std::invalid_argument("solve_linear_program: inconsistent sizes");
  Program qp(CGAL::SMALLER, false, 0, false, 0);  // rows <=, variables free
  for (std::size_t i = 0; i < lp.rows.size(); ++i) {
    if (lp.rows[i].size() != lp.variables)
      throw std::invalid_argument("solve_linear_program: row of the wrong length");
    const std::vector<mpz_class> r = integer_row(lp.rows[i], &lp.rhs[i]);
    for (int j = 0; j < n; ++j)
      if (sgn(r[j]) != 0) qp.set_a(j, static_cast<int>(i), to_gmpz(r[j]));
    qp.set_b(static_cast<int>(i), to_gmpz(r[n]));
  }
  // A positive multiple of c has the same minimisers; the value is recomputed exactly below.
  const std::vector<mpz_class> c = integer_row(lp.objective, nullptr);
  for (int j = 0; j < n; ++j)
    if (sgn(c[j]) != 0) qp.set_c(j, to_gmpz(c[j]));
  // Make every variable known to the program even when no row or objective term mentions it.
  for (int j = 0; j < n; ++j) qp.set_l(j, false, 0), qp.set_u(j, false, 0);

  const CGAL::Quadratic_program_solution<CGAL::Gmpz> s =
      CGAL::solve_linear_program(qp, CGAL::Gmpz());
  LpSolution out;
  if (s.is_infeasible()) return out;
  if (s.is_unbounded()) {
    out.status = LpStatus::unbounded;
    return out;
  }
  out.status = LpStatus::optimal;
  auto v = s.variable_values_begin();
  for (int j = 0; j < n; ++j, ++v) {
    Rational x(to_mpz(v->numerator()), to_mpz(v->denominator()));
    x.canonicalize();
    out.x.push_back(x);
  }
  out.value = 0;
  for (int j = 0; j < n; ++j) out.value += lp.objective[j] * out.x[j];
  for (auto it = s.optimality_certificate_numerators_begin();
       it != s.optimality_certificate_numerators_end(); ++it)
    out.tight_in_every_optimum.push_back(CGAL::sign(*it) != CGAL::ZERO);
  out.tight_in_every_optimum.resize(lp.rows.size(), false);
  return out;
}

}  // namespace internal
}  // namespace gmcc
