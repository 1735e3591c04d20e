#include "hilight/solve/solver.hpp"
#include "hilight/solve/luminaire_aim.hpp"

#include "hilight/error.hpp"
#include "hilight/light_bounds.hpp"
#include "hilight/light_cache_file.hpp"
#include "hilight/light_cache_store.hpp"
#include "hilight/solve/alternative.hpp"
#include "hilight/solve/cuts.hpp"
#include "hilight/solve/diagnosis.hpp"
#include "hilight/solve/fit.hpp"
#include "hilight/solve/gauss_newton.hpp"
#include "hilight/solve/refine_problem.hpp"
#include "hilight/solve/solve_context.hpp"
#include "hilight/solve/solve_plans.hpp"
#include "hilight/solve/spot_proposals.hpp"
#include "solver_internal.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <tbb/task_group.h>
#include <cstdio>
#include <sstream>

namespace hilight {

using namespace solver_detail;

namespace {

std::string hex(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

} // namespace

JudgeSettings judge_settings(const SolveSettings& settings) {
  JudgeSettings j;
  j.eps_impro = settings.eps_impro;
  j.eps_w = settings.seeding.weak_threshold;
  j.eps_opt = settings.eps_opt;
  j.n_cut = settings.n_cut;
  j.fixed_count = settings.fixed_count;
  j.min_count = settings.placement.min_count;
  j.max_count = settings.placement.max_count;
  return j;
}

size_t sample_count_for(size_t target_points) { return std::clamp<size_t>((target_points + 7) / 14, 3000, 10000); }

Solver::Solver(std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays, Renderer& renderer,
               Renderer& reference, Sampler& sampler, Optimizer& optimizer, const LightCacheBuilder* cache,
               SolveSettings settings, ProgressFn progress)
    : m_scene(std::move(scene)), m_rays(std::move(rays)), m_closed_bounds(m_scene->light_bounds()),
      m_open_bounds(open_light_bounds(*m_scene)), m_space(std::in_place, *m_rays, settings.placement, m_closed_bounds),
      m_luminaire_renderer(settings.luminaire ? std::optional<LuminaireRenderer>(std::in_place, renderer, *settings.luminaire) : std::nullopt),
      m_luminaire_reference(settings.luminaire ? std::optional<LuminaireRenderer>(std::in_place, reference, *settings.luminaire) : std::nullopt),
      m_stoppable_renderer(m_luminaire_renderer ? static_cast<Renderer&>(*m_luminaire_renderer) : renderer, m_stop),
      m_stoppable_reference(m_luminaire_reference ? static_cast<Renderer&>(*m_luminaire_reference) : reference, m_stop),
      m_renderer(m_stoppable_renderer),
      m_reference(m_stoppable_reference), m_sampler(sampler),
      m_optimizer(optimizer), m_cache_builder(cache),
      m_settings(std::move(settings)), m_judge(judge_settings(m_settings)), m_progress(std::move(progress)) {}

Fit Solver::run(const Plan& plan, const Target& target, const SampleSet& samples, SolveReport& report, Fit start) {
  SolveContext ctx{*m_scene, target,   samples, *m_space, m_renderer, m_reference, m_cache.get(), m_optimizer,
                   m_judge,  m_settings, m_stop,  m_progress, report,   m_products};
  return run_plan(plan, ctx, std::move(start));
}

void Solver::stage(const std::string& name) const { announce_stage(m_stop, m_progress, name); }

float Solver::neighbourhood_radius() const {
  // Two tessellation edges, within [diagonal/1000, diagonal/20]: a coarse
  // --max-edge must not make "local" the whole scene (quadratic sampling).
  const float d = m_scene->diagonal();
  return std::clamp(2.f * m_scene->max_edge, 1e-3f * d, 0.05f * d);
}

void Solver::ensure_cache(SolveReport& report) {
  if (!m_cache_builder) {
    report.cache_state = "off";
    return;
  }
  if (m_cache) {
    report.cache_state = "in memory";
    return;
  }
  Stopwatch watch;
  const Bounds bounds = m_open ? m_open_bounds : m_closed_bounds;
  const uint64_t key = light_cache_key(*m_scene, m_renderer.settings_key(), m_cache_builder->settings_key(), bounds);
  std::filesystem::path file;
  if (!m_settings.cache_dir.empty()) {
    file = m_settings.cache_dir / ("lightcache-" + hex(key) + ".bin");
    LoadedCache loaded = load_light_cache(file, key, *m_cache_builder, m_scene->positions.size());
    m_cache = std::move(loaded.cache);
    if (!loaded.damage.empty())
      std::fprintf(stderr, "hilight: warning: light cache %s is unusable: %s; building it again\n", file.c_str(),
                   loaded.damage.c_str());
  }
  if (m_cache) {
    report.cache_state = "loaded";
    touch_cache_file(file);  // recently used: evicted last
  } else {
    stage("building the light cache");
    m_cache = m_cache_builder->build({*m_scene, *m_rays, m_renderer, bounds});
    // Its bounce gathers at every vertex (hundreds of MB in a building) are
    // not needed again: the solve works on its samples and the target.
    m_renderer.release_scratch();
    report.cache_state = "built";
    if (!file.empty()) {
      try {
        save_light_cache(file, key, *m_cache);
        evict_cache(m_settings.cache_dir, m_settings.cache_cap_bytes, file);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "hilight: warning: light cache not saved to %s: %s\n", file.c_str(), e.what());
      }
    }
  }
  report.seconds["cache"] += watch.seconds();
}

Lighting Solver::cut_lights(size_t k) const {
  if (m_products.cuts.empty()) throw std::logic_error("Solver::cut_lights: no solve yet");
  return to_output(m_products.cuts[std::clamp<size_t>(k, 1, m_products.cuts.size()) - 1]);
}

Lighting Solver::to_points(const Lighting& lights) const {
  return m_settings.luminaire ? as_points(lights, *m_settings.luminaire) : lights;
}

Lighting Solver::to_output(Lighting lights) const {
  return m_settings.luminaire ? as_luminaires(lights, *m_settings.luminaire) : lights;
}

std::vector<Rgb> Solver::illumination(const Target& target, const Lighting& lights) {
  return m_reference.illuminate(target.points, lights);
}

double Solver::measure_dbar(const Target& target, const Lighting& lights) {
  SampleSet measured = evaluation_set(target, m_settings.evaluation_points);
  return normalized_difference(m_reference.illuminate(measured.points, lights), measured);
}


void Solver::finish_report(const Target& target, const Lighting& lights, SolveReport& report) {
  report.chosen = lights.size();
  report.target_points = target.size();
  if (report.dbar_points > 0) return;  // measured by polish_residuals
  Stopwatch watch;
  const SampleSet measured = evaluation_set(target, m_settings.evaluation_points);
  report.dbar = normalized_difference(m_reference.illuminate(measured.points, lights), measured);
  report.dbar_points = measured.size();
  report.seconds["evaluation"] += watch.seconds();
}

void Solver::require_admissible(const Lighting& lights, const std::string& what) const {
  for (size_t j = 0; j < lights.size(); ++j)
    if (lights[j].type == LightType::Luminaire || is_area(lights[j].type))
      throw InputError(what + ": light " + std::to_string(j) + " is a luminaire or an area source; the solve optimizes those only as --luminaire or --area-light");
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
  stage("sampling");
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

/// The whole-answer alternatives' view of this Solver, bound to the target
/// being solved: only what AlternativeContext lets them do.
class Solver::AlternativeHost final : public AlternativeContext {
public:
  AlternativeHost(Solver& solver, const Target& target) : m_solver(solver), m_target(target) {}
  const Judge& judge() const override { return m_solver.m_judge; }
  const SolveSettings& settings() const override { return m_solver.m_settings; }
  void stage(const std::string& name) const override { m_solver.stage(name); }
  Lighting solve_points(SolveReport& report) override { return m_solver.solve_in_space(m_target, report); }
  Lighting solve_spots(double points_dbar, SolveReport& report) override {
    return m_solver.spots_in_space(m_target, points_dbar, report);
  }
  bool can_open_space() const override { return m_solver.can_open_space(); }
  void open_space(bool open) override { m_solver.open_space(open); }
  void turn_luminaire(float spin_deg) override { m_solver.turn_luminaire(spin_deg); }

private:
  Solver& m_solver;
  const Target& m_target;
};

Lighting Solver::solve(const Target& target, SolveReport& report, std::stop_token stop) {
  m_stop = std::move(stop);
  Stopwatch total;
  open_space_for(m_settings.spot_hints);
  require_admissible(m_settings.spot_hints, "spot hints");
  // Chosen before the solve: the luminaire's turns start from its spin now.
  const Alternatives alternatives = answer_alternatives(m_settings);
  Answer answer{{}, std::move(report)};
  answer.lights = solve_in_space(target, answer.report);
  AlternativeHost host(*this, target);
  answer = run_alternatives(alternatives, host, std::move(answer));
  report = std::move(answer.report);
  Lighting lights = std::move(answer.lights);
  drop_idle_lights(lights);
  if (const Plan aim = aim_plan(m_settings); !aim.steps.empty() && !lights.empty()) {
    // An asymmetric luminaire: each one's turn about its aim, on samples of
    // their own, then measured again.
    stage("aiming the luminaires");
    const SampleSet samples = sample(target, report);
    Fit aimed = run(aim, target, samples, report, Fit{to_output(std::move(lights)), report.dbar_samples});
    lights = std::move(aimed.lights);
    report.dbar_points = 0;
  }
  finish_report(target, lights, report);
  if (m_judge.poor_fit(report.dbar)) report.unreachable = unreachable_share(target, *m_space);
  report.seconds["total"] = total.seconds();
  return to_output(std::move(lights));
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
  if (open == m_open) return;
  std::shared_ptr<const Regions> regions = m_space->shared_regions();  // copied: emplace destroys the old space first
  m_space.emplace(*m_rays, m_settings.placement, open ? m_open_bounds : m_closed_bounds, std::move(regions));
  m_open = open;
  std::swap(m_cache, m_other_cache);
  m_products.hierarchy.reset();
  m_products.cuts.clear();
}

bool Solver::can_open_space() const {
  return !m_open && (m_open_bounds.lo != m_closed_bounds.lo || m_open_bounds.hi != m_closed_bounds.hi);
}

void Solver::open_space_for(const Lighting& lights) {
  for (const auto& l : lights)
    if (!m_closed_bounds.contains(l.position) && m_open_bounds.contains(l.position)) return open_space(true);
}

Lighting Solver::solve_in_space(const Target& target, SolveReport& report) {
  ensure_cache(report);
  const SampleSet samples = sample(target, report);
  Fit fit = run(point_plan(m_settings), target, samples, report, Fit{});
  finish_report(target, fit.lights, report);
  return std::move(fit.lights);
}

void Solver::turn_luminaire(float spin_deg) {
  if (m_settings.luminaire->spin_deg == spin_deg) return;
  m_settings.luminaire->spin_deg = spin_deg;
  m_luminaire_renderer->set_luminaire(*m_settings.luminaire);
  m_luminaire_reference->set_luminaire(*m_settings.luminaire);
  // A light cache is of one luminaire turned one way (its key says so).
  m_cache.reset();
  m_other_cache.reset();
}

Lighting Solver::spots_in_space(const Target& target, double points_dbar, SolveReport& report) {
  ensure_cache(report);
  const SampleSet samples = sample(target, report);
  Fit fit = run(spot_plan(m_settings, points_dbar), target, samples, report, Fit{});
  if (fit.lights.empty()) return {};
  finish_report(target, fit.lights, report);
  return std::move(fit.lights);
}

Lighting Solver::fine_tune(const Target& target, const Lighting& given, SolveReport& report, std::stop_token stop) {
  const Lighting lights = to_points(given);
  m_stop = std::move(stop);
  Stopwatch total;
  open_space_for(lights);
  require_admissible(lights, "lights to fine-tune");
  ensure_cache(report);
  SampleSet samples = sample(target, report);
  // Anchored at the reference from the start: lights that already produce
  // the target have a zero objective and stay exactly where they are. One
  // round, and no residual polish: fine-tune follows the painter's strokes.
  Fit fit = run(fine_tune_plan(m_settings), target, samples, report, Fit{lights, 1.0});
  finish_report(target, fit.lights, report);
  report.seconds["total"] = total.seconds();
  return to_output(std::move(fit.lights));
}

Lighting Solver::add_lights(const Target& target, const Lighting& given, SolveReport& report, std::stop_token stop) {
  const Lighting lights = to_points(given);
  m_stop = std::move(stop);
  Stopwatch total;
  open_space_for(lights);
  open_space_for(m_settings.spot_hints);
  require_admissible(m_settings.spot_hints, "spot hints");
  for (size_t j = 0; j < lights.size(); ++j)
    if (lights[j].type == LightType::Luminaire || is_area(lights[j].type))
      throw InputError("lights to add to: light " + std::to_string(j) + " is a luminaire or an area source; the solve optimizes those only as --luminaire or --area-light");
  ensure_cache(report);
  // ΔΨ = max(Ψ − I(L), 0): what the current lights leave to be lit.
  std::vector<Rgb> current = illumination(target, lights);
  Target missing = target;
  for (size_t i = 0; i < missing.size(); ++i) missing.value[i] = glm::max(target.value[i] - current[i], Rgb(0.f));
  // What is left below ε_w of the target is model noise, not a missing light.
  if (!(missing.norm() > m_judge.eps_w() * target.norm()))
    throw InputError(target.source, "the given lights already produce the target to within " +
                                        std::to_string(int(std::round(100 * m_judge.eps_w()))) + "%: nothing to add");
  SampleSet samples = sample(missing, report);
  Fit added = run(add_plan(m_settings), missing, samples, report, Fit{});
  Lighting all = lights;
  all.insert(all.end(), added.lights.begin(), added.lights.end());
  finish_report(target, all, report);
  report.seconds["total"] = total.seconds();
  return to_output(std::move(all));
}

} // namespace hilight
