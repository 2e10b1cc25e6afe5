#pragma once
// An exact linear program over the rationals: CGAL's QP solver (Fischer & Gärtner's exact
// simplex; <CGAL/QP_functions.h>) on integer-scaled rows, behind a plain interface. Internal to
// gmcc::geometry; implemented in linear_program.cpp.

#include <gmcc/geometry/rational.h>

#include <cstddef>
#include <vector>

namespace gmcc::internal {

/// minimise c·x subject to rows[i]·x <= rhs[i]; every variable free.
struct LinearProgram {
  std::size_t variables = 0;
  std::vector<std::vector<Rational>> rows;  ///< each of length `variables`
  std::vector<Rational> rhs;
  std::vector<Rational> objective;          ///< c, length `variables`
  /// Rows the solver starts from (constraint generation, below). Empty: every row at once.
  /// Best chosen so that they alone bound the objective (a box); if they do not, the solver
  /// falls back to every row.
  std::vector<std::size_t> initial;
};

enum class LpStatus { optimal, infeasible, unbounded };

struct LpSolution {
  LpStatus status = LpStatus::infeasible;
  std::vector<Rational> x;  ///< an optimal vertex (optimal only)
  Rational value;           ///< c·x (optimal only)
  /// For each row, whether its multiplier in the solver's optimality certificate is non-zero:
  /// by complementary slackness such a row is tight at *every* optimal x (optimal only).
  std::vector<bool> tight_in_every_optimum;
  /// The rows the last simplex run had (every row without `initial`): a warm start for a
  /// related program.
  std::vector<std::size_t> rows_taken;
};

/// Solve exactly, with a guarantee of termination (docs/math.md §1b "The exact LP"):
///  - every simplex run uses Bland's pivoting rule, which cannot cycle (the default rule of
///    CGAL's solver cycled forever on a degenerate CRULE program of 80 Munsell colours);
///  - with `initial` rows, by constraint generation: solve on the rows taken so far, add the
///    rows the optimum violates (the 64 most violated, exactly), repeat. Each round adds at least
///    one row, so at most rows.size() rounds; the last optimum satisfies every row and is optimal
///    for the whole program, and its multipliers (zero for rows never taken) are an optimal dual
///    of the whole program, so `tight_in_every_optimum` keeps its meaning.
/// Complexity: small programs per round instead of one program of every row (the CRULE program
/// has |canonical facets| × |image hull vertices| rows, tens of thousands, of which tens matter).
LpSolution solve_linear_program(const LinearProgram& lp);

}  // namespace gmcc::internal
