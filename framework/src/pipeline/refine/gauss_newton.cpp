#include "hilight/pipeline/gauss_newton.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace hilight {

namespace {

/// Weighted residuals √w_i (Ψ_i − Σ_j l_j φ_j(i)), channel-interleaved, and their squared norm.
double residuals(const SampleSet& s, const std::vector<Rgb>& phi, const Lighting& lights, Eigen::VectorXd& r) {
  const size_t m = s.size();
  r.resize(Eigen::Index(3 * m));
  double sum = 0;
  for (size_t i = 0; i < m; ++i) {
    const double sw = std::sqrt(double(s.weight[i]));
    for (int c = 0; c < 3; ++c) {
      double lit = 0;
      for (size_t j = 0; j < lights.size(); ++j) lit += double(lights[j].intensity[c]) * double(phi[j * m + i][c]);
      const double v = sw * (double(s.target[i][c]) - lit);
      r[Eigen::Index(3 * i + size_t(c))] = v;
      sum += v * v;
    }
  }
  return sum;
}

} // namespace

Lighting gauss_newton_polish(SampleRefineProblem& problem, const Lighting& start, const GaussNewtonSettings& settings) {
  const SampleSet& s = problem.samples();
  const size_t m = s.size(), n = start.size();
  if (n == 0 || m == 0) return start;
  std::vector<size_t> movable;  // point lights: their positions are parameters
  for (size_t j = 0; j < n; ++j)
    if (start[j].type == LightType::Point) movable.push_back(j);
  const size_t np = 3 * movable.size(), p = np + 3 * n;
  const double h = settings.relative_step * double(problem.scale());
  // Positions move along the scene's own axes, not the world's: the
  // Jacobian, its damping and the shadow-edge test then turn with the
  // scene, and a turned scene takes the same steps, turned.
  const glm::mat3 axes = problem.space().rays().own_frame().axes;

  Lighting current = start;
  std::vector<Rgb> phi = problem.responses(current);
  Eigen::VectorXd r;
  double cost = residuals(s, phi, current, r);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < settings.iterations && cost > 0; ++iteration) {
    // Finite differences: every moved copy in one batch, each corrected as its light.
    Lighting moved;
    std::vector<size_t> anchor;
    for (size_t q = 0; q < movable.size(); ++q)
      for (int k = 0; k < 3; ++k) {
        Light l = current[movable[q]];
        l.position += float(h) * axes[k];
        if (auto placed = problem.space().place(l.position)) l.position = *placed;  // along the mount, if there is one
        moved.push_back(l);
        anchor.push_back(movable[q]);
      }
    std::vector<Rgb> moved_phi = moved.empty() ? std::vector<Rgb>{} : problem.responses_as(moved, anchor);
    // J (3m × p): positions in units of h (well scaled), then intensities.
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(Eigen::Index(3 * m), Eigen::Index(p));
    for (size_t i = 0; i < m; ++i) {
      const double sw = std::sqrt(double(s.weight[i]));
      for (int c = 0; c < 3; ++c) {
        const Eigen::Index row = Eigen::Index(3 * i + size_t(c));
        for (size_t q = 0; q < movable.size(); ++q) {
          const size_t j = movable[q];
          for (int k = 0; k < 3; ++k) {
            const double before = double(phi[j * m + i][c]), after = double(moved_phi[(3 * q + size_t(k)) * m + i][c]);
            // A sample whose light jumps over a step of 10⁻⁴ of the diagonal
            // crosses a shadow edge: no slope there, and its spike would
            // swamp the smooth falloff of all the others (a far light then
            // stalls a metre off: the glTF engine's key lights).
            const double d = std::abs(after - before) > settings.jump * std::max(std::abs(before), std::abs(after)) ? 0.0 : after - before;
            J(row, Eigen::Index(3 * q + size_t(k))) = -sw * double(current[j].intensity[c]) * d;
          }
        }
        for (size_t j = 0; j < n; ++j) J(row, Eigen::Index(np + 3 * j + size_t(c))) = -sw * double(phi[j * m + i][c]);
      }
    }
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool accepted = false;
    for (int attempt = 0; attempt < 8 && !accepted; ++attempt) {
      Eigen::MatrixXd damped = A;
      for (Eigen::Index d = 0; d < damped.rows(); ++d) damped(d, d) += lambda * std::max(A(d, d), 1e-30);
      const Eigen::VectorXd delta = damped.ldlt().solve(-g);
      Lighting trial = current;
      bool admissible = delta.allFinite();
      for (size_t q = 0; q < movable.size(); ++q)
        for (int k = 0; k < 3; ++k) trial[movable[q]].position += float(h * delta[Eigen::Index(3 * q + size_t(k))]) * axes[k];
      admissible = admissible && problem.place(trial);
      for (size_t j = 0; j < n && admissible; ++j)
        for (int c = 0; c < 3; ++c)
          trial[j].intensity[c] = float(std::max(0.0, double(trial[j].intensity[c]) + delta[Eigen::Index(np + 3 * j + size_t(c))]));
      if (!admissible) {
        lambda *= 10;
        continue;
      }
      std::vector<Rgb> trial_phi = problem.responses(trial);
      Eigen::VectorXd trial_r;
      const double trial_cost = residuals(s, trial_phi, trial, trial_r);
      if (trial_cost < cost) {
        const double gain = (cost - trial_cost) / cost;
        current = std::move(trial), phi = std::move(trial_phi), r = std::move(trial_r), cost = trial_cost;
        lambda = std::max(lambda / 3, 1e-9);
        accepted = true;
        if (gain < settings.min_improvement) return current;
      } else {
        lambda *= 10;
      }
    }
    if (!accepted) break;
  }
  return current;
}

} // namespace hilight
