#include "core/solve_job.hpp"

#include "hilight/error.hpp"
#include "hilight/solve/diagnosis.hpp"

#include <chrono>
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

void SolveJob::start_solve(Target target, Lighting spot_hints) {
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
    std::function<void()> on_finished;
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      if (result.outcome == JobOutcome::Done && kind != JobKind::FineTune) {
        m_cuts_valid = true;
        m_cut_base = kind == JobKind::AddLights ? lights : Lighting{};
      }
      m_progress.clear();
      m_result = std::move(result);
      m_busy = false;
      on_finished = m_on_finished;
      m_done.notify_all();
    }
    if (on_finished) on_finished();
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
