// The exact LP behind CRULE and min-violation (docs/math.md §1b "The exact LP"): constraint
// generation against one simplex run over every row, on seeded programs built to be degenerate
// (many rows through one vertex, repeated rows, rows tight on a whole face), the kind that made
// CGAL's default pivoting rule cycle. Both routes must agree on the status and the optimal value,
// each optimum must satisfy every row, and a row either route calls tight in every optimum must be
// tight at the other route's optimum too.
#include "../test_support.h"

#include "internal/linear_program.h"

#include <boost/test/unit_test.hpp>

using namespace gmcc;
using gmcc::test::Rng;
using R = Rational;

namespace {

R row_value(const std::vector<R>& row, const std::vector<R>& x) {
  R s = 0;
  for (std::size_t j = 0; j < row.size(); ++j) s += row[j] * x[j];
  return s;
}

// The max-slack program of a random polytope in 3 variables (plus the slack), shaped like the one
// feasible_set_3d solves: a box, and rows a·d + s <= b of which many pass through one point p
// (a degenerate vertex) and some repeat. `flat` adds a pair of opposite rows meeting on a plane
// through p (s* = 0: an implicit equality).
internal::LinearProgram slack_program(Rng& rng, int rows, bool flat) {
  internal::LinearProgram lp;
  lp.variables = 4;
  lp.objective = {0, 0, 0, -1};
  const std::vector<R> p{test::random_rational(rng, 1, 5, 3), test::random_rational(rng, 1, 5, 3),
                         test::random_rational(rng, 1, 5, 3)};
  for (int k = 0; k < 3; ++k) {  // box 0 <= d_k <= 10
    std::vector<R> lo(4, R(0)), hi(4, R(0));
    lo[k] = -1, lo[3] = 1, hi[k] = 1, hi[3] = 1;
    lp.initial.push_back(lp.rows.size()), lp.rows.push_back(lo), lp.rhs.push_back(0);
    lp.initial.push_back(lp.rows.size()), lp.rows.push_back(hi), lp.rhs.push_back(10);
  }
  for (int i = 0; i < rows; ++i) {
    std::vector<R> a{test::random_rational(rng, -6, 6, 2), test::random_rational(rng, -6, 6, 2),
                     test::random_rational(rng, -6, 6, 2), R(1)};
    const std::vector<R> pa{a[0], a[1], a[2]};
    // One row in three through p itself, the rest a little outside it.
    R b = row_value(pa, p) + (i % 3 == 2 ? R(0) : test::random_rational(rng, 1, 3, 4));
    lp.rows.push_back(a), lp.rhs.push_back(b);
    if (i % 7 == 0) lp.rows.push_back(a), lp.rhs.push_back(b);  // a repeat
  }
  if (flat) {  // d_1 + d_2 <= t and -(d_1 + d_2) <= -t through p: F lies in a plane, s* = 0
    const R t = p[0] + p[1];
    lp.rows.push_back({1, 1, 0, 1}), lp.rhs.push_back(t);
    lp.rows.push_back({-1, -1, 0, 1}), lp.rhs.push_back(R(-t));
  }
  lp.rows.push_back({0, 0, 0, 1}), lp.rhs.push_back(1);
  lp.initial.push_back(lp.rows.size() - 1);
  return lp;
}

void check_optimum(const internal::LinearProgram& lp, const internal::LpSolution& s) {
  BOOST_REQUIRE(s.x.size() == lp.variables);
  BOOST_REQUIRE(s.tight_in_every_optimum.size() == lp.rows.size());
  for (std::size_t i = 0; i < lp.rows.size(); ++i) BOOST_TEST(row_value(lp.rows[i], s.x) <= lp.rhs[i]);
  BOOST_TEST(s.value == row_value(lp.objective, s.x));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(exact_linear_program)

BOOST_AUTO_TEST_CASE(constraint_generation_agrees_with_every_row_at_once) {
  Rng rng(1313);
  int optimal = 0, flat = 0, with_rounds = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const bool is_flat = trial % 4 == 3;
    internal::LinearProgram generated = slack_program(rng, 20 + 10 * (trial % 8), is_flat);
    internal::LinearProgram whole = generated;
    whole.initial.clear();
    const internal::LpSolution a = internal::solve_linear_program(generated);
    const internal::LpSolution b = internal::solve_linear_program(whole);
    BOOST_TEST(static_cast<int>(a.status) == static_cast<int>(b.status));
    if (a.status != internal::LpStatus::optimal || b.status != internal::LpStatus::optimal) continue;
    ++optimal;
    check_optimum(generated, a);
    check_optimum(whole, b);
    BOOST_TEST(a.value == b.value);
    for (std::size_t i = 0; i < generated.rows.size(); ++i) {
      if (a.tight_in_every_optimum[i]) BOOST_TEST(row_value(generated.rows[i], b.x) == generated.rhs[i]);
      if (b.tight_in_every_optimum[i]) BOOST_TEST(row_value(generated.rows[i], a.x) == generated.rhs[i]);
    }
    if (is_flat) {
      ++flat;
      BOOST_TEST(sgn(a.value) == 0);  // p is feasible and the plane allows no slack: s* = 0
    }
    // The box alone leaves rows violated: constraint generation really took rounds.
    with_rounds += a.x != b.x || generated.rows.size() > 64;
  }
  BOOST_TEST(optimal == 60);
  BOOST_TEST(flat == 15);
  BOOST_TEST(with_rounds > 0);
}

BOOST_AUTO_TEST_CASE(infeasible_and_unbounded_subsets) {
  // x <= -1 and -x <= -1 (x >= 1): infeasible, whatever the start.
  internal::LinearProgram lp;
  lp.variables = 1;
  lp.objective = {1};
  lp.rows = {{R(1)}, {R(-1)}};
  lp.rhs = {R(-1), R(-1)};
  lp.initial = {0};
  BOOST_TEST((internal::solve_linear_program(lp).status == internal::LpStatus::infeasible));
  // minimise x with x >= 2 known only to the rows not in the start: the start is unbounded, the
  // solver falls back to every row and finds x = 2.
  lp.rows = {{R(1)}, {R(-1)}};
  lp.rhs = {R(5), R(-2)};
  lp.initial = {0};
  const internal::LpSolution s = internal::solve_linear_program(lp);
  BOOST_TEST((s.status == internal::LpStatus::optimal));
  BOOST_TEST(s.x.at(0) == R(2));
  BOOST_TEST(s.tight_in_every_optimum.at(1));
  BOOST_TEST(!s.tight_in_every_optimum.at(0));
}

BOOST_AUTO_TEST_SUITE_END()
