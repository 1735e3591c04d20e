#include "hilight/pipeline/solver.hpp"

#include "hilight/error.hpp"
#include "hilight/light_bounds.hpp"
#include "hilight/light_cache_store.hpp"
#include "hilight/pipeline/cuts.hpp"
#include "hilight/pipeline/diagnosis.hpp"
#include "hilight/pipeline/fit.hpp"
#include "hilight/pipeline/gauss_newton.hpp"
#include "hilight/pipeline/refine_problem.hpp"
#include "hilight/pipeline/spot_proposals.hpp"

#include <chrono>
#include <limits>
#include <numeric>
#include <tbb/task_group.h>
#include <cstdio>
#include <sstream>

namespace hilight {

namespace {

/// D̄ below which a light more is noise-fitting, not a missing lamp: the same
/// order as ε_w (a light worth keeping explains 5% of ‖Ψ‖), and invisible.
constexpr double kVisibleDbar = 5e-3;
/// D̄ above which point lights (all the count rule would add) leave the
/// target to spotlights (issue 10 §3), and how many at most. Point lights
/// leave a stage's pools at 24–65%; a renderer's own floor (ism-vulkan's
/// bounce, 2–4%) or the far lights of a product (2–4%) must not start a
/// spot search that cannot pay.
constexpr double kSpotDbar = 0.05;
constexpr int kMaxSpots = 4;
/// D̄ at the samples above which a light is tried split in two: a fit this
/// poor is missing a lamp; below it, a light more mostly fits the remaining
/// error of far or bounce-lit lights (the product sweep: 20 of 20 at 1%, 19
/// at 0.5%).
constexpr double kSplitDbar = 0.01;
/// D̄ above which a solve looks for the cause (unreachable painted light).
constexpr double kPoorFitDbar = 0.05;

class Stopwatch {
public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }

private:
  std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
};

std::string hex(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

/// Lights of cut `k` (positions and summed intensities) followed by the spots.
Lighting lights_of_cut(const LightHierarchy& h, size_t k, const Lighting& spots, std::vector<Rgb>& phi) {
  Lighting lights;
  phi.clear();
  for (int node : h.cut(k)) {
    const Cluster& c = h.nodes()[node];
    lights.push_back(Light::point(c.position, c.intensity));
    phi.insert(phi.end(), c.phi.begin(), c.phi.end());
  }
  lights.insert(lights.end(), spots.begin(), spots.end());
  return lights;
}

} // namespace

size_t sample_count_for(size_t target_points) { return std::clamp<size_t>((target_points + 7) / 14, 3000, 10000); }

Solver::Solver(std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays, Renderer& renderer,
               Renderer& reference, Sampler& sampler, Optimizer& optimizer, SolveSettings settings, ProgressFn progress)
    : m_scene(std::move(scene)), m_rays(std::move(rays)), m_closed_bounds(m_scene->light_bounds()),
      m_open_bounds(open_light_bounds(*m_scene)), m_space(std::in_place, *m_rays, settings.placement, m_closed_bounds), m_renderer(renderer), m_reference(reference), m_sampler(sampler),
      m_optimizer(optimizer),
      m_settings(std::move(settings)), m_progress(std::move(progress)) {}

float Solver::neighbourhood_radius() const {
  // Two tessellation edges, within [diagonal/1000, diagonal/20]: a coarse
  // --max-edge must not make "local" the whole scene (quadratic sampling).
  const float d = m_scene->diagonal();
  return std::clamp(2.f * m_scene->max_edge, 1e-3f * d, 0.05f * d);
}

void Solver::ensure_cache(SolveReport& report) {
  if (!m_settings.use_cache) {
    report.cache_state = "off";
    return;
  }
  if (m_cache) {
    report.cache_state = "in memory";
    return;
  }
  Stopwatch watch;
  uint64_t key = LightCache::key(*m_scene, m_renderer.settings_key(), m_settings.cache);
  std::filesystem::path file;
  if (!m_settings.cache_dir.empty()) {
    file = m_settings.cache_dir / ("lightcache-" + hex(key) + ".bin");
    m_cache = LightCache::load(file, key, m_scene->positions.size());
  }
  if (m_cache) {
    report.cache_state = "loaded";
    touch_cache_file(file);  // recently used: evicted last
  } else {
    if (m_progress) m_progress("building the light cache");
    m_cache = LightCache::build(*m_scene, *m_rays, m_renderer, m_settings.cache);
    report.cache_state = "built";
    if (!file.empty()) {
      try {
        m_cache->save(file);
        evict_cache(m_settings.cache_dir, m_settings.cache_cap_bytes, file);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "hilight: warning: light cache not saved to %s: %s\n", file.c_str(), e.what());
      }
    }
  }
  report.seconds["cache"] += watch.seconds();
}

Lighting Solver::solve_samples(const SampleSet& samples, SolveReport& report) {
  const size_t m = samples.size();
  m_cuts.clear();
  m_hierarchy.reset();
  std::optional<LightCacheView> view;
  if (m_cache) view.emplace(*m_cache, *m_scene, samples);
  ResponseModel model(m_renderer, samples, view ? &*view : nullptr);

  if (m_progress) m_progress("seeding");
  Stopwatch seed_watch;
  SeedResult seed = seed_lights(model, *m_space, m_settings.spot_hints, m_settings.seeding);
  report.seconds["seeding"] += seed_watch.seconds();
  const size_t n_points = seed.lights.size() - seed.spot_count;
  report.seed_lights = n_points;
  report.seeds_tried = seed.lights_tried;
  if (n_points == 0 && seed.spot_count == 0)
    throw InputError(m_space->rules().any() ? "--place " + m_space->rules().describe() +
                                                 ": no light allowed there brightens the target (the rules exclude the lit region, or no place satisfies them)"
                                           : std::string("the seeding found no light that brightens the target"));
  if (n_points == 0) {  // only the requested spotlights: no hierarchy, refine them alone
    Stopwatch refine_watch;
    ResponseModel exact(m_renderer, samples, nullptr);
    Lighting spots_only = refine_anchored(model, exact, seed.lights, report.dbar_samples);
    report.seconds["refinement"] += refine_watch.seconds();
    return spots_only;
  }

  if (m_progress) m_progress("building the light hierarchy");
  Stopwatch hierarchy_watch;
  Lighting leaves(seed.lights.begin(), seed.lights.begin() + std::ptrdiff_t(n_points));
  std::vector<Rgb> leaf_phi(seed.phi.begin(), seed.phi.begin() + std::ptrdiff_t(n_points * m));
  std::vector<Rgb> spot_phi(seed.phi.begin() + std::ptrdiff_t(n_points * m), seed.phi.end());
  Lighting spots(seed.lights.begin() + std::ptrdiff_t(n_points), seed.lights.end());
  std::vector<Rgb> spot_l;
  for (const auto& s : spots) spot_l.push_back(s.intensity);
  // A merged light stands in free space, in the room of one of the two.
  const LightSpace& space = *m_space;
  auto may_stand_at = [&space](const Vec3& x, const Vec3& a, const Vec3& b) {
    if (!space.admissible(x)) return false;
    const int room = space.regions().at(x);
    return room == space.regions().at(a) || room == space.regions().at(b);
  };
  m_hierarchy = LightHierarchy::build(model, leaves, leaf_phi, spot_phi, spot_l, m_settings.hierarchy, may_stand_at);
  report.seconds["hierarchy"] += hierarchy_watch.seconds();

  // Every cut's D̄ with intensities re-fitted (a better start than the sums).
  report.cuts.assign(n_points, {});
  std::vector<Lighting> starts(n_points);
  for (size_t k = 1; k <= n_points; ++k) {
    std::vector<Rgb> phi;
    Lighting lights = lights_of_cut(*m_hierarchy, k, spots, phi);
    phi.insert(phi.end(), spot_phi.begin(), spot_phi.end());
    std::vector<Rgb> l = fit_intensities(phi, lights.size(), samples);
    for (size_t j = 0; j < lights.size(); ++j) lights[j].intensity = l[j];
    report.cuts[k - 1].lights = k;
    report.cuts[k - 1].dbar_initial = normalized_difference(combine(phi, l, m), samples);
    starts[k - 1] = std::move(lights);
  }

  // Which cuts to refine and how many lights (pipeline/cuts.cpp).
  // A count the seeding cannot reach (--lights N, count:MIN) takes every
  // seeded light here; add_missing_lights() adds the rest where the fit is worst.
  CountRule rule{std::min(m_settings.fixed_count, n_points), m_settings.n_cut, m_settings.eps_opt, m_settings.eps_impro, kVisibleDbar};
  rule.min_count = std::min(min_lights(), n_points);
  rule.max_count = max_lights();
  std::vector<double> initial;
  for (const auto& c : report.cuts) initial.push_back(c.dbar_initial);
  const std::vector<size_t> chosen = choose_cuts(initial, rule);

  Stopwatch refine_watch;
  ResponseModel exact(m_renderer, samples, nullptr);
  auto refine_cut = [&](size_t k) {
    if (report.cuts[k - 1].refined) return;
    if (m_progress) m_progress("refining the cut with " + std::to_string(k) + " lights");
    CutRecord& rec = report.cuts[k - 1];
    rec.refined_lights = refine_anchored(model, exact, starts[k - 1], rec.dbar_refined);
    rec.refined = true;
  };
  auto dbar_of = [&](size_t k) { return report.cuts[k - 1].refined ? report.cuts[k - 1].dbar_refined : report.cuts[k - 1].dbar_initial; };
  {
    // The walk always needs a neighbour of the first cut: refine both at
    // once (each refinement has serial stretches; two fill both cores).
    const size_t first = chosen.front();
    const FirstNeighbour neighbour = first_neighbour(initial, chosen, rule);
    tbb::task_group group;
    group.run([&] { refine_cut(first); });
    if (neighbour == FirstNeighbour::Below) group.run([&] { refine_cut(first - 1); });
    if (neighbour == FirstNeighbour::Above) group.run([&] { refine_cut(first + 1); });
    group.wait();
  }
  // Cuts are refined lazily, only as the walk needs them.
  const size_t count = walk_count(initial, chosen, rule, [&](size_t k) {
    refine_cut(k);
    return report.cuts[k - 1].dbar_refined;
  });
  report.seconds["refinement"] += refine_watch.seconds();
  for (size_t k = 1; k < n_points; ++k) {
    double next = dbar_of(k + 1);
    report.improvement.push_back(next > 0 ? dbar_of(k) / next : 0.0);
  }
  report.dbar_samples = report.cuts[count - 1].dbar_refined;
  // Kept for cut_lights(): every cut, refined where the solve refined it.
  m_cuts.clear();
  for (size_t k = 1; k <= n_points; ++k)
    m_cuts.push_back(report.cuts[k - 1].refined ? report.cuts[k - 1].refined_lights : starts[k - 1]);
  return report.cuts[count - 1].refined_lights;
}

Lighting Solver::cut_lights(size_t k) const {
  if (m_cuts.empty()) throw std::logic_error("Solver::cut_lights: no solve yet");
  return m_cuts[std::clamp<size_t>(k, 1, m_cuts.size()) - 1];
}

Lighting Solver::refine_anchored(ResponseModel& model, ResponseModel& exact, const Lighting& start, double& dbar,
                                 RefineEffort effort) {
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
        contribution(phi, j, refined[j].intensity, samples) >= m_settings.seeding.weak_threshold * norm)
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
  dbar = std::sqrt(std::max(0.0, value)) / norm;
  return refined;
}

std::vector<Rgb> Solver::illumination(const Target& target, const Lighting& lights) {
  return m_reference.illuminate(target.points, lights);
}

SampleSet Solver::evaluation_set(const Target& target) const {
  const size_t want = m_settings.evaluation_points;
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

double Solver::measure_dbar(const Target& target, const Lighting& lights) {
  SampleSet measured = evaluation_set(target);
  return normalized_difference(m_reference.illuminate(measured.points, lights), measured);
}

Lighting Solver::polish_with_reference(const SampleSet& samples, const Lighting& lights, bool keep_count, double& dbar,
                                       int rounds) {
  // The fast model (fast twin, light cache) found the positions; the
  // reference decides. Anchoring makes the model equal to the reference at
  // the lights it is anchored at, so every value compared below is exact.
  std::optional<LightCacheView> view;
  if (m_cache) view.emplace(*m_cache, *m_scene, samples);
  ResponseModel model(m_renderer, samples, view ? &*view : nullptr);
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
  // Below 0.01% D̄ at the samples nothing is left that anyone could see.
  for (int round = 0; round < rounds && norm > 0 && std::sqrt(best) > 1e-4 * norm; ++round) {
    Lighting stepped = gauss_newton_polish(problem, fitted);
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
  dbar = norm > 0 ? std::sqrt(std::max(0.0, best)) / norm : 0.0;
  return fitted;
}

size_t Solver::min_lights() const { return m_settings.fixed_count ? m_settings.fixed_count : m_settings.placement.min_count; }
size_t Solver::max_lights() const { return m_settings.fixed_count ? m_settings.fixed_count : m_settings.placement.max_count; }

Lighting Solver::add_missing_lights(const SampleSet& samples, Lighting lights, double& dbar) {
  const size_t least = min_lights(), most = max_lights();
  if (m_settings.fixed_count != 0 && lights.size() >= least) return lights;
  const size_t m = samples.size();
  std::optional<LightCacheView> view;
  if (m_cache) view.emplace(*m_cache, *m_scene, samples);
  ResponseModel model(m_renderer, samples, view ? &*view : nullptr), exact(m_renderer, samples, nullptr);
  const Vec3 extent = m_space->bounds().extent();
  const float cell = std::max({extent.x, extent.y, extent.z}) / float(2 * std::max(1, m_settings.seeding.coarse_cells));
  // `base` plus the residual candidate that explains most of what `base`
  // leaves unexplained (by NNLS with the rest), refined and polished.
  // `quick`: the light is only placed and fitted (below the count asked for,
  // lights are added regardless; one polish follows).
  auto with_best_candidate = [&](const Lighting& base, double& result_dbar, bool quick) -> std::optional<Lighting> {
    std::vector<Rgb> phi = model.responses(base);
    const std::vector<Rgb> l0 = fit_intensities(phi, base.size(), samples);
    const Lighting candidates = residual_candidates(combine(phi, l0, m), samples, *m_space, cell, 8);
    if (candidates.empty()) return std::nullopt;
    const std::vector<Rgb> candidate_phi = model.responses(candidates);
    size_t best = 0;
    double best_dbar = std::numeric_limits<double>::max();
    for (size_t c = 0; c < candidates.size(); ++c) {
      std::vector<Rgb> with = phi;
      with.insert(with.end(), candidate_phi.begin() + std::ptrdiff_t(c * m), candidate_phi.begin() + std::ptrdiff_t((c + 1) * m));
      const std::vector<Rgb> l = fit_intensities(with, base.size() + 1, samples);
      const double d = normalized_difference(combine(with, l, m), samples);
      if (d < best_dbar) best_dbar = d, best = c;
    }
    Lighting more = base;
    more.push_back(candidates[best]);
    if (quick) {
      const std::vector<Rgb> l = fit_intensities(model.responses(more), more.size(), samples);
      for (size_t j = 0; j < more.size(); ++j) more[j].intensity = l[j];
      result_dbar = best_dbar;
      return more;
    }
    more = refine_anchored(model, exact, more, result_dbar);
    return polish_with_reference(samples, more, false, result_dbar);
  };
  for (int round = 0; round < 8 + int(least) && (dbar > kVisibleDbar || lights.size() < least) && (most == 0 || lights.size() < most);
       ++round) {
    // One light more, kept by eq. 9 — or, when several lamps are missing and
    // each explains only its share, by eq. 6's measure: it takes away at
    // least ε_w of ‖Ψ‖ from the residual. Below the count asked for it is
    // kept anyway.
    double more_dbar = 0;
    const bool forced = lights.size() < least;
    auto more = with_best_candidate(lights, more_dbar, forced && lights.size() + 1 < least);
    const bool pays = more && more->size() > lights.size() &&
                      (lights.size() < least || dbar >= m_settings.eps_impro * more_dbar ||
                       dbar - more_dbar >= m_settings.seeding.weak_threshold);
    if (!pays) return lights;
    lights = std::move(*more);
    dbar = more_dbar;
  }
  return lights;
}

Lighting Solver::add_spots(const SampleSet& samples, double give_up_dbar, double& dbar) {
  if (m_progress) m_progress("screening spotlights");
  SpotProposalSettings settings;
  settings.max_spots = max_lights() ? std::min<size_t>(kMaxSpots, max_lights()) : kMaxSpots;  // the count rule
  settings.weak_threshold = m_settings.seeding.weak_threshold;
  settings.eps_impro = m_settings.eps_impro;
  settings.visible_dbar = kVisibleDbar;
  const Lighting spots = propose_spots(samples, *m_space, m_renderer, m_reference, settings, dbar);
  // Spots that explain less than the point lights did are not what the
  // target lacks (a painted patch no light makes): the reference polish and
  // the point lights beside them would cost 5x the proposal to lose.
  if (spots.empty() || dbar >= give_up_dbar) return {};
  return polish_with_reference(samples, spots, false, dbar);
}

Lighting Solver::merge_close_pairs(const SampleSet& samples, Lighting lights, double& dbar) {
  if (m_settings.fixed_count != 0) return lights;
  auto weight = [](const Light& l) { return double(l.intensity.r + l.intensity.g + l.intensity.b); };
  while (lights.size() > min_lights()) {
    size_t a = 0, b = 0;
    float nearest = std::numeric_limits<float>::max();
    for (size_t i = 0; i < lights.size(); ++i)
      for (size_t j = i + 1; j < lights.size(); ++j)
        if (lights[i].type == LightType::Point && lights[j].type == LightType::Point &&
            glm::length(lights[i].position - lights[j].position) < nearest)
          nearest = glm::length(lights[i].position - lights[j].position), a = i, b = j;
    if (nearest > 0.08f * m_scene->diagonal()) return lights;  // far apart: different lamps, not a split one
    const double wa = weight(lights[a]), wb = weight(lights[b]);
    if (!(wa + wb > 0)) return lights;
    Lighting merged;
    for (size_t i = 0; i < lights.size(); ++i)
      if (i != a && i != b) merged.push_back(lights[i]);
    const Vec3 position = Vec3((wa * DVec3(lights[a].position) + wb * DVec3(lights[b].position)) / (wa + wb));
    if (!m_space->admissible(position)) return lights;
    merged.insert(merged.begin() + std::ptrdiff_t(std::min(a, merged.size())), Light::point(position, lights[a].intensity + lights[b].intensity));
    double merged_dbar = 0;
    merged = polish_with_reference(samples, merged, false, merged_dbar);
    if (!(merged_dbar <= m_settings.eps_impro * dbar)) return lights;
    lights = std::move(merged);
    dbar = merged_dbar;
  }
  return lights;
}

Lighting Solver::split_lamps(const SampleSet& samples, Lighting lights, double& dbar) {
  const size_t most = max_lights();
  if (m_settings.fixed_count != 0 || dbar <= kSplitDbar || (most != 0 && lights.size() >= most)) return lights;
  const size_t m = samples.size();
  std::optional<LightCacheView> view;
  if (m_cache) view.emplace(*m_cache, *m_scene, samples);
  ResponseModel model(m_renderer, samples, view ? &*view : nullptr), exact(m_renderer, samples, nullptr);
  // Each sample's residual goes to the light that gives it the most light.
  const std::vector<Rgb> phi = model.responses(lights);
  const std::vector<Rgb> l = fit_intensities(phi, lights.size(), samples);
  const std::vector<Rgb> lit = combine(phi, l, m);
  std::vector<double> share(lights.size(), 0.0);
  double total = 0;
  for (size_t i = 0; i < m; ++i) {
    const DVec3 d = DVec3(samples.target[i]) - DVec3(lit[i]);
    const double r = double(samples.weight[i]) * glm::dot(d, d);
    size_t owner = 0;
    float brightest = -1.f;
    for (size_t j = 0; j < lights.size(); ++j) {
      const Rgb c = phi[j * m + i] * l[j];
      if (c.r + c.g + c.b > brightest) brightest = c.r + c.g + c.b, owner = j;
    }
    share[owner] += r, total += r;
  }
  const size_t j = size_t(std::max_element(share.begin(), share.end()) - share.begin());
  if (lights[j].type != LightType::Point || !(share[j] > 0.25 * total)) return lights;
  // Two halves a quarter of a seeding cell to either side, along each axis.
  const Vec3 extent = m_space->bounds().extent();
  const float offset = 0.25f * std::max({extent.x, extent.y, extent.z}) / float(2 * std::max(1, m_settings.seeding.coarse_cells));
  Lighting best;
  double best_dbar = dbar;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 step(0.f);
    step[axis] = offset;
    Lighting trial;
    for (size_t k = 0; k < lights.size(); ++k)
      if (k != j) trial.push_back(lights[k]);
    for (float side : {-1.f, 1.f}) {
      const Vec3 p = lights[j].position + side * step;
      if (!m_space->admissible(p)) break;
      trial.push_back(Light::point(p, 0.5f * lights[j].intensity));
    }
    if (trial.size() != lights.size() + 1) continue;
    double trial_dbar = 0;
    trial = refine_anchored(model, exact, trial, trial_dbar, RefineEffort::Polish);
    trial = polish_with_reference(samples, trial, false, trial_dbar);
    if (trial.size() == lights.size() + 1 && trial_dbar < best_dbar) best = std::move(trial), best_dbar = trial_dbar;
  }
  if (best.empty() || !(dbar >= m_settings.eps_impro * best_dbar)) return lights;  // eq. 9: the light more must pay
  dbar = best_dbar;
  return best;
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
  if (!m_settings.residual_samples || report.dbar <= 2e-3 || report.dbar <= 1.25 * report.dbar_samples) return lights;
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
  double dbar_samples = 0;
  Lighting polished = polish_with_reference(samples, lights, keep_count, dbar_samples);
  report.seconds["residual polish"] += polish_watch.seconds();
  Stopwatch again;
  const double dbar = normalized_difference(m_reference.illuminate(measured.points, polished), measured);
  report.seconds["evaluation"] += again.seconds();
  if (!(dbar < report.dbar)) return lights;
  report.dbar = dbar;
  report.dbar_samples = dbar_samples;
  report.residual_samples = added;
  report.samples = samples.size();
  return polished;
}

void Solver::finish_report(const Target& target, const Lighting& lights, SolveReport& report) {
  report.chosen = lights.size();
  report.target_points = target.size();
  if (report.dbar_points > 0) return;  // measured by polish_residuals
  Stopwatch watch;
  const SampleSet measured = evaluation_set(target);
  report.dbar = normalized_difference(m_reference.illuminate(measured.points, lights), measured);
  report.dbar_points = measured.size();
  report.seconds["evaluation"] += watch.seconds();
}

void Solver::require_admissible(const Lighting& lights, const std::string& what) const {
  for (size_t j = 0; j < lights.size(); ++j) {
    const Vec3& p = lights[j].position;
    const char* problem = !m_space->light_bounds().contains(p) ? "is outside the space lights may take (the scene's bounds)"
                          : m_rays->inside_solid(p)    ? "is inside solid geometry"
                                                       : nullptr;
    if (!problem) continue;
    std::ostringstream message;
    message << what << ": light " << j << " at (" << p.x << ", " << p.y << ", " << p.z << ") " << problem;
    throw InputError(message.str());
  }
}

SampleSet Solver::sample(const Target& target, SolveReport& report) {
  if (m_progress) m_progress("sampling");
  Stopwatch watch;
  const size_t count = m_settings.samples ? m_settings.samples : sample_count_for(target.size());
  SampleSet samples = m_sampler.draw(target, {count, neighbourhood_radius(), m_settings.seed});
  // Samples that miss every lit point cannot constrain anything (a tiny lit
  // patch in a huge target, too few samples): take every point instead.
  if (!(samples.target_norm() > 0.0)) samples = all_samples(target);
  report.samples = samples.size();
  report.seconds["sampling"] += watch.seconds();
  return samples;
}

Lighting Solver::solve(const Target& target, SolveReport& report) {
  Stopwatch total;
  open_space_for(m_settings.spot_hints);
  require_admissible(m_settings.spot_hints, "spot hints");
  Lighting lights = solve_in_space(target, report);
  // Lights inside cannot explain the target: perhaps it is lit from outside
  // (a product, a facade). Look again beyond the open sides; keep the better.
  const bool can_open = !m_settings.cache.open_space &&
                        (m_open_bounds.lo != m_closed_bounds.lo || m_open_bounds.hi != m_closed_bounds.hi);
  if (m_settings.open_space_dbar > 0 && report.dbar > m_settings.open_space_dbar && can_open &&
      !m_settings.placement.ceiling_offset) {
    if (m_progress) m_progress("looking beyond the scene's bounds");
    SolveReport open_report;
    open_report.seconds = report.seconds;
    open_space(true);
    Lighting open_lights = solve_in_space(target, open_report);
    if (open_report.dbar < 0.8 * report.dbar) {
      open_report.dbar_closed = report.dbar;
      open_report.open_space = true;
      report = std::move(open_report);
      lights = std::move(open_lights);
    } else {
      report.seconds = open_report.seconds;
      report.dbar_closed = report.dbar;
      open_space(false);
    }
  }
  // Point lights cannot explain the target, inside or beyond: spotlights
  // from nothing (point lights beside them where they pay) compete; the
  // fewer lights win unless the others improve D̄ by ε_impro (eq. 9).
  if (m_settings.propose_spots && report.dbar > kSpotDbar && m_settings.spot_hints.empty() && m_settings.fixed_count == 0) {
    if (m_progress) m_progress("looking for spotlights");
    SolveReport spot_report;
    spot_report.seconds = report.seconds;
    spot_report.open_space = report.open_space;
    spot_report.dbar_closed = report.dbar_closed;
    Lighting spots = spots_in_space(target, report.dbar_samples, spot_report);
    const size_t n_spots = spots.size(), n_points = lights.size();
    const double d_spots = spot_report.dbar, d_points = report.dbar, eps = m_settings.eps_impro;
    const bool counts = n_spots >= min_lights() && (max_lights() == 0 || n_spots <= max_lights());
    const bool spots_win = !spots.empty() && counts && (n_spots == n_points ? d_spots < d_points
                                              : n_spots < n_points ? d_spots < eps * d_points  // the extra point lights do not pay
                                                                   : d_points >= eps * d_spots);  // the extra lights pay
    if (spots_win) {
      report = std::move(spot_report);
      lights = std::move(spots);
    } else {
      report.seconds = spot_report.seconds;
    }
  }
  drop_idle_lights(lights);
  finish_report(target, lights, report);
  if (report.dbar > kPoorFitDbar) report.unreachable = unreachable_share(target, *m_space);
  report.seconds["total"] = total.seconds();
  return lights;
}

void Solver::drop_idle_lights(Lighting& lights) const {
  // A light a millionth as bright as the brightest does nothing a designer
  // could see; the fit sometimes parks one at ~0 instead of removing it.
  if (m_settings.fixed_count > 0) return;
  float brightest = 0.f;
  for (const auto& l : lights) brightest = std::max({brightest, l.intensity.r, l.intensity.g, l.intensity.b});
  Lighting kept;
  for (const auto& l : lights)
    if (l.type == LightType::Spot || std::max({l.intensity.r, l.intensity.g, l.intensity.b}) > 1e-6f * brightest)
      kept.push_back(l);  // spots stay: they are the user's hints
  if (!kept.empty() && kept.size() >= min_lights()) lights = std::move(kept);
}

void Solver::open_space(bool open) {
  const bool is_open = m_settings.cache.open_space;
  if (open == is_open) return;
  std::shared_ptr<const Regions> regions = m_space->shared_regions();  // copied: emplace destroys the old space first
  m_space.emplace(*m_rays, m_settings.placement, open ? m_open_bounds : m_closed_bounds, std::move(regions));
  m_settings.cache.open_space = open;
  std::swap(m_cache, m_other_cache);
  m_hierarchy.reset();
  m_cuts.clear();
}

void Solver::open_space_for(const Lighting& lights) {
  for (const auto& l : lights)
    if (!m_closed_bounds.contains(l.position) && m_open_bounds.contains(l.position)) return open_space(true);
}

Lighting Solver::solve_in_space(const Target& target, SolveReport& report) {
  ensure_cache(report);
  SampleSet samples = sample(target, report);
  Lighting found = solve_samples(samples, report);
  Stopwatch polish_watch;
  Lighting lights = polish_with_reference(samples, found, false, report.dbar_samples);
  lights = add_missing_lights(samples, std::move(lights), report.dbar_samples);
  report.seconds["reference polish"] += polish_watch.seconds();
  return finish_in_space(target, std::move(samples), std::move(lights), report);
}

Lighting Solver::spots_in_space(const Target& target, double points_dbar, SolveReport& report) {
  ensure_cache(report);
  SampleSet samples = sample(target, report);
  Stopwatch watch;
  Lighting lights = add_spots(samples, points_dbar, report.dbar_samples);
  if (!lights.empty()) lights = add_missing_lights(samples, std::move(lights), report.dbar_samples);
  report.seconds["spots"] += watch.seconds();
  if (lights.empty()) return lights;
  return finish_in_space(target, std::move(samples), std::move(lights), report);
}

Lighting Solver::finish_in_space(const Target& target, SampleSet samples, Lighting lights, SolveReport& report) {
  Stopwatch merge_watch;
  lights = merge_close_pairs(samples, std::move(lights), report.dbar_samples);
  for (int round = 0; round < 4; ++round) {  // each split must pay (eq. 9)
    const size_t before = lights.size();
    lights = split_lamps(samples, std::move(lights), report.dbar_samples);
    if (lights.size() == before) break;
  }
  report.seconds["reference polish"] += merge_watch.seconds();
  lights = polish_residuals(target, std::move(samples), lights, false, report);
  finish_report(target, lights, report);
  return lights;
}

Lighting Solver::fine_tune(const Target& target, const Lighting& lights, SolveReport& report) {
  Stopwatch total;
  open_space_for(lights);
  require_admissible(lights, "lights to fine-tune");
  ensure_cache(report);
  SampleSet samples = sample(target, report);
  // Anchored at the reference from the start: lights that already produce
  // the target have a zero objective and stay exactly where they are. One
  // round, and no residual polish: fine-tune follows the painter's strokes.
  Stopwatch refine_watch;
  Lighting refined = polish_with_reference(samples, lights, true, report.dbar_samples, 1);
  report.seconds["refinement"] += refine_watch.seconds();
  finish_report(target, refined, report);
  report.seconds["total"] = total.seconds();
  return refined;
}

Lighting Solver::add_lights(const Target& target, const Lighting& lights, SolveReport& report) {
  Stopwatch total;
  open_space_for(lights);
  open_space_for(m_settings.spot_hints);
  require_admissible(m_settings.spot_hints, "spot hints");
  ensure_cache(report);
  // ΔΨ = max(Ψ − I(L), 0): what the current lights leave to be lit.
  std::vector<Rgb> current = illumination(target, lights);
  Target missing = target;
  for (size_t i = 0; i < missing.size(); ++i) missing.value[i] = glm::max(target.value[i] - current[i], Rgb(0.f));
  // What is left below ε_w of the target is model noise, not a missing light.
  if (!(missing.norm() > m_settings.seeding.weak_threshold * target.norm()))
    throw InputError(target.source, "the given lights already produce the target to within " +
                                        std::to_string(int(std::round(100 * m_settings.seeding.weak_threshold))) + "%: nothing to add");
  SampleSet samples = sample(missing, report);
  Lighting added = polish_with_reference(samples, solve_samples(samples, report), false, report.dbar_samples);
  Lighting all = lights;
  all.insert(all.end(), added.begin(), added.end());
  finish_report(target, all, report);
  report.seconds["total"] = total.seconds();
  return all;
}

} // namespace hilight
