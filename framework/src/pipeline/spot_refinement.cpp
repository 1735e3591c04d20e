#include "hilight/pipeline/spot_refinement.hpp"

#include "hilight/pipeline/fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <tbb/parallel_for.h>

namespace hilight {

namespace {

/// Per spot: position (in hundredths of the diagonal), direction (radians
/// along two tangents), cutoff and soft edge (degrees) — similar scales.
constexpr int kParams = 7;
constexpr double kFiniteStep[kParams] = {0.1, 0.1, 0.1, 2e-3, 2e-3, 0.1, 0.1};

Light moved(const Light& s, const double* x, float position_unit, float falloff_share) {
  Light l = s;
  l.position += position_unit * Vec3(float(x[0]), float(x[1]), float(x[2]));
  const Vec3 d = glm::normalize(s.direction);
  const Vec3 e1 = glm::normalize(std::abs(d.y) < 0.9f ? glm::cross(d, Vec3(0.f, 1.f, 0.f)) : glm::cross(d, Vec3(1.f, 0.f, 0.f)));
  const Vec3 e2 = glm::cross(d, e1);
  l.direction = glm::normalize(d + float(x[3]) * e1 + float(x[4]) * e2);
  l.cutoff_deg = std::clamp(s.cutoff_deg + float(x[5]), kMinSpotCutoffDeg, kMaxSpotCutoffDeg);
  l.falloff_deg = std::clamp(s.falloff_deg + float(x[6]), kMinSpotFalloffDeg, std::max(kMinSpotFalloffDeg, falloff_share * l.cutoff_deg));
  return l;
}

/// The model's weighted residual √w (Ψ − Σ l φ), channel-interleaved.
struct Evaluation {
  Eigen::VectorXd r;
  std::vector<Rgb> intensities;
  double cost = 0.0;
  std::vector<Rgb> scale;  ///< per sample and channel: over_weight where over-lit, else 1 (empty: all 1)
};

class Model {
public:
  Model(const SampleSet& samples, const std::vector<Rgb>& base_phi, size_t base_count, const std::vector<Rgb>& bounce,
        double over_weight)
      : m_samples(samples), m_base_phi(base_phi), m_base_count(base_count), m_bounce(bounce), m_over_weight(over_weight) {}

  /// `direct`: each spot's direct light (light-major). With over_weight,
  /// the over-lit samples are found by a few rounds of reweighting, unless
  /// `mask` gives them (a Jacobian's moved copies keep the point's own, so
  /// the slopes are of one smooth function).
  Evaluation evaluate(const std::vector<Rgb>& direct, const std::vector<Rgb>* mask = nullptr) const {
    const size_t m = m_samples.size(), k = direct.size() / std::max<size_t>(1, m);
    std::vector<Rgb> phi = m_base_phi;
    phi.insert(phi.end(), direct.begin(), direct.end());
    if (!m_bounce.empty())
      for (size_t i = 0; i < k * m; ++i) phi[m_base_count * m + i] += m_bounce[i];
    Evaluation e;
    if (mask) e.scale = *mask;
    e.intensities = fit_intensities(phi, m_base_count + k, m_samples, e.scale);
    std::vector<Rgb> lit = combine(phi, e.intensities, m);
    for (int round = 0; round < (m_over_weight != 1.0 && !mask ? 2 : 0); ++round) {
      e.scale.assign(m, Rgb(1.f));
      for (size_t i = 0; i < m; ++i)
        for (int c = 0; c < 3; ++c)
          if (lit[i][c] > m_samples.target[i][c]) e.scale[i][c] = float(m_over_weight);
      e.intensities = fit_intensities(phi, m_base_count + k, m_samples, e.scale);
      lit = combine(phi, e.intensities, m);
    }
    e.r.resize(Eigen::Index(3 * m));
    for (size_t i = 0; i < m; ++i) {
      const double sw = std::sqrt(double(m_samples.weight[i]));
      for (int c = 0; c < 3; ++c) {
        double v = sw * (double(m_samples.target[i][c]) - double(lit[i][c]));
        if (!e.scale.empty()) v *= std::sqrt(double(e.scale[i][c]));
        e.r[Eigen::Index(3 * i + size_t(c))] = v;
        e.cost += v * v;
      }
    }
    return e;
  }

private:
  const SampleSet& m_samples;
  const std::vector<Rgb>& m_base_phi;
  size_t m_base_count;
  const std::vector<Rgb>& m_bounce;
  double m_over_weight;
};

} // namespace

Lighting refine_spots(const Lighting& spots, const std::vector<Rgb>& bounce, const SampleSet& samples, const LightSpace& space,
                      Renderer& renderer, const std::vector<Rgb>& base_phi, size_t base_count, double& dbar,
                      const SpotRefineSettings& settings) {
  const size_t m = samples.size(), k = spots.size(), p = kParams * k;
  const double norm = samples.target_norm();
  const float unit = 0.01f * space.rays().scene().diagonal();
  const Model model(samples, base_phi, base_count, bounce, settings.over_weight);
  auto direct_of = [&](const Lighting& lights) { return renderer.unit_responses(samples.points, lights, Transport::DirectOnly); };
  // A step out of the light bounds is clamped back (the spot slides along the
  // bound instead of stopping there), then placed by the rules.
  const Bounds& box = space.light_bounds();
  const Vec3 inset = 1e-4f * box.extent();
  auto place = [&](Lighting& lights) {
    for (auto& l : lights) {
      const auto at = space.place(glm::clamp(l.position, box.lo + inset, box.hi - inset));
      if (!at || !space.admissible(*at)) return false;
      l.position = *at;
    }
    return true;
  };

  const float share = float(settings.max_falloff_share);
  Lighting current = spots;
  for (auto& l : current) {  // the start obeys the bounds the steps keep
    const double none[kParams] = {};
    l = moved(l, none, unit, share);
  }
  std::vector<Rgb> direct = direct_of(current);
  Evaluation now = model.evaluate(direct);
  double lambda = 1e-3;
  int small_gains = 0;
  for (int iteration = 0; iteration < settings.iterations && k > 0 && now.cost > 0.0; ++iteration) {
    // Finite differences: every moved copy in one batch; only its own column changes.
    Lighting copies;
    for (size_t s = 0; s < k; ++s)
      for (int q = 0; q < kParams; ++q) {
        double x[kParams] = {};
        x[q] = kFiniteStep[q];
        copies.push_back(moved(current[s], x, unit, share));
      }
    const std::vector<Rgb> copy_direct = direct_of(copies);
    Eigen::MatrixXd J(Eigen::Index(3 * m), Eigen::Index(p));
    tbb::parallel_for(size_t(0), p, [&](size_t col) {
      const size_t s = col / kParams;
      std::vector<Rgb> d = direct;
      for (size_t i = 0; i < m; ++i) {
        // A sample crossing a shadow edge jumps: no slope, and its spike
        // would swamp the others' (the fit then stalls a spot's length off).
        const Rgb& moved_value = copy_direct[col * m + i];
        const bool was_lit = direct[s * m + i] != Rgb(0.f), is_lit = moved_value != Rgb(0.f);
        if (was_lit == is_lit) d[s * m + i] = moved_value;
      }
      // Sign: J is the derivative of the model's light, −∂r.
      J.col(Eigen::Index(col)) = (now.r - model.evaluate(d, &now.scale).r) / kFiniteStep[col % kParams];
    });
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd Jtr = J.transpose() * now.r;
    bool accepted = false;
    for (int attempt = 0; attempt < 8 && !accepted; ++attempt) {
      Eigen::MatrixXd A = JtJ;
      for (Eigen::Index d = 0; d < A.rows(); ++d) A(d, d) += lambda * std::max(JtJ(d, d), 1e-12);
      const Eigen::VectorXd step = A.ldlt().solve(Jtr);
      Lighting trial;
      for (size_t s = 0; s < k; ++s) trial.push_back(moved(current[s], step.data() + s * kParams, unit, share));
      if (place(trial)) {
        std::vector<Rgb> trial_direct = direct_of(trial);
        Evaluation e = model.evaluate(trial_direct);
        if (e.cost < now.cost) {
          small_gains = e.cost > (1.0 - settings.min_improvement) * now.cost ? small_gains + 1 : 0;
          current = std::move(trial), direct = std::move(trial_direct), now = std::move(e);
          lambda = std::max(lambda / 3.0, 1e-7);
          accepted = true;
          continue;
        }
      }
      lambda *= 4.0;
    }
    if (!accepted || small_gains >= 2) break;
  }
  for (size_t s = 0; s < k; ++s) current[s].intensity = now.intensities[base_count + s];
  dbar = norm > 0 ? std::sqrt(now.cost) / norm : 0.0;
  return current;
}

} // namespace hilight
