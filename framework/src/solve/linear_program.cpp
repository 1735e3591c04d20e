// Dense linear programs through COIN-OR Clp (solve/linear_program.hpp).
#include "hilight/solve/linear_program.hpp"

#include <ClpSimplex.hpp>
#include <CoinFinite.hpp>
#include <stdexcept>

namespace hilight {

namespace {

/// Clp wants the matrix column by column, zeros left out.
LpSolution run(const LinearProgram& lp, size_t slack_cols, double penalty) {
  if (lp.a.size() != lp.rows * lp.cols || lp.b.size() != lp.rows || lp.c.size() != lp.cols || lp.lo.size() != lp.cols ||
      lp.hi.size() != lp.cols)
    throw std::logic_error("solve_lp: sizes do not match");
  const size_t cols = lp.cols + slack_cols;
  std::vector<CoinBigIndex> start(cols + 1, 0);
  std::vector<int> index;
  std::vector<double> value;
  index.reserve(lp.a.size() / 2);
  value.reserve(lp.a.size() / 2);
  for (size_t j = 0; j < lp.cols; ++j) {
    for (size_t i = 0; i < lp.rows; ++i)
      if (const double v = lp.a[i * lp.cols + j]; v != 0.0) {
        index.push_back(int(i));
        value.push_back(v);
      }
    start[j + 1] = CoinBigIndex(index.size());
  }
  std::vector<double> lo = lp.lo, hi = lp.hi, c = lp.c;
  for (size_t s = 0; s < slack_cols; ++s) {  // one slack per row
    index.push_back(int(s));
    value.push_back(1.0);
    start[lp.cols + s + 1] = CoinBigIndex(index.size());
    lo.push_back(0.0);
    hi.push_back(COIN_DBL_MAX);
    c.push_back(penalty);
  }
  const std::vector<double> row_hi(lp.rows, COIN_DBL_MAX);
  ClpSimplex model;
  model.setLogLevel(0);
  model.loadProblem(int(cols), int(lp.rows), start.data(), index.data(), value.data(), lo.data(), hi.data(), c.data(),
                    lp.b.data(), row_hi.data());
  model.dual();
  LpSolution out;
  if (!model.isProvenOptimal()) return out;
  out.feasible = true;
  out.objective = model.getObjValue();
  const double* x = model.getColSolution();
  out.x.assign(x, x + cols);
  const double* y = model.getRowPrice();
  out.duals.assign(y, y + lp.rows);
  return out;
}

} // namespace

LpSolution solve_lp(const LinearProgram& lp) { return run(lp, 0, 0.0); }

LpSolution solve_lp_with_slack(const LinearProgram& lp, double penalty, double& shortfall) {
  LpSolution s = run(lp, lp.rows, penalty);
  shortfall = 0;
  if (!s.feasible) return s;  // only numerical trouble: slack makes every program feasible
  for (size_t r = 0; r < lp.rows; ++r) shortfall += s.x[lp.cols + r];
  s.x.resize(lp.cols);
  s.objective = 0;
  for (size_t j = 0; j < lp.cols; ++j) s.objective += lp.c[j] * s.x[j];
  return s;
}

} // namespace hilight
