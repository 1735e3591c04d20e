// Variable projection: for fixed positions the best intensities are an NNLS
// solve, so the simplex searches geometry only (3 parameters per point light
// instead of 6), and it does so one light at a time — moving one light costs
// one light's φ, the others' responses are kept by the problem. Sweeps repeat
// until a sweep improves the objective by less than `tolerance`, or the fit
// is good beyond sight (RefineProblem::negligible). A polish
// (RefineEffort::Polish) is one sweep with small first steps and half the
// evaluations.
//
// | property          | default | meaning                                         |
// |-------------------|---------|-------------------------------------------------|
// | sweeps            | 4       | passes over all lights                          |
// | evaluations       | 20      | simplex evaluations per point light and sweep   |
// |                   |         | (4x for a spotlight: 6 parameters, flat valley)|
//
// 20, not 40: the simplex only brings each light into its valley; the
// Gauss–Newton steps after it and the reference's polish go to the floor.
// At 40 the bench building's refinement took 8.3 s, at 20 4.3 s, with the
// same lights and D̄ (docs/benchmarks.md), and the suite's recoveries held.
// | tolerance         | 1e-4    | relative improvement below which sweeps stop    |
#include "hilight/error.hpp"
#include "hilight/solve/light_parameters.hpp"
#include "hilight/solve/simplex.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"

namespace {

using namespace hilight;

class VarProOptimizer final : public Optimizer {
public:
  VarProOptimizer(int sweeps, int evaluations, double tolerance)
      : m_sweeps(sweeps), m_evaluations(evaluations), m_tolerance(tolerance) {}

  Lighting refine(RefineProblem& problem, const Lighting& start, RefineEffort effort) override {
    const float scale = problem.scale();
    Lighting best = start;
    double best_value = problem.objective_with_best_intensities(best);
    // A polish starts near the optimum: one sweep with small first steps.
    const int sweeps = effort == RefineEffort::Polish ? 1 : m_sweeps;
    const int first_step_level = effort == RefineEffort::Polish ? 2 : 0;
    for (int sweep = 0; sweep < sweeps && best_value > problem.negligible(); ++sweep) {
      const double before = best_value;
      for (size_t j = 0; j < best.size() && best_value > problem.negligible(); ++j) {
        std::vector<double> x, steps;
        append_geometry(best[j], scale, x, steps);
        // Later sweeps take smaller first steps: the lights are close by then.
        for (auto& s : steps) s /= double(1 << std::min(sweep + first_step_level, 3));
        auto f = [&](const std::vector<double>& p) {
          Lighting trial = best;
          read_geometry(trial[j], scale, p, 0);
          return problem.objective_with_best_intensities(trial);
        };
        SimplexSettings settings;
        // A spot has 6 parameters and a long, flat valley (distance trades
        // against cutoff and intensity): it gets four times a point's budget.
        settings.max_evaluations = x.size() > 3 ? 4 * m_evaluations : m_evaluations;
        if (effort == RefineEffort::Polish) settings.max_evaluations = std::max(12, settings.max_evaluations / 2);
        settings.x_tolerance = 2e-4;  // 0.02% of the diagonal
        settings.f_target = problem.negligible();
        SimplexResult r = nelder_mead(f, x, steps, settings);
        if (r.value < best_value) {
          read_geometry(best[j], scale, r.x, 0);
          best_value = problem.objective_with_best_intensities(best);
        }
      }
      if (before - best_value <= m_tolerance * before) break;
    }
    return best;
  }

private:
  int m_sweeps, m_evaluations;
  double m_tolerance;
};

void register_varpro(PluginRegistrar& registrar) {
  registrar.optimizer([](const Properties& props) -> std::unique_ptr<Optimizer> {
    long long sweeps = props.get_int("sweeps", 4), evals = props.get_int("evaluations", 20);
    double tol = props.get_double("tolerance", 1e-4);
    if (sweeps < 1 || sweeps > 1000) throw InputError("optimizer varpro: sweeps must be in [1, 1000]");
    if (evals < 4 || evals > 1'000'000) throw InputError("optimizer varpro: evaluations must be in [4, 1e6]");
    if (!(tol >= 0)) throw InputError("optimizer varpro: tolerance must be >= 0");
    return std::make_unique<VarProOptimizer>(int(sweeps), int(evals), tol);
  });
}

} // namespace

HILIGHT_PLUGIN("optimizer", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION,
               "variable projection: simplex over positions, light by light, intensities by NNLS", register_varpro)
