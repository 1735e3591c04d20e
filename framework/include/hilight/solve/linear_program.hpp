#pragma once
/// A small dense linear program, solved by COIN-OR Clp (Debian's
/// coinor-libclp-dev): minimise c·x subject to A x ≥ b and lo ≤ x ≤ hi.
/// The illuminance design (solve/illuminance_design.hpp) lives on it:
/// minimum illuminances are lower bounds, total flux the objective.
#include <cstddef>
#include <vector>

namespace hilight {

struct LinearProgram {
  size_t rows = 0, cols = 0;
  std::vector<double> a;       ///< rows × cols, row-major
  std::vector<double> b;       ///< per row: A x ≥ b
  std::vector<double> c;       ///< per column: the cost
  std::vector<double> lo, hi;  ///< per column: bounds
};

struct LpSolution {
  bool feasible = false;
  double objective = 0;
  std::vector<double> x;
  std::vector<double> duals;  ///< per row: d(objective)/d(b), ≥ 0 (what one more unit of a row's bound costs)
};

/// Solves `lp` (dual simplex). Infeasible: feasible = false, x empty.
LpSolution solve_lp(const LinearProgram& lp);

/// Solves `lp` with every row allowed to fall short by a slack s ≥ 0 costing
/// `penalty` per unit: always feasible. `shortfall` receives Σ s (0 when the
/// rows can all be met).
LpSolution solve_lp_with_slack(const LinearProgram& lp, double penalty, double& shortfall);

} // namespace hilight
