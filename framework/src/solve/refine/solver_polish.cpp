// The Solver's refinement: a cut's lights refined by the optimizer plugin,
// anchored at the reference; the polish by the reference (Gauss-Newton);
// the second polish with the worst-explained target points as samples.
#include "hilight/solve/solver.hpp"

#include "hilight/error.hpp"
#include "hilight/solve/fit.hpp"
#include "hilight/solve/gauss_newton.hpp"
#include "hilight/solve/refine_problem.hpp"
#include "hilight/solve/spot_proposals.hpp"
#include "../solver_internal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace hilight {

using namespace solver_detail;

Fit Solver::refine_anchored(ResponseModel& model, ResponseModel& exact, const Lighting& start, RefineEffort effort) {
  SampleRefineProblem problem(model, *m_space, m_cache ? &exact : nullptr);
  const SampleSet& samples = model.samples();
  const double norm = samples.target_norm();
  problem.anchor(start);
  const double start_value = problem.objective(start);
  Lighting refined = m_optimizer.refine(problem, start, effort);
  auto polish = [&] {  // re-anchor where the lights went and refine a little
    problem.anchor(refined);
    Lighting polished = m_optimizer.refine(problem, refined, RefineEffort::Polish);
    if (problem.objective(polished) <= problem.objective(refined)) refined = polished;
  };
  if (m_cache && effort == RefineEffort::Full) polish();
  // The simplex leaves lights near surfaces short of their valley's floor, and
  // a cut judged there is judged too harshly by the count rule (measured: 37
  // of 40 ceiling-lamp trials right without this step, 38 with it).
  {
    GaussNewtonSettings judge;  // enough to judge the cut; the final polish goes to the bottom
    judge.iterations = 4;
    Lighting stepped = gauss_newton_polish(problem, refined, judge);
    if (problem.objective(stepped) < problem.objective(refined)) refined = std::move(stepped);
  }

  // Eq. 6 once more on the refined lights: refinement often leaves a point
  // light with nothing to do (zero, or a few % of the target) once its
  // neighbours moved into place. Drop those, re-fit, polish again.
  std::vector<Rgb> phi = problem.responses(refined);
  Lighting kept;
  for (size_t j = 0; j < refined.size(); ++j)
    if (refined[j].type == LightType::Spot ||
        !m_judge.weak(contribution(phi, j, refined[j].intensity, samples), norm))
      kept.push_back(refined[j]);
  // With the count fixed by the user (--lights N) every light stays.
  if (m_settings.fixed_count == 0 && effort == RefineEffort::Full && !kept.empty() && kept.size() < refined.size() &&
      kept.size() >= min_lights()) {
    refined = kept;
    problem.anchor(refined);
    problem.objective_with_best_intensities(refined);
    polish();
  }
  // Each value is accurate at its own anchor, so the two compare fairly.
  double value = problem.objective(refined);
  if (value > start_value) refined = start, value = start_value;  // refinement may only help
  return {std::move(refined), std::sqrt(std::max(0.0, value)) / norm};
}

Fit Solver::polish_with_reference(const SampleSet& samples, const Lighting& lights, bool keep_count, int rounds) {
  // The fast model (fast twin, light cache) found the positions; the
  // reference decides. Anchoring makes the model equal to the reference at
  // the lights it is anchored at, so every value compared below is exact.
  const auto view = cache_view(samples);
  ResponseModel model(m_renderer, samples, view.get());
  ResponseModel reference(m_reference, samples, nullptr);
  SampleRefineProblem problem(model, *m_space, &reference);
  const double norm = samples.target_norm();
  Lighting fitted = lights;
  if (!problem.place(fitted)) fitted = lights;  // (the objective says so below)
  problem.anchor(fitted);  // where the placement rules put them: the anchor must be where they stand
  double best = problem.objective_with_best_intensities(fitted);
  if (!keep_count && m_settings.fixed_count == 0) {
    // A point light the fit switches off does nothing: not part of the answer.
    Lighting kept;
    for (const auto& l : fitted)
      if (l.type == LightType::Spot || l.intensity != Rgb(0.f)) kept.push_back(l);
    if (!kept.empty() && kept.size() < fitted.size() && kept.size() >= min_lights()) {
      fitted = std::move(kept);
      problem.anchor(fitted);
      best = problem.objective_with_best_intensities(fitted);
    }
  }
  // Gauss–Newton (not a simplex: it converges in a few steps where the
  // lights are already near), re-anchored after each round — the anchor's
  // correction is exact only where it was taken, so each round's value is
  // the reference's own, and the next round starts anchored at `fitted`.
  // Settled (D̄ 0.01% at the samples): nothing is left that anyone could see.
  for (int round = 0; round < rounds && norm > 0 && !m_judge.settled(std::sqrt(best) / norm); ++round) {
    GaussNewtonSettings settings;
    settings.move_spots = true;
    Lighting stepped = gauss_newton_polish(problem, fitted, settings);
    // A single round (fine-tune, interactive) takes the anchored model's word
    // for the step — Gauss–Newton only takes steps that lower it — and saves
    // the reference's φ at the new place.
    if (rounds > 1) problem.anchor(stepped);
    const double value = problem.objective(stepped);
    if (!(value < best)) break;
    const bool small_gain = value > 0.9 * best;
    fitted = std::move(stepped), best = value;
    if (small_gain) break;
  }
  return {std::move(fitted), norm > 0 ? std::sqrt(std::max(0.0, best)) / norm : 0.0};
}

Lighting Solver::polish_residuals(const Target& target, SampleSet samples, const Lighting& lights, bool keep_count,
                                  SolveReport& report) {
  Stopwatch watch;
  const SampleSet measured = evaluation_set(target);
  std::vector<Rgb> lit = m_reference.illuminate(measured.points, lights);
  report.dbar = normalized_difference(lit, measured);
  report.dbar_points = measured.size();
  report.seconds["evaluation"] += watch.seconds();
  // Below 0.2% D̄ there is nothing a designer would see; and where the whole
  // target is explained about as well as the samples, the samples saw what
  // matters (an infeasible target stays infeasible with more of them).
  if (!m_settings.residual_samples || !m_judge.add_residual_samples(report.dbar, report.dbar_samples)) {
    report.stages.push_back({"residual polish", 0, report.dbar, report.dbar, true, false,
                             !m_settings.residual_samples ? "turned off" : "the samples saw what the target lacks"});
    return lights;
  }
  // The points that hold most of the remaining squared error — often a few
  // hot spots under lamps that the samples barely touch — join the samples.
  std::vector<double> residual(measured.size());
  double total = 0;
  for (size_t i = 0; i < measured.size(); ++i) {
    const DVec3 d = DVec3(measured.target[i]) - DVec3(lit[i]);
    residual[i] = double(measured.weight[i]) * glm::dot(d, d);
    total += residual[i];
  }
  std::vector<uint32_t> order(measured.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return residual[a] > residual[b] || (residual[a] == residual[b] && a < b); });
  std::vector<char> sampled(target.size(), 0);
  for (uint32_t i : samples.target_index) sampled[i] = 1;
  const size_t cap = std::max<size_t>(16, samples.size() / 2);
  size_t added = 0;
  double covered = 0;
  for (uint32_t k : order) {
    if (added >= cap || covered >= 0.5 * total) break;
    covered += residual[k];
    const uint32_t i = measured.target_index[k];
    if (sampled[i]) continue;
    samples.add(target, i);
    ++added;
  }
  if (added == 0) return lights;
  Stopwatch polish_watch;
  Fit polished = polish_with_reference(samples, lights, keep_count);
  report.seconds["residual polish"] += polish_watch.seconds();
  Stopwatch again;
  const double dbar = normalized_difference(m_reference.illuminate(measured.points, polished.lights), measured);
  report.seconds["evaluation"] += again.seconds();
  StageRecord record{"residual polish", polish_watch.seconds(), report.dbar, dbar, true, dbar < report.dbar, {}};
  report.stages.push_back(record);
  if (!(dbar < report.dbar)) return lights;
  report.dbar = dbar;
  report.dbar_samples = polished.dbar;
  report.residual_samples = added;
  report.samples = samples.size();
  return std::move(polished.lights);
}

} // namespace hilight
