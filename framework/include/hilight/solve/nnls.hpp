#pragma once
/// Non-negative least squares, min ‖Ax − b‖ s.t. x ≥ 0, by the active-set
/// method of Lawson & Hanson in the "fast" form of Bro & de Jong (FNNLS): it
/// works on AᵀA and Aᵀb, so the cost per iteration is independent of the
/// number of rows (samples). Same iterates and result as Lawson–Hanson.
#include <Eigen/Dense>

namespace hilight {

struct NnlsResult {
  Eigen::VectorXd x;
  int iterations = 0;
  bool converged = true;
};

/// `ata` = AᵀA (n×n, symmetric PSD), `atb` = Aᵀb. `tolerance` is relative to
/// the largest |Aᵀb|.
NnlsResult solve_nnls(const Eigen::MatrixXd& ata, const Eigen::VectorXd& atb, double tolerance = 1e-10);

} // namespace hilight
