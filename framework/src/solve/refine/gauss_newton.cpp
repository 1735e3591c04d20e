#include "hilight/solve/gauss_newton.hpp"

#include "hilight/solve/levenberg_marquardt.hpp"
#include "hilight/solve/spot_refinement.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <utility>

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

/// One geometric parameter of one light, moved in steps of its own size:
/// a position along one of the scene's own axes (point lights and spots),
/// a spot's aim along one of two tangents, its cutoff or its soft edge.
struct GeometryParameter {
  size_t light;
  enum Kind { Position, Aim, Cutoff, Falloff } kind;
  Vec3 axis{0.f};  ///< Position: the own axis; Aim: the tangent
};

/// Finite-difference and step units: the aim in radians, the cone in degrees.
constexpr double kAimStep = 1e-3, kConeStepDeg = 0.05;

/// Two tangents to `d`, laid out from the scene's own axes (the one least
/// along `d`), so a turned scene aims its spots along the same tangents.
std::pair<Vec3, Vec3> tangents(const Vec3& d, const glm::mat3& axes) {
  int least = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(glm::dot(d, axes[k])) < std::abs(glm::dot(d, axes[least]))) least = k;
  const Vec3 e1 = glm::normalize(glm::cross(d, axes[least]));
  return {e1, glm::cross(d, e1)};
}

/// `l` moved by `amount` steps of parameter `q` (position: `h`).
void move(Light& l, const GeometryParameter& q, double amount, double h) {
  switch (q.kind) {
    case GeometryParameter::Position: l.position += float(amount * h) * q.axis; break;
    case GeometryParameter::Aim: l.direction = glm::normalize(glm::normalize(l.direction) + float(amount * kAimStep) * q.axis); break;
    case GeometryParameter::Cutoff:
      l.cutoff_deg = std::clamp(l.cutoff_deg + float(amount * kConeStepDeg), kMinSpotCutoffDeg, kMaxSpotCutoffDeg);
      l.falloff_deg = std::min(l.falloff_deg, l.cutoff_deg);
      break;
    case GeometryParameter::Falloff:
      l.falloff_deg = std::clamp(l.falloff_deg + float(amount * kConeStepDeg), kMinSpotFalloffDeg, std::max(kMinSpotFalloffDeg, l.cutoff_deg));
      break;
  }
}

} // namespace

Lighting gauss_newton_polish(SampleRefineProblem& problem, const Lighting& start, const GaussNewtonSettings& settings) {
  const SampleSet& s = problem.samples();
  const size_t m = s.size(), n = start.size();
  if (n == 0 || m == 0) return start;
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
    // The parameters, spots' aims along tangents of their aim now.
    std::vector<GeometryParameter> params;
    for (size_t j = 0; j < n; ++j) {
      const bool spot = current[j].type == LightType::Spot;
      if (current[j].type != LightType::Point && !(spot && settings.move_spots)) continue;
      for (int k = 0; k < 3; ++k) params.push_back({j, GeometryParameter::Position, axes[k]});
      if (!spot) continue;
      const auto [e1, e2] = tangents(glm::normalize(current[j].direction), axes);
      params.push_back({j, GeometryParameter::Aim, e1});
      params.push_back({j, GeometryParameter::Aim, e2});
      params.push_back({j, GeometryParameter::Cutoff});
      params.push_back({j, GeometryParameter::Falloff});
    }
    const size_t np = params.size(), p = np + 3 * n;
    // Finite differences: every moved copy in one batch, each corrected as its light.
    Lighting moved;
    std::vector<size_t> anchor;
    for (const auto& q : params) {
      Light l = current[q.light];
      move(l, q, 1.0, h);
      if (auto placed = problem.space().place(l.position)) l.position = *placed;  // along the mount, if there is one
      moved.push_back(l);
      anchor.push_back(q.light);
    }
    std::vector<Rgb> moved_phi = moved.empty() ? std::vector<Rgb>{} : problem.responses_as(moved, anchor);
    // J (3m × p): geometry in units of its step (well scaled), then intensities.
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(Eigen::Index(3 * m), Eigen::Index(p));
    for (size_t i = 0; i < m; ++i) {
      const double sw = std::sqrt(double(s.weight[i]));
      for (int c = 0; c < 3; ++c) {
        const Eigen::Index row = Eigen::Index(3 * i + size_t(c));
        for (size_t q = 0; q < np; ++q) {
          const size_t j = params[q].light;
          const double before = double(phi[j * m + i][c]), after = double(moved_phi[q * m + i][c]);
          // A sample whose light jumps over a step of 10⁻⁴ of the diagonal
          // crosses a shadow edge (or a hard cone edge): no slope there, and
          // its spike would swamp the smooth falloff of all the others (a
          // far light then stalls a metre off: the glTF engine's key lights).
          const bool jumps = std::abs(after - before) > settings.jump * std::max(std::abs(before), std::abs(after));
          J(row, Eigen::Index(q)) = jumps ? 0.0 : -sw * double(current[j].intensity[c]) * (after - before);
        }
        for (size_t j = 0; j < n; ++j) J(row, Eigen::Index(np + 3 * j + size_t(c))) = -sw * double(phi[j * m + i][c]);
      }
    }
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    const Eigen::VectorXd downhill = -g;
    double gain = 0;
    const bool accepted = levenberg_marquardt_step(A, downhill, lambda, LevenbergMarquardtDamping{}, [&](const Eigen::VectorXd& delta) {
      Lighting trial = current;
      bool admissible = delta.allFinite();
      if (admissible) {
        // A spot's aim moves along both tangents at once (from its aim now).
        std::vector<Vec3> aim_shift(n, Vec3(0.f));
        for (size_t q = 0; q < np; ++q) {
          if (params[q].kind == GeometryParameter::Aim)
            aim_shift[params[q].light] += float(delta[Eigen::Index(q)] * kAimStep) * params[q].axis;
          else
            move(trial[params[q].light], params[q], delta[Eigen::Index(q)], h);
        }
        for (size_t j = 0; j < n; ++j)
          if (aim_shift[j] != Vec3(0.f)) trial[j].direction = glm::normalize(glm::normalize(current[j].direction) + aim_shift[j]);
      }
      admissible = admissible && problem.place(trial);
      for (size_t j = 0; j < n && admissible; ++j)
        for (int c = 0; c < 3; ++c)
          trial[j].intensity[c] = float(std::max(0.0, double(trial[j].intensity[c]) + delta[Eigen::Index(np + 3 * j + size_t(c))]));
      if (!admissible) return false;
      std::vector<Rgb> trial_phi = problem.responses(trial);
      Eigen::VectorXd trial_r;
      const double trial_cost = residuals(s, trial_phi, trial, trial_r);
      if (!(trial_cost < cost)) return false;
      gain = (cost - trial_cost) / cost;
      current = std::move(trial), phi = std::move(trial_phi), r = std::move(trial_r), cost = trial_cost;
      return true;
    });
    if (!accepted) break;
    if (gain < settings.min_improvement) return current;
  }
  return current;
}

} // namespace hilight
