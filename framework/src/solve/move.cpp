// The plan runner and the context's services.
#include "hilight/solve/move.hpp"

#include "hilight/solve/solve_context.hpp"
#include "hilight/solve/stoppable_renderer.hpp"
#include "solver_internal.hpp"

#include <algorithm>

namespace hilight {

using solver_detail::Stopwatch;

void SolveContext::stage(const std::string& name) const { solver_detail::announce_stage(stop, progress, name); }

std::unique_ptr<LightCacheView> SolveContext::cache_view(const SampleSet& on) const {
  return cache ? cache->view(space.rays(), on) : nullptr;
}

float SolveContext::seeding_cell() const {
  const Vec3 extent = space.bounds().extent();
  return std::max({extent.x, extent.y, extent.z}) / float(2 * std::max(1, settings.seeding.coarse_cells));
}

SampleSet evaluation_set(const Target& target, size_t want) {
  if (want == 0 || want >= target.size()) return all_samples(target);
  // Evenly spaced target points estimate the whole target's D̄ at a fixed
  // cost — unless the target's light is concentrated where the spacing does
  // not look (a small painted patch): then every point is measured.
  const size_t n = target.size();
  SampleSet measured;
  for (size_t k = 0; k < want; ++k) measured.add(target, uint32_t(std::min(n - 1, k * n / want)));
  const double share = double(measured.size()) / double(n);
  const double energy = measured.target_norm() * measured.target_norm(), total = target.norm() * target.norm();
  if (!(energy > 0.5 * share * total && energy < 2.0 * share * total)) return all_samples(target);
  return measured;
}

SampleSet SolveContext::evaluation_set() const { return hilight::evaluation_set(target, settings.evaluation_points); }

Fit run_plan(const Plan& plan, SolveContext& ctx, Fit fit) {
  for (const PlanStep& step : plan.steps) {
    if (ctx.stop.stop_requested()) throw SolveCancelled();
    const std::string name = step.move->name();
    if (std::string why = step.move->premise_fails(ctx, fit); !why.empty()) {
      ctx.report.stages.push_back({name, 0, fit.dbar, fit.dbar, false, false, std::move(why)});
      continue;
    }
    Stopwatch watch;
    Fit after = step.move->run(ctx, fit);
    const double seconds = watch.seconds();
    if (!step.seconds_key.empty()) ctx.report.seconds[step.seconds_key] += seconds;
    const bool changed = after.lights != fit.lights || after.dbar != fit.dbar;
    ctx.report.stages.push_back({name, seconds, fit.dbar, after.dbar, false, changed, {}});
    fit = std::move(after);
    ctx.report.dbar_samples = fit.dbar;
    if (plan.stop_when_empty && fit.lights.empty()) break;
  }
  return fit;
}

} // namespace hilight
