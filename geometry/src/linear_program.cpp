// The exact LP behind internal/linear_program.h: CGAL's QP solver (Fischer & Gärtner's exact
// simplex) on integer-scaled rows, with Bland's rule and constraint generation (docs/math.md §1b
// "The exact LP"). A CGAL translation unit of its own, used by feasible_set_3d and min_violation.
#include "internal/linear_program.h"
#include <gmcc/numerics/filtered_sign.h>

#include <gmcc/geometry/integers_over_lcm.h>

#include <CGAL/Gmpz.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace gmcc {
namespace internal {
namespace {
mpz_class to_mpz(const CGAL::Gmpz& z) { return mpz_class(z.mpz()); }
CGAL::Gmpz to_gmpz(const mpz_class& z) { return CGAL::Gmpz(z.get_mpz_t()); }

// The integer row k·(a, b) for k the lcm of the denominators: same half-space, integer data.
std::vector<mpz_class> integer_row(const std::vector<Rational>& a, const Rational* b) {
  mpz_class l = lcm_of_denominators(a);
  if (b) include_denominator(l, *b);
  std::vector<mpz_class> out;
  for (const Rational& x : a) out.push_back(times_lcm(x, l));
  if (b) out.push_back(times_lcm(*b, l));
  return out;
}
}  // namespace

namespace {
// One exact simplex run (Bland's rule) on the rows `take` of `lp`; the certificate is indexed like
// `take`.
LpSolution solve_rows(const LinearProgram& lp, const std::vector<std::size_t>& take) {
  using Program = CGAL::Quadratic_program<CGAL::Gmpz>;
  const int n = static_cast<int>(lp.variables);
  Program qp(CGAL::SMALLER, false, 0, false, 0);  // rows <=, variables free
  for (std::size_t t = 0; t < take.size(); ++t) {
    const std::vector<mpz_class> r = integer_row(lp.rows[take[t]], &lp.rhs[take[t]]);
    for (int j = 0; j < n; ++j)
      if (sgn(r[j]) != 0) qp.set_a(j, static_cast<int>(t), to_gmpz(r[j]));
    qp.set_b(static_cast<int>(t), to_gmpz(r[n]));
  }
  // A positive multiple of c has the same minimisers; the value is recomputed exactly below.
  const std::vector<mpz_class> c = integer_row(lp.objective, nullptr);
  for (int j = 0; j < n; ++j)
    if (sgn(c[j]) != 0) qp.set_c(j, to_gmpz(c[j]));
  // Make every variable known to the program even when no row or objective term mentions it.
  for (int j = 0; j < n; ++j) qp.set_l(j, false, 0), qp.set_u(j, false, 0);

  CGAL::Quadratic_program_options options;
  options.set_pricing_strategy(CGAL::QP_BLAND);  // no cycling: a finite number of pivots
  const CGAL::Quadratic_program_solution<CGAL::Gmpz> s =
      CGAL::solve_linear_program(qp, CGAL::Gmpz(), options);
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
  out.tight_in_every_optimum.resize(take.size(), false);
  return out;
}
}  // namespace

namespace {

// A double filter for the rows' violation test, its bound proved here: each coefficient and
// right-hand side as mpq_get_d truncates it (relative error below 2u), used only when every
// non-zero one lies in [2^-400, 2^400] (then every product below is a normal double). For a point
// x with the same property, a row's excess Σ a_j·x_j − b computed in doubles over n = variables
// terms has |s~ − s| <= (5.1u + (n + 1)·u)·T + O(u²) with T = Σ|a_j·x_j| + |b| (each product of
// two inputs within 2u each, rounded once; then n additions), below 16u·T~ for n <= 8. A row
// with s~ < −16u·T~ certainly holds at x and is passed over; every other row is tested exactly,
// so the rows found violated, and so the rounds, are those of the exact test alone.
class RowFilter {
 public:
  explicit RowFilter(const LinearProgram& lp) : n_(lp.variables) {
    if (n_ > 8) return;  // beyond the bound's term count: no filter
    rows_.resize(lp.rows.size() * (n_ + 1));
    usable_.assign(lp.rows.size(), 1);
    for (std::size_t i = 0; i < lp.rows.size(); ++i) {
      for (std::size_t j = 0; j <= n_; ++j) {
        const Rational& v = j < n_ ? lp.rows[i][j] : lp.rhs[i];
        const std::optional<double> d = in_range(v);
        if (!d) usable_[i] = 0;
        else rows_[i * (n_ + 1) + j] = *d;
      }
    }
  }
  // x as doubles, when every coordinate is in the filter's range.
  static std::optional<std::vector<double>> point(const std::vector<Rational>& x) {
    std::vector<double> d;
    for (const Rational& v : x) {
      const std::optional<double> e = in_range(v);
      if (!e) return std::nullopt;
      d.push_back(*e);
    }
    return d;
  }
  bool certainly_satisfied(std::size_t i, const std::vector<double>& x) const {
    if (usable_.empty() || !usable_[i]) return false;
    const double* r = &rows_[i * (n_ + 1)];
    double s = -r[n_], t = std::fabs(r[n_]);
    for (std::size_t j = 0; j < n_; ++j) {
      const double p = r[j] * x[j];
      s += p, t += std::fabs(p);
    }
    return s < -16 * numerics::unit_roundoff * t;
  }

 private:
  static std::optional<double> in_range(const Rational& v) {
    if (sgn(v) == 0) return 0.0;
    const double d = mpq_get_d(v.get_mpq_t());
    const double m = std::fabs(d);
    if (!(m >= 0x1p-400 && m <= 0x1p400)) return std::nullopt;
    return d;
  }
  std::size_t n_;
  std::vector<double> rows_;
  std::vector<char> usable_;
};

}  // namespace

LpSolution solve_linear_program(const LinearProgram& lp) {
  if (lp.objective.size() != lp.variables || lp.rows.size() != lp.rhs.size())
    throw std::invalid_argument("solve_linear_program: inconsistent sizes");
  for (const std::vector<Rational>& r : lp.rows)
    if (r.size() != lp.variables) throw std::invalid_argument("solve_linear_program: row of the wrong length");
  auto every_row = [&lp] {
    std::vector<std::size_t> all(lp.rows.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    LpSolution s = solve_rows(lp, all);
    s.rows_taken = std::move(all);
    return s;
  };
  if (lp.initial.empty()) return every_row();

  std::vector<bool> taken(lp.rows.size(), false);
  std::vector<std::size_t> take;
  for (std::size_t i : lp.initial) {
    if (i >= lp.rows.size()) throw std::invalid_argument("solve_linear_program: initial row out of range");
    if (!taken[i]) taken[i] = true, take.push_back(i);
  }
  constexpr std::size_t per_round = 64;
  const RowFilter filter(lp);
  std::vector<std::vector<mpz_class>> integers(lp.rows.size());  // integer rows, made when first needed
  for (;;) {
    LpSolution s = solve_rows(lp, take);
    // Infeasible on a subset: infeasible. Unbounded on a subset says nothing: every row at once.
    if (s.status == LpStatus::infeasible) return s;
    if (s.status == LpStatus::unbounded) return every_row();
    const std::optional<std::vector<double>> x = RowFilter::point(s.x);
    // x times the lcm D of its denominators: a row's excess has the sign of its integer row
    // (integer_row) dotted with (X, −D), no gcd.
    const mpz_class D = lcm_of_denominators(s.x);
    std::vector<mpz_class> X;
    for (const Rational& v : s.x) X.push_back(times_lcm(v, D));
    std::vector<std::pair<Rational, std::size_t>> violated;
    for (std::size_t i = 0; i < lp.rows.size(); ++i) {
      if (taken[i] || (x && filter.certainly_satisfied(i, *x))) continue;
      if (integers[i].empty()) integers[i] = integer_row(lp.rows[i], &lp.rhs[i]);
      mpz_class dot = -integers[i][lp.variables] * D;
      for (std::size_t j = 0; j < lp.variables; ++j) dot += integers[i][j] * X[j];
      if (sgn(dot) <= 0) continue;
      Rational excess = -lp.rhs[i];
      for (std::size_t j = 0; j < lp.variables; ++j)
        if (sgn(lp.rows[i][j]) != 0) excess += lp.rows[i][j] * s.x[j];
      if (sgn(excess) > 0) violated.emplace_back(std::move(excess), i);
    }
    if (violated.empty()) {  // optimal for every row; rows never taken have zero multipliers
      std::vector<bool> tight(lp.rows.size(), false);
      for (std::size_t t = 0; t < take.size(); ++t) tight[take[t]] = s.tight_in_every_optimum[t];
      s.tight_in_every_optimum = std::move(tight);
      s.rows_taken = std::move(take);
      return s;
    }
    const std::size_t k = std::min(per_round, violated.size());
    std::partial_sort(violated.begin(), violated.begin() + static_cast<std::ptrdiff_t>(k), violated.end(),
                      [](const auto& a, const auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
    for (std::size_t t = 0; t < k; ++t) taken[violated[t].second] = true, take.push_back(violated[t].second);
  }
}

}  // namespace internal
}  // namespace gmcc
