#pragma once
/// Runs the shared pipeline (hilight::Solver, the same object `hilight solve`
/// drives) in a background thread: solve, fine-tune and add lights, with
/// progress text, a cancel request and a result the UI polls. The Solver and
/// its renderers live as long as the job, so the scene's BVH and light cache
/// are built once; only a change of spot hints (a Solver setting) makes a
/// new Solver (the light cache then comes back from `cache_dir` on disk when set).
///
/// The solve is assembled as the CLI assembles it (SolveSession): the
/// reference as configured and the renderer's declared fast twin for φ.
///
/// Cancelling: each job gets a stop token; cancel() requests it, and the
/// Solver throws SolveCancelled at its next stage or renderer batch
/// (solve/stoppable_renderer.hpp); the light cache's build is one batch.
#include "hilight/solve/criteria_in_scene.hpp"
#include "hilight/solve/fit_notes.hpp"
#include "hilight/solve/solve_session.hpp"
#include "hilight/registry.hpp"

#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <stop_token>
#include <thread>
#include <vector>

namespace hilight::painter {

/// Which plugins and settings, as `hilight solve` takes them (the spec's
/// spot_hints are ignored: pass them per solve).
using SolveJobOptions = SolveSpec;

enum class JobKind { Solve, FineTune, AddLights };
const char* to_string(JobKind kind);

/// Superseded: done, but the document changed while it ran (set by SessionPlayer).
enum class JobOutcome { Done, Failed, Cancelled, Superseded };

struct JobResult {
  JobKind kind = JobKind::Solve;
  JobOutcome outcome = JobOutcome::Done;
  Lighting lights;      ///< the result (Done only)
  SolveReport report;   ///< (Done only)
  std::string error;    ///< one line (Failed only)
  /// A poor fit (Done only): the scene vertices of the painted points that
  /// no place a light may stand can see (diagnosis.hpp, every painted point
  /// looked at); report.unreachable is their share of the painted light.
  std::vector<uint32_t> unreachable_vertices;
  /// A solve for lux criteria (SolveJob::set_criteria; Done only): each
  /// grid's maintained figures against what it asks, and the luminaires'
  /// count and flux, in the words `hilight solve` prints them (a grid not
  /// met is a warning); `criteria_met` when every one is.
  std::vector<FitNote> criteria_notes;
  bool criteria_met = false;
};

class SolveJob {
public:
  /// Creates the renderers, sampler and optimizer from `registry` (InputError
  /// for unknown or unavailable ones) and binds them to `scene`.
  SolveJob(const Registry& registry, std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays,
           SolveJobOptions options);
  /// Cancels a running job and waits for it.
  ~SolveJob();
  SolveJob(const SolveJob&) = delete;
  SolveJob& operator=(const SolveJob&) = delete;

  /// A lux target instead of paint (`hilight paint --target C.json`, the
  /// criteria in the scene file's coordinates): start_solve then places the
  /// luminaire (the options' settings.luminaire) for it as `hilight solve`
  /// does (criteria_in_scene.hpp), under the placement rules; fine-tune and
  /// add lights have nothing painted to work on. Not while busy.
  void set_criteria(IlluminanceCriteria criteria, CriteriaDesign design);
  bool has_criteria() const { return m_criteria.has_value(); }
  /// The criteria's file ("" without criteria).
  std::string criteria_source() const { return m_criteria ? m_criteria->source : std::string(); }

  /// Full solve of `target` (with criteria: of them, `target` unused);
  /// `spot_hints` are spotlights the designer asked for.
  void start_solve(Target target, Lighting spot_hints = {});
  /// Re-optimizes `lights` (the count never changes).
  void start_fine_tune(Target target, Lighting lights);
  /// Appends lights for what `lights` leave unlit; `lights` come back unchanged.
  void start_add_lights(Target target, Lighting lights);

  /// True from a start_* until the result is ready.
  bool busy() const { return m_busy.load(); }
  /// The stage the running job is in ("" when idle).
  std::string progress() const;
  /// Asks the running job to stop at its next stage (no-op when idle).
  void cancel() { m_stop.request_stop(); }
  /// Called on the worker thread when a job has finished and its result is
  /// ready (the window wakes its event loop with it). Set while idle.
  void set_on_finished(std::function<void()> callback);
  /// The finished job's result, once (nullopt while running or when taken).
  std::optional<JobResult> take_result();
  /// Blocks until the running job (if any) finishes, then takes its result;
  /// nullopt if there was none to take.
  std::optional<JobResult> wait();

  /// The light-count control: the last solve's (or add's) hierarchy cut with
  /// k point lights, no new solve. std::logic_error while busy or when no
  /// solve has finished since the last Solver was made.
  Lighting cut_lights(size_t k) const;
  /// Number of cuts available to cut_lights (0 if none).
  size_t cut_count() const;
  /// How many lights cut_lights puts before the cut (the lights an add kept; 0 after a solve).
  size_t cut_base_count() const;
  /// Forgets the last solve's cuts (its result was not used).
  void discard_cuts();
  /// Where the next solves' lights may stand (--place rules; the panel's
  /// "Placement"). Not while busy (std::logic_error).
  void set_placement(PlacementRules rules);

  /// The reference renderer (the user's settings), for the painter's own
  /// evaluations (region adjustment, shadow erase, display). Only while not
  /// busy(): the worker uses it.
  Renderer& renderer();
  /// A new renderer configured like the reference and bound to the scene, for
  /// the window's own evaluations while a job runs (each thread its own).
  std::unique_ptr<Renderer> make_renderer() const;
  const SolveJobOptions& options() const { return m_options; }
  const SolveSession& session() const { return *m_session; }

private:
  void start(JobKind kind, Target target, Lighting lights, Lighting spot_hints);
  void start_criteria();
  /// Hands a finished job's result over (the worker's last step).
  void finish(JobResult result, const Lighting& kept);
  Solver& solver_for(const Lighting& spot_hints);

  const Registry& m_registry;
  std::shared_ptr<const Scene> m_scene;
  std::shared_ptr<const RayScene> m_rays;
  SolveJobOptions m_options;
  std::unique_ptr<SolveSession> m_session;
  std::unique_ptr<Solver> m_solver;
  Lighting m_solver_hints;
  std::optional<IlluminanceCriteria> m_criteria;  ///< in the scene file's coordinates
  CriteriaDesign m_design;
  Lighting m_cut_base;  ///< lights an add kept (cut_lights puts them first)
  bool m_cuts_valid = false;

  std::thread m_worker;
  std::atomic<bool> m_busy{false};
  std::stop_source m_stop;  ///< the running job's: cancel() requests it, the Solver stops
  mutable std::mutex m_mutex;
  std::condition_variable m_done;
  std::string m_progress;
  std::optional<JobResult> m_result;
  std::function<void()> m_on_finished;
};

} // namespace hilight::painter
