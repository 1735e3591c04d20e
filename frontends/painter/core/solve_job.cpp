#include "core/solve_job.hpp"

#include "core/cancellable_renderer.hpp"
#include "hilight/error.hpp"

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

bool has_setting(const std::vector<std::string>& settings, const std::string& key) {
  for (const auto& kv : settings)
    if (kv.rfind(key + "=", 0) == 0) return true;
  return false;
}

bool same_hints(const Lighting& a, const Lighting& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].position != b[i].position || a[i].direction != b[i].direction || a[i].cutoff_deg != b[i].cutoff_deg ||
        a[i].falloff_deg != b[i].falloff_deg)
      return false;
  return true;
}

} // namespace

SolveJob::SolveJob(const Registry& registry, std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays,
                   SolveJobOptions options)
    : m_registry(registry), m_scene(std::move(scene)), m_rays(std::move(rays)), m_options(std::move(options)) {
  // As `hilight solve` does: the renderer's sample streams follow the solve's
  // seed, the reference is the renderer as configured, and for Embree the
  // solve's own φ uses the fast bounce (direct light interpolated at vertices).
  std::vector<std::string> settings = m_options.renderer_settings;
  if (!has_setting(settings, "seed")) settings.push_back("seed=" + std::to_string(m_options.solve.seed & 0x7FFFFFFFFFFFFFFFull));
  m_reference_settings = settings;
  m_reference = make_renderer();
  if (m_options.renderer == "embree" && !has_setting(settings, "bounce_direct")) settings.push_back("bounce_direct=vertex");
  m_fast = registry.create_renderer(m_options.renderer, Properties::from_assignments(settings));
  m_fast->set_scene(m_scene);
  m_fast_guarded = std::make_unique<CancellableRenderer>(*m_fast, m_cancel);
  m_reference_guarded = std::make_unique<CancellableRenderer>(*m_reference, m_cancel);
  m_sampler = registry.create_sampler(m_options.sampler, {});
  m_optimizer = registry.create_optimizer(m_options.optimizer, Properties::from_assignments(m_options.optimizer_settings));
  m_options.solve.spot_hints.clear();
}

SolveJob::~SolveJob() {
  m_cancel = true;
  if (m_worker.joinable()) m_worker.join();
}

Solver& SolveJob::solver_for(const Lighting& spot_hints) {
  if (!m_solver || !same_hints(spot_hints, m_solver_hints)) {
    SolveSettings settings = m_options.solve;
    settings.spot_hints = spot_hints;
    for (auto& h : settings.spot_hints) h.intensity = Rgb(1.f);
    m_solver = std::make_unique<Solver>(m_scene, m_rays, *m_fast_guarded, *m_reference_guarded, *m_sampler, *m_optimizer, settings,
                                        [this](const std::string& stage) {
                                          if (m_cancel) throw SolveCancelled();
                                          std::lock_guard<std::mutex> lock(m_mutex);
                                          m_progress = stage;
                                        });
    m_solver_hints = spot_hints;
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
  m_cancel = false;
  m_busy = true;
  m_worker = std::thread([this, kind, &solver, target = std::move(target), lights = std::move(lights)]() {
    JobResult result;
    result.kind = kind;
    try {
      result.lights = kind == JobKind::Solve      ? solver.solve(target, result.report)
                      : kind == JobKind::FineTune ? solver.fine_tune(target, lights, result.report)
                                                  : solver.add_lights(target, lights, result.report);
      result.outcome = JobOutcome::Done;
    } catch (const SolveCancelled&) {
      result.outcome = JobOutcome::Cancelled;
    } catch (const std::exception& e) {
      result.outcome = JobOutcome::Failed;
      result.error = e.what();
    }
    std::lock_guard<std::mutex> lock(m_mutex);
    if (result.outcome == JobOutcome::Done && kind != JobKind::FineTune) {
      m_cuts_valid = true;
      m_cut_base = kind == JobKind::AddLights ? lights : Lighting{};
    }
    m_progress.clear();
    m_result = std::move(result);
    m_busy = false;
    m_done.notify_all();
  });
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

std::unique_ptr<Renderer> SolveJob::make_renderer() const {
  auto renderer = m_registry.create_renderer(m_options.renderer, Properties::from_assignments(m_reference_settings));
  renderer->set_scene(m_scene);
  return renderer;
}

Renderer& SolveJob::renderer() {
  if (m_busy) throw std::logic_error("SolveJob: the renderer is in use by a running job");
  return *m_reference;
}

} // namespace hilight::painter
