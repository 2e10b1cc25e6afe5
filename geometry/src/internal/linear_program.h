#pragma once
// An exact linear program over the rationals: CGAL's QP solver (Fischer & Gärtner's exact
// simplex; <CGAL/QP_functions.h>) on integer-scaled rows, behind a plain interface. Internal to
// gmcc::geometry; implemented in feasible_set_3d.cpp, the library's 3-D CGAL translation unit.

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
};

enum class LpStatus { optimal, infeasible, unbounded };

struct LpSolution {
  LpStatus status = LpStatus::infeasible;
  std::vector<Rational> x;  ///< an optimal vertex (optimal only)
  Rational value;           ///< c·x (optimal only)
  /// For each row, whether its multiplier in the solver's optimality certificate is non-zero:
  /// by complementary slackness such a row is tight at *every* optimal x (optimal only).
  std::vector<bool> tight_in_every_optimum;
};

/// Solve exactly. Complexity: the simplex method on (rows × variables); small in gmcc's uses.
LpSolution solve_linear_program(const LinearProgram& lp);

}  // namespace gmcc::internal
