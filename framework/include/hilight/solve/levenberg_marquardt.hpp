#pragma once
/// The damped step both Levenberg–Marquardt loops of the solve take: the
/// reference polish's over every light's geometry and intensity
/// (gauss_newton.hpp) and the spot search's over spots on the bounce held
/// (spot_refinement.hpp). Each builds its own Jacobian (its parameters and
/// model differ); the damping, the tries and λ's schedule are here, each
/// loop's constants in its LevenbergMarquardtDamping.
#include <Eigen/Dense>
#include <algorithm>

namespace hilight {

struct LevenbergMarquardtDamping {
  /// The least diagonal entry λ scales: a parameter with no slope is damped too.
  double diagonal_floor = 1e-30;
  double min_lambda = 1e-9;  ///< λ shrinks after a taken step to no less than this
  double grow = 10.0;        ///< λ's factor after a refused try
  double shrink = 3.0;       ///< λ's divisor after a taken step
  int attempts = 8;          ///< tries per Jacobian
};

/// One Jacobian's step: solves (A + λ·diag(max(A_dd, floor))) δ = b and hands
/// δ to `try_step` (true: taken), λ growing after each refused try, up to
/// `attempts` tries; λ shrinks after the step taken. A is JᵀJ, b the
/// downhill direction (−Jᵀr for J = ∂r). Whether a step was taken.
template <class TryStep>
bool levenberg_marquardt_step(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double& lambda,
                              const LevenbergMarquardtDamping& damping, TryStep&& try_step) {
  for (int attempt = 0; attempt < damping.attempts; ++attempt) {
    Eigen::MatrixXd damped = A;
    for (Eigen::Index d = 0; d < damped.rows(); ++d) damped(d, d) += lambda * std::max(A(d, d), damping.diagonal_floor);
    const Eigen::VectorXd delta = damped.ldlt().solve(b);
    if (try_step(delta)) {
      lambda = std::max(lambda / damping.shrink, damping.min_lambda);
      return true;
    }
    lambda *= damping.grow;
  }
  return false;
}

} // namespace hilight
