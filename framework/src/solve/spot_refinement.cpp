#include "hilight/solve/spot_refinement.hpp"

#include "hilight/solve/fit.hpp"
#include "hilight/solve/levenberg_marquardt.hpp"
#include "hilight/solve/simplex.hpp"

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
/// Simplex runs at most, each from where the last stopped.
constexpr int kSimplexRuns = 8;
/// The spot search's damping: a gentler λ schedule than the reference
/// polish's (×4 after a refused try, down to 1e-7), its own since the spot search began (the reference polish: ×10, down to 1e-9).
constexpr LevenbergMarquardtDamping kSpotDamping{1e-12, 1e-7, 4.0, 3.0, 8};

Light moved(const Light& s, const double* x, float position_unit, float falloff_share) {
  Light l = s;
  l.position += position_unit * Vec3(float(x[0]), float(x[1]), float(x[2]));
  if (s.type != LightType::Spot) return l;
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

/// One refinement: the lights where they are, their direct light and the
/// model's evaluation there; each method only moves them downhill.
class SpotSearch {
public:
  SpotSearch(const Lighting& spots, const std::vector<Rgb>& bounce, const SampleSet& samples, const LightSpace& space, Renderer& renderer,
             const std::vector<Rgb>& base_phi, size_t base_count, const SpotRefineSettings& settings)
      : m_samples(samples), m_space(space), m_renderer(renderer), m_settings(settings),
        m_model(samples, base_phi, base_count, bounce, settings.over_weight), m_unit(0.01f * space.rays().scene().diagonal()),
        m_share(float(settings.max_falloff_share)), m_current(spots) {
    for (auto& l : m_current) {  // the start obeys the bounds the steps keep
      const double none[kParams] = {};
      l = moved(l, none, m_unit, m_share);
    }
    m_direct = direct_of(m_current);
    m_now = m_model.evaluate(m_direct);
  }

  const Lighting& lights() const { return m_current; }
  const Evaluation& evaluation() const { return m_now; }

  void levenberg_marquardt() {
    const size_t m = m_samples.size(), k = m_current.size();
    double lambda = 1e-3;
    int small_gains = 0;
    for (int iteration = 0; iteration < m_settings.iterations && k > 0 && m_now.cost > 0.0; ++iteration) {
      // Finite differences: every moved copy in one batch; only its own
      // column changes.
      Lighting copies;
      const auto columns = parameters();
      for (const auto& [s, q] : columns) {
        double x[kParams] = {};
        x[q] = kFiniteStep[q];
        copies.push_back(moved(m_current[s], x, m_unit, m_share));
      }
      const size_t p = columns.size();
      const std::vector<Rgb> copy_direct = direct_of(copies);
      Eigen::MatrixXd J(Eigen::Index(3 * m), Eigen::Index(p));
      tbb::parallel_for(size_t(0), p, [&](size_t col) {
        const auto [s, q] = columns[col];
        std::vector<Rgb> d = m_direct;
        for (size_t i = 0; i < m; ++i) {
          // A sample crossing a shadow edge jumps: no slope, and its spike
          // would swamp the others' (the fit then stalls a spot's length off).
          const Rgb& moved_value = copy_direct[col * m + i];
          const bool was_lit = m_direct[s * m + i] != Rgb(0.f), is_lit = moved_value != Rgb(0.f);
          if (was_lit == is_lit) d[s * m + i] = moved_value;
        }
        // Sign: J is the derivative of the model's light, −∂r.
        J.col(Eigen::Index(col)) = (m_now.r - m_model.evaluate(d, &m_now.scale).r) / kFiniteStep[q];
      });
      const Eigen::MatrixXd JtJ = J.transpose() * J;
      const Eigen::VectorXd Jtr = J.transpose() * m_now.r;  // downhill: J is −∂r
      const bool accepted = levenberg_marquardt_step(JtJ, Jtr, lambda, kSpotDamping, [&](const Eigen::VectorXd& step) {
        const double before = m_now.cost;
        if (!try_move(at(m_current, columns, step.data()))) return false;
        small_gains = m_now.cost > (1.0 - m_settings.min_improvement) * before ? small_gains + 1 : 0;
        return true;
      });
      if (!accepted || small_gains >= 2) break;
    }
  }

  /// Derivative-free: a shadow edge sweeping over samples as a lamp moves
  /// is a kink that no finite difference sees (they leave those samples out).
  void simplex() {
    if (m_settings.simplex_evaluations <= 0 || m_current.empty() || !(m_now.cost > 0.0)) return;
    const auto columns = parameters();
    std::vector<double> steps;
    for (const auto& c : columns) steps.push_back(m_settings.simplex_step * kFiniteStep[c.second]);
    const Lighting start = m_current;
    SimplexSettings settings;
    settings.max_evaluations = m_settings.simplex_evaluations;
    settings.x_tolerance = 1e-4;
    const SimplexResult r = nelder_mead(
        [&](const std::vector<double>& v) {
          Lighting l = at(start, columns, v.data());
          if (!place(l)) return 1e300;
          return m_model.evaluate(direct_of(l)).cost;
        },
        std::vector<double>(steps.size(), 0.0), steps, settings);
    try_move(at(start, columns, r.x.data()));
  }

private:
  using Columns = std::vector<std::pair<size_t, int>>;  ///< (light, parameter)

  /// What may move: a spot's every parameter, a point light's position.
  Columns parameters() const {
    Columns columns;
    for (size_t s = 0; s < m_current.size(); ++s)
      for (int q = 0; q < (m_current[s].type == LightType::Spot ? kParams : 3); ++q) columns.emplace_back(s, q);
    return columns;
  }
  /// `from` moved by `values`, one per column.
  Lighting at(const Lighting& from, const Columns& columns, const double* values) const {
    std::vector<double> x(kParams * from.size(), 0.0);
    for (size_t c = 0; c < columns.size(); ++c) x[columns[c].first * kParams + size_t(columns[c].second)] = values[c];
    Lighting l;
    for (size_t s = 0; s < from.size(); ++s) l.push_back(moved(from[s], x.data() + s * kParams, m_unit, m_share));
    return l;
  }
  std::vector<Rgb> direct_of(const Lighting& lights) const {
    return m_renderer.unit_responses(m_samples.points, lights, Transport::DirectOnly);
  }
  bool place(Lighting& lights) const { return place_within_bounds(m_space, lights); }
  /// Moves to `trial` if it is placeable and better.
  bool try_move(Lighting trial) {
    if (!place(trial)) return false;
    std::vector<Rgb> direct = direct_of(trial);
    Evaluation e = m_model.evaluate(direct);
    if (!(e.cost < m_now.cost)) return false;
    m_current = std::move(trial), m_direct = std::move(direct), m_now = std::move(e);
    return true;
  }

  const SampleSet& m_samples;
  const LightSpace& m_space;
  Renderer& m_renderer;
  const SpotRefineSettings& m_settings;
  const Model m_model;
  const float m_unit, m_share;
  Lighting m_current;
  std::vector<Rgb> m_direct;
  Evaluation m_now;
};

} // namespace

bool place_within_bounds(const LightSpace& space, Lighting& lights) {
  const Bounds& box = space.light_bounds();
  const Vec3 inset = 1e-4f * box.extent();
  for (auto& l : lights) {
    const auto at = space.place(glm::clamp(l.position, box.lo + inset, box.hi - inset));
    if (!at || !space.admissible(*at)) return false;
    l.position = *at;
  }
  return true;
}

Fit refine_spots(const Lighting& spots, const std::vector<Rgb>& bounce, const SampleSet& samples, const LightSpace& space,
                 Renderer& renderer, const std::vector<Rgb>& base_phi, size_t base_count, const SpotRefineSettings& settings) {
  SpotSearch search(spots, bounce, samples, space, renderer, base_phi, base_count, settings);
  search.levenberg_marquardt();
  if (settings.simplex_evaluations > 0) {
    // The simplex steps over the kinks, the slopes then go to the bottom of
    // where it stopped; a simplex collapses on a kink's ridge, so a fresh
    // one starts there while the two still gain (measured: the curved
    // models turned, 1 cm off with one run, 0.1 mm with up to four).
    for (int run = 0; run < kSimplexRuns; ++run) {
      const double before = search.evaluation().cost;
      search.simplex();
      search.levenberg_marquardt();
      if (!(search.evaluation().cost < 0.98 * before)) break;
    }
  }
  Lighting found = search.lights();
  for (size_t s = 0; s < found.size(); ++s) found[s].intensity = search.evaluation().intensities[base_count + s];
  const double norm = samples.target_norm();
  return {std::move(found), norm > 0 ? std::sqrt(search.evaluation().cost) / norm : 0.0};
}

} // namespace hilight
