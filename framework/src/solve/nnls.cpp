#include "hilight/solve/nnls.hpp"

#include <vector>

namespace hilight {

namespace {

/// Least squares restricted to the passive set P: solves (AᵀA)_PP z_P = (Aᵀb)_P.
Eigen::VectorXd passive_solve(const Eigen::MatrixXd& ata, const Eigen::VectorXd& atb, const std::vector<char>& passive) {
  std::vector<int> idx;
  for (int i = 0; i < int(passive.size()); ++i)
    if (passive[i]) idx.push_back(i);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(ata.rows());
  if (idx.empty()) return z;
  const int k = int(idx.size());
  Eigen::MatrixXd sub(k, k);
  Eigen::VectorXd rhs(k);
  for (int r = 0; r < k; ++r) {
    rhs(r) = atb(idx[r]);
    for (int c = 0; c < k; ++c) sub(r, c) = ata(idx[r], idx[c]);
  }
  // Columns can be (nearly) dependent (two unit lights with the same
  // response): a tiny ridge keeps the factorization defined.
  double ridge = 1e-12 * std::max(1e-300, sub.diagonal().maxCoeff());
  sub.diagonal().array() += ridge;
  Eigen::VectorXd sol = sub.ldlt().solve(rhs);
  for (int r = 0; r < k; ++r) z(idx[r]) = sol(r);
  return z;
}

} // namespace

NnlsResult solve_nnls(const Eigen::MatrixXd& ata, const Eigen::VectorXd& atb, double tolerance) {
  const int n = int(atb.size());
  NnlsResult result;
  result.x = Eigen::VectorXd::Zero(n);
  if (n == 0) return result;
  const double tol = tolerance * std::max(1e-300, atb.cwiseAbs().maxCoeff());
  std::vector<char> passive(n, 0);
  Eigen::VectorXd& x = result.x;
  Eigen::VectorXd w = atb;  // gradient of -½‖Ax−b‖²: Aᵀb − AᵀA x
  const int max_iterations = 3 * n + 30;
  while (result.iterations < max_iterations) {
    // Outer loop: move the most promising active variable into P.
    int best = -1;
    double best_w = tol;
    for (int i = 0; i < n; ++i)
      if (!passive[i] && w(i) > best_w) {
        best_w = w(i);
        best = i;
      }
    if (best < 0) break;
    passive[best] = 1;
    ++result.iterations;
    Eigen::VectorXd z = passive_solve(ata, atb, passive);
    // Inner loop: step back to feasibility while some passive z is ≤ 0.
    for (int inner = 0; inner < 3 * n + 30; ++inner) {
      double alpha = 1.0;
      bool infeasible = false;
      for (int i = 0; i < n; ++i)
        if (passive[i] && z(i) <= 0.0) {
          infeasible = true;
          double a = x(i) / (x(i) - z(i));
          alpha = std::min(alpha, a);
        }
      if (!infeasible) break;
      x += alpha * (z - x);
      for (int i = 0; i < n; ++i)
        // Relative to the largest: intensities scale with the scene's size squared.
        if (passive[i] && x(i) <= 1e-15 * x.cwiseAbs().maxCoeff()) {
          passive[i] = 0;
          x(i) = 0.0;
        }
      z = passive_solve(ata, atb, passive);
    }
    x = z;
    w = atb - ata * x;
  }
  result.converged = result.iterations < max_iterations;
  for (int i = 0; i < n; ++i) x(i) = std::max(0.0, x(i));
  return result;
}

} // namespace hilight
