// The paper's refinement (§3.3): one Nelder–Mead simplex over every parameter
// of the cut at once — positions, intensities, spot directions and cutoffs.
//
// | property         | default | meaning                                          |
// |------------------|---------|--------------------------------------------------|
// | max_evaluations  | 3000    | objective evaluations per cut                    |
// | restarts         | 1       | fresh simplices around the best point afterwards |
#include "hilight/error.hpp"
#include "hilight/solve/light_parameters.hpp"
#include "hilight/solve/simplex.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"

#include <algorithm>
#include <cmath>

namespace {

using namespace hilight;

class NelderMeadOptimizer final : public Optimizer {
public:
  NelderMeadOptimizer(int max_evaluations, int restarts) : m_max_evaluations(max_evaluations), m_restarts(restarts) {}

  Lighting refine(RefineProblem& problem, const Lighting& start, RefineEffort effort) override {
    const float scale = problem.scale();
    std::vector<double> x, steps;
    // A dark channel still gets a step: a share of the brightest one's, not an
    // absolute amount (intensities scale with the scene's size squared).
    double brightest = 0.0;
    for (const auto& l : start)
      for (int c = 0; c < 3; ++c) brightest = std::max(brightest, std::sqrt(std::max(0.0, double(l.intensity[c]))));
    const double least_step = brightest > 0.0 ? 1e-3 * brightest : 1e-3;
    for (const auto& l : start) {
      append_geometry(l, scale, x, steps);
      // Intensities as square roots: any real value maps to l ≥ 0.
      for (int c = 0; c < 3; ++c) {
        double s = std::sqrt(std::max(0.f, l.intensity[c]));
        x.push_back(s);
        steps.push_back(0.2 * s + least_step);
      }
    }
    auto decode = [&](const std::vector<double>& p) {
      Lighting lights = start;
      size_t o = 0;
      for (auto& l : lights) {
        o = read_geometry(l, scale, p, o);
        for (int c = 0; c < 3; ++c) l.intensity[c] = float(p[o + c] * p[o + c]);
        o += 3;
      }
      return lights;
    };
    auto f = [&](const std::vector<double>& p) { return problem.objective(decode(p)); };
    SimplexSettings settings;
    settings.max_evaluations = m_max_evaluations;
    settings.f_target = problem.negligible();
    if (effort == RefineEffort::Polish) {  // near the optimum: smaller simplex, a quarter of the budget
      for (auto& s : steps) s *= 0.25;
      settings.max_evaluations = std::max(10, m_max_evaluations / 4);
    }
    SimplexResult r = nelder_mead(f, x, steps, settings);
    for (int k = 0; k < (effort == RefineEffort::Polish ? 0 : m_restarts); ++k) {
      for (auto& s : steps) s *= 0.5;
      SimplexResult again = nelder_mead(f, r.x, steps, settings);
      if (again.value < r.value) r = again;
    }
    return decode(r.x);
  }

private:
  int m_max_evaluations, m_restarts;
};

void register_nelder_mead(PluginRegistrar& registrar) {
  registrar.optimizer([](const Properties& props) -> std::unique_ptr<Optimizer> {
    long long evals = props.get_int("max_evaluations", 3000), restarts = props.get_int("restarts", 1);
    if (evals < 10 || evals > 10'000'000) throw InputError("optimizer nelder-mead: max_evaluations must be in [10, 1e7]");
    if (restarts < 0 || restarts > 100) throw InputError("optimizer nelder-mead: restarts must be in [0, 100]");
    return std::make_unique<NelderMeadOptimizer>(int(evals), int(restarts));
  });
}

} // namespace

HILIGHT_PLUGIN("optimizer", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION, "Nelder-Mead simplex over positions, intensities and spot cones (the paper)",
               register_nelder_mead)
