#include "core/solve_job.hpp"

#include "hilight/error.hpp"
#include "hilight/solve/diagnosis.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hilight::painter {

const char* to_string(JobKind kind) {
  switch (kind) {
  case JobKind::Solve: return "solve";
  case JobKind::FineTune: return "fine-tune";
  case JobKind::AddLights: return "add lights";
  }
  return "?";
}

namespace {

/// A poor fit's cause, on every painted point (the solve itself looks at a
/// sample, and fine-tunes and adds not at all): the window marks them.
void diagnose(const Solver& solver, const Target& target, JobResult& result) {
  if (!solver.judge().poor_fit(result.report.dbar)) return;
  const auto start = std::chrono::steady_clock::now();
  const Unreachable found = find_unreachable(target, solver.light_space());
  result.report.seconds["diagnosis"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.report.unreachable = found.share;
  for (uint32_t i : found.points)
    if (target.vertex[i] >= 0) result.unreachable_vertices.push_back(uint32_t(target.vertex[i]));
}

/// A criteria solve's answer in `hilight solve`'s words: per grid, then the luminaires.
std::vector<FitNote> criteria_notes(const IlluminanceCriteria& criteria, const DesignReport& report, size_t count) {
  std::vector<FitNote> notes;
  for (size_t g = 0; g < criteria.grids.size() && g < report.figures.size(); ++g) {
    const CriterionGrid& c = criteria.grids[g];
    const GridFigures& f = report.figures[g];
    char text[256];
    std::snprintf(text, sizeof text, "%s: maintained Ē %.0f lx, U0 %.2f (wanted Ē ≥ %g, U0 ≥ %g)%s", c.name.c_str(), f.mean, f.u0, c.lux,
                  c.u0, f.met ? "" : ": not met");
    notes.push_back({!f.met, text});
  }
  char text[256];
  std::snprintf(text, sizeof text, "%zu luminaire%s, %.0f lm (least possible %.0f lm), MF %.2f, layout %s", count, count == 1 ? "" : "s",
                report.flux_lm, report.least_flux_lm, report.maintenance_factor, report.chosen.c_str());
  notes.push_back({false, text});
  if (std::isfinite(report.ugr) && report.luminous_area > 0) {
    std::snprintf(text, sizeof text, "UGR %.1f at the standard observers", report.ugr);
    notes.push_back({false, text});
  }
  if (!report.met && !report.unmet.empty()) notes.push_back({true, report.unmet});
  return notes;
}

/// Hints as the Solver sees them: only their shape (intensity is the solve's to find).
Lighting hint_shapes(Lighting hints) {
  for (auto& h : hints) h.intensity = Rgb(1.f);
  return hints;
}

} // namespace

SolveJob::SolveJob(const Registry& registry, std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays,
                   SolveJobOptions options)
    : m_registry(registry), m_scene(std::move(scene)), m_rays(std::move(rays)), m_options(std::move(options)) {
  m_options.settings.spot_hints.clear();
  m_session = std::make_unique<SolveSession>(registry, m_options, m_scene, m_rays);  // as `hilight solve` assembles it
}

SolveJob::~SolveJob() {
  m_stop.request_stop();
  if (m_worker.joinable()) m_worker.join();
}

Solver& SolveJob::solver_for(const Lighting& spot_hints) {
  if (!m_solver || hint_shapes(spot_hints) != m_solver_hints) {
    SolveSettings settings = m_options.settings;
    settings.spot_hints = hint_shapes(spot_hints);
    m_solver = m_session->make_solver(settings, [this](const std::string& stage) {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_progress = stage;
    });
    m_solver_hints = settings.spot_hints;
    m_cuts_valid = false;
  }
  return *m_solver;
}

void SolveJob::set_criteria(IlluminanceCriteria criteria, CriteriaDesign design) {
  if (m_busy) throw std::logic_error("SolveJob::set_criteria while busy");
  m_criteria = std::move(criteria);
  m_design = std::move(design);
}

void SolveJob::start_solve(Target target, Lighting spot_hints) {
  if (m_criteria) return start_criteria();
  start(JobKind::Solve, std::move(target), {}, std::move(spot_hints));
}
void SolveJob::start_fine_tune(Target target, Lighting lights) {
  start(JobKind::FineTune, std::move(target), std::move(lights), {});
}
void SolveJob::start_add_lights(Target target, Lighting lights) {
  start(JobKind::AddLights, std::move(target), std::move(lights), {});
}

void SolveJob::start(JobKind kind, Target target, Lighting lights, Lighting spot_hints) {
  if (m_busy) throw std::logic_error("SolveJob: a job is already running");
  if (m_worker.joinable()) m_worker.join();
  // Fine-tune uses no spot hints, so any Solver serves; the others need theirs
  // (add lights: none — the designer's spots are already among the lights).
  Solver& solver = kind == JobKind::FineTune && m_solver ? *m_solver : solver_for(spot_hints);
  if (kind != JobKind::FineTune) m_cuts_valid = false;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_result.reset();
    m_progress = "starting";
  }
  m_stop = std::stop_source();
  m_busy = true;
  m_worker = std::thread([this, kind, &solver, target = std::move(target), lights = std::move(lights), stop = m_stop.get_token()]() {
    JobResult result;
    result.kind = kind;
    try {
      result.lights = kind == JobKind::Solve      ? solver.solve(target, result.report, stop)
                      : kind == JobKind::FineTune ? solver.fine_tune(target, lights, result.report, stop)
                                                  : solver.add_lights(target, lights, result.report, stop);
      diagnose(solver, target, result);
      result.outcome = JobOutcome::Done;
    } catch (const SolveCancelled&) {
      result.outcome = JobOutcome::Cancelled;
    } catch (const std::exception& e) {
      result.outcome = JobOutcome::Failed;
      result.error = e.what();
    }
    finish(std::move(result), lights);
  });
}

void SolveJob::finish(JobResult result, const Lighting& kept) {
  std::function<void()> on_finished;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (result.outcome == JobOutcome::Done && result.kind != JobKind::FineTune && !m_criteria) {
      m_cuts_valid = true;
      m_cut_base = result.kind == JobKind::AddLights ? kept : Lighting{};
    }
    m_progress.clear();
    m_result = std::move(result);
    m_busy = false;
    on_finished = m_on_finished;
    m_done.notify_all();
  }
  if (on_finished) on_finished();
}

void SolveJob::start_criteria() {
  if (m_busy) throw std::logic_error("SolveJob: a job is already running");
  if (m_worker.joinable()) m_worker.join();
  criteria_luminaire(m_options.settings.luminaire, m_criteria->source);  // before the worker: an input error of the action
  m_cuts_valid = false;
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_result.reset();
    m_progress = "placing the luminaires";
  }
  m_stop = std::stop_source();
  m_busy = true;
  // The design itself cannot stop midway: a cancel takes effect when it ends.
  m_worker = std::thread([this, stop = m_stop.get_token()]() {
    JobResult result;
    result.kind = JobKind::Solve;
    try {
      IlluminanceCriteria criteria = *m_criteria;  // moved into the scene's frame by the design
      PlacementRules rules = m_options.settings.placement;
      DesignReport report;
      result.lights = design_in_scene(m_session->reference(), *m_scene, *m_rays, criteria, rules, *m_options.settings.luminaire,
                                      m_design, report);
      result.report.chosen = result.lights.size();
      result.report.seconds = report.seconds;
      result.criteria_met = report.met;
      result.criteria_notes = criteria_notes(criteria, report, result.lights.size());
      result.outcome = stop.stop_requested() ? JobOutcome::Cancelled : JobOutcome::Done;
    } catch (const std::exception& e) {
      result.outcome = JobOutcome::Failed;
      result.error = e.what();
    }
    finish(std::move(result), {});
  });
}

void SolveJob::set_on_finished(std::function<void()> callback) {
  std::lock_guard<std::mutex> lock(m_mutex);
  m_on_finished = std::move(callback);
}

std::string SolveJob::progress() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_progress;
}

std::optional<JobResult> SolveJob::take_result() {
  std::lock_guard<std::mutex> lock(m_mutex);
  std::optional<JobResult> result = std::move(m_result);
  m_result.reset();
  return result;
}

std::optional<JobResult> SolveJob::wait() {
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    m_done.wait(lock, [this] { return !m_busy.load(); });
  }
  if (m_worker.joinable()) m_worker.join();
  return take_result();
}

Lighting SolveJob::cut_lights(size_t k) const {
  if (m_busy) throw std::logic_error("SolveJob: cut_lights while a job runs");
  if (!m_cuts_valid || !m_solver) throw std::logic_error("SolveJob: no finished solve to take cuts from");
  Lighting lights = m_cut_base;  // after an add: the lights it kept, then the added cut
  Lighting cut = m_solver->cut_lights(k);
  lights.insert(lights.end(), cut.begin(), cut.end());
  return lights;
}

size_t SolveJob::cut_count() const {
  if (m_busy || !m_cuts_valid || !m_solver) return 0;
  return m_solver->cut_count();
}

void SolveJob::set_placement(PlacementRules rules) {
  if (m_busy) throw std::logic_error("SolveJob::set_placement while busy");
  m_options.settings.placement = std::move(rules);
  m_solver.reset();  // the next job makes a Solver with the new rules
  m_cuts_valid = false;
}

size_t SolveJob::cut_base_count() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  return m_cut_base.size();
}

void SolveJob::discard_cuts() {
  std::lock_guard<std::mutex> lock(m_mutex);
  m_cuts_valid = false;
}

std::unique_ptr<Renderer> SolveJob::make_renderer() const { return m_session->make_renderer(m_session->reference_settings()); }

Renderer& SolveJob::renderer() {
  if (m_busy) throw std::logic_error("SolveJob: the renderer is in use by a running job");
  return m_session->reference();
}

} // namespace hilight::painter
