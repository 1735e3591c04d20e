#pragma once
/// The shared pipeline of every frontend: samples → light cache → seeding →
/// hierarchy → cuts → refinement → light count; plus the editing modes of
/// §4.2 (fine-tune, add lights). The CLI and the painter both call this.
#include "hilight/light_cache.hpp"
#include "hilight/light_space.hpp"
#include "hilight/optimizer.hpp"
#include "hilight/sampler.hpp"
#include "hilight/solve/fit.hpp"
#include "hilight/solve/hierarchy.hpp"
#include "hilight/solve/judge.hpp"
#include "hilight/solve/seeder.hpp"
#include "hilight/solve/luminaire_renderer.hpp"
#include "hilight/solve/move.hpp"
#include "hilight/solve/stoppable_renderer.hpp"
#include "hilight/target.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace hilight {

/// Default cap on the points D̄ is measured on (SolveSettings::evaluation_points).
constexpr size_t kDefaultEvaluationPoints = 20000;

struct SolveSettings {
  size_t samples = 0;                ///< surface samples drawn by the sampler (0: sample_count_for(target points))
  uint64_t seed = 1;                 ///< sampling seed
  SeedSettings seeding;
  HierarchySettings hierarchy;
  std::filesystem::path cache_dir;   ///< empty: keep the cache in memory only
  uint64_t cache_cap_bytes = 1024ull << 20;  ///< the folder's size cap (least recently used files go first)
  size_t n_cut = 4;                  ///< N_cut: cuts refined
  double eps_opt = 0.15;             ///< ε_opt: only cuts with D̄ below are refined
  double eps_impro = 1.6;            ///< ε_impro of eq. 9
  size_t fixed_count = 0;            ///< --lights N (0: automatic)
  /// Target points D̄ is measured on: every point up to this many, else this
  /// many evenly spaced (an estimate; 0: always every point). The exact
  /// bounce over a 138k-point building costs 4.9 s for 6 lights on 2 cores.
  size_t evaluation_points = kDefaultEvaluationPoints;
  bool residual_samples = true;      ///< after the fit, add the worst-explained points as samples and polish
  Lighting spot_hints;               ///< spotlights the user asked for
  PlacementRules placement;          ///< where lights may stand (--place)
  /// When the lights found inside the scene's light bounds leave D̄ above
  /// this, the solve looks again with lights allowed beyond its open sides
  /// (open_light_bounds(): a product lit from outside) and keeps the better
  /// answer. 0: never.
  double open_space_dbar = 0.05;
  /// When point lights (inside and beyond the open sides) leave D̄ above 5%,
  /// look for spotlights from nothing (no hints; solve/spot_proposals.hpp)
  /// and keep them if they win by eq. 9 (docs/solve.md, "Spotlights").
  bool propose_spots = true;
  /// Fine-tune's lights, after its Gauss–Newton round, settled as the spot
  /// search settles its answer (held bounce, simplex, the bounce's spikes
  /// left out; kept where the reference says it fits better): with the
  /// bounce the polish's slopes run through the gathers and stall
  /// centimetres off. It renders the direct light hundreds of times:
  /// seconds with a renderer whose direct light is cheap
  /// (RendererTraits::cheap_direct), not the painter's tenths (`hilight
  /// solve --mode fine-tune` turns it on with the bounce and such a renderer).
  bool settle_fine_tune = false;
  /// Every light the solve places is this luminaire (`--luminaire FILE`):
  /// its profile, aim and spin; the solve chooses positions, count and
  /// intensities (solve/luminaire_renderer.hpp).
  std::optional<Light> luminaire;
};

/// The automatic sample count: one sample per 14 target points, within
/// [3000, 10000]. A large target needs more samples to see each room's hot
/// spots (measured on the 108k-point IFC house: 3000 samples left a ceiling
/// lamp 2–4 cm off, 8000 found it), a small one is covered by 3000.
size_t sample_count_for(size_t target_points);

/// The judge's settings from the solve's: ε_impro, ε_w, ε_opt, N_cut and the count bounds.
JudgeSettings judge_settings(const SolveSettings& settings);

struct CutRecord {
  size_t lights = 0;        ///< point lights of the cut (spots are added to every cut)
  double dbar_initial = 0;  ///< D̄ at the samples, intensities re-fitted by NNLS
  bool refined = false;
  double dbar_refined = 0;
  Lighting refined_lights;  ///< may hold fewer lights: weak ones are pruned after refinement
};

/// One stage of a solve (a move of its plan, or a whole alternative such as
/// the open space or the spot search): what it cost and what it did.
struct StageRecord {
  std::string name;
  double seconds = 0;
  double dbar_before = 0, dbar_after = 0;  ///< D̄ at the samples (target: over the target points, as SolveReport::dbar)
  bool target = false;  ///< D̄ measured over the target points, not the samples
  bool kept = false;    ///< the stage changed the answer (its proposal won)
  std::string skipped;  ///< why it did not run (its premise failed); empty when it ran
};

struct SolveReport {
  size_t chosen = 0;                 ///< lights in the result (point + spot)
  double dbar = 0;                   ///< D̄ of the result over the target, by the reference renderer
  size_t dbar_points = 0;            ///< target points dbar was measured on (all unless evaluation_points)
  double dbar_samples = 0;           ///< ...and over the samples (the solve's own objective)
  size_t residual_samples = 0;       ///< samples added where the fit explained the target worst
  std::vector<CutRecord> cuts;       ///< in order of light count
  std::vector<double> improvement;   ///< eq. 9 between consecutive cuts
  size_t samples = 0, target_points = 0;
  size_t seed_lights = 0, seeds_tried = 0;
  std::string cache_state;           ///< "loaded", "built", "off"
  bool open_space = false;           ///< lights were sought beyond the scene's bounds (open_light_bounds())
  double dbar_closed = -1;           ///< when that was tried: D̄ of the best answer inside the bounds
  double unreachable = 0;            ///< poor fits: share of the target no allowed light position sees (diagnosis.hpp)
  std::map<std::string, double> seconds;
  std::vector<StageRecord> stages;   ///< in the order they ran, skipped ones included
};

using ProgressFn = std::function<void(const std::string& stage)>;

/// What a solve leaves for later calls: the hierarchy and every cut (the
/// painter's count control moves along them without a new solve).
struct SolveProducts {
  std::optional<LightHierarchy> hierarchy;
  std::vector<Lighting> cuts;  ///< index k-1: the cut with k point lights
};



/// A solve session over one scene: keeps the ray scene, renderer and light
/// cache alive so later edits (fine-tune, add) reuse them.
class Solver {
public:
  /// `renderer`: what the solve evaluates φ with (fast settings); `reference`:
  /// what D̄ is measured with (the user's settings, as `hilight render` uses
  /// them; may be the same object). Both bound to `scene`.
  /// `cache`: the light cache plugin (nullptr: every φ from the renderer).
  Solver(std::shared_ptr<const Scene> scene, std::shared_ptr<const RayScene> rays, Renderer& renderer,
         Renderer& reference, Sampler& sampler, Optimizer& optimizer, const LightCacheBuilder* cache,
         SolveSettings settings, ProgressFn progress = {});
  Solver(const Solver&) = delete;  // its renderers hold a reference to its stop token
  Solver& operator=(const Solver&) = delete;

  /// Full solve: the lights for `target`. Each of these calls throws
  /// SolveCancelled once `stop` is requested (solve/stoppable_renderer.hpp).
  Lighting solve(const Target& target, SolveReport& report, std::stop_token stop = {});
  /// Re-optimizes `lights` against `target` without adding or removing any
  /// (a polish: after an edit the lights start near their new optimum).
  Lighting fine_tune(const Target& target, const Lighting& lights, SolveReport& report, std::stop_token stop = {});
  /// Solves for max(Ψ − I(lights), 0) and returns `lights` followed by the new ones.
  Lighting add_lights(const Target& target, const Lighting& lights, SolveReport& report, std::stop_token stop = {});

  /// Illumination of `lights` at every target point from the solve's renderer
  /// (no light cache).
  std::vector<Rgb> illumination(const Target& target, const Lighting& lights);
  /// D̄ of `lights` on the target, measured with the reference renderer.
  double measure_dbar(const Target& target, const Lighting& lights);
  /// The one judge of every count decision and threshold (judge.hpp).
  const Judge& judge() const { return m_judge; }
  /// Where lights may stand now (the last call's space: closed, or open).
  const LightSpace& light_space() const { return *m_space; }
  /// InputError unless every light may stand where it is (in bounds, out of solids).
  void require_admissible(const Lighting& lights, const std::string& what) const;
  /// The hierarchy of the last solve (for moving between cuts).
  const std::optional<LightHierarchy>& hierarchy() const { return m_products.hierarchy; }
  /// Number of cuts of the last solve (point lights of its largest cut).
  size_t cut_count() const { return m_products.cuts.size(); }
  /// The lights of the last solve's (or add's: the added lights') cut with
  /// `k` point lights (k clamped to [1, cut_count()]), refined if the solve
  /// refined it — refinement may have pruned weak lights, so a refined cut
  /// can hold fewer — else with NNLS intensities; spots included. Moving the
  /// light count along the hierarchy needs no new solve (paper §3.3, the
  /// painter's count control). Throws std::logic_error before any solve or
  /// after a solve that found only spotlights (no cuts).
  Lighting cut_lights(size_t k) const;

private:
  /// What the whole-answer alternatives (alternative.hpp) may do, over this
  /// Solver and one target (solver.cpp).
  class AlternativeHost;

  /// The point-light solve in the current light space: seeding to residual polish.
  Lighting solve_in_space(const Target& target, SolveReport& report);
  /// Turns the template luminaire (renderers and caches follow).
  void turn_luminaire(float spin_deg);
  /// Spotlights from nothing in the current light space, point lights
  /// beside them where they pay (empty when no spot helps, or when the spots
  /// alone explain less than `points_dbar`, D̄ at the samples of the point
  /// lights they compete with).
  Lighting spots_in_space(const Target& target, double points_dbar, SolveReport& report);
  /// Removes lights with (almost) zero intensity, unless the count is fixed or at its minimum.
  void drop_idle_lights(Lighting& lights) const;
  /// Lights may stand beyond the scene's open sides from now on (its own
  /// light cache); `open_space(false)` goes back.
  void open_space(bool open);
  /// Lights may still be sought beyond the scene's open sides: the space is
  /// closed and the open bounds reach beyond the closed ones.
  bool can_open_space() const;
  /// Opens the space if some of `lights` stand outside the scene's light
  /// bounds but within the open ones (lights from an earlier open solve).
  void open_space_for(const Lighting& lights);
  void ensure_cache(SolveReport& report);
  /// With --luminaire: given lights of its profile as the point lights the
  /// pipeline works with, and its results as luminaires; otherwise as they are.
  Lighting to_points(const Lighting& lights) const;
  Lighting to_output(Lighting lights) const;
  /// The count bounds: --lights N, else the placement's count:MIN:MAX (0: none).
  size_t min_lights() const { return m_judge.min_lights(); }
  size_t max_lights() const { return m_judge.max_lights(); }
  SampleSet sample(const Target& target, SolveReport& report);
  void finish_report(const Target& target, const Lighting& lights, SolveReport& report);
  float neighbourhood_radius() const;
  /// Reports a stage to the progress callback; SolveCancelled if stop was requested.
  void stage(const std::string& name) const;
  /// Runs `plan` (solve_plans.hpp) on `samples` of `target` from `start`,
  /// its moves given exactly what a SolveContext holds.
  Fit run(const Plan& plan, const Target& target, const SampleSet& samples, SolveReport& report, Fit start);

  std::shared_ptr<const Scene> m_scene;
  std::shared_ptr<const RayScene> m_rays;
  Bounds m_closed_bounds, m_open_bounds;  ///< light_bounds() and open_light_bounds(), computed once
  std::optional<LightSpace> m_space;  ///< where lights may stand now (closed or open)
  std::stop_token m_stop;  ///< the running call's (its renderers below check it)
  std::optional<LuminaireRenderer> m_luminaire_renderer, m_luminaire_reference;  ///< with --luminaire
  StoppableRenderer m_stoppable_renderer, m_stoppable_reference;
  Renderer& m_renderer;   ///< = m_stoppable_renderer
  Renderer& m_reference;  ///< = m_stoppable_reference
  Sampler& m_sampler;
  Optimizer& m_optimizer;
  const LightCacheBuilder* m_cache_builder;
  SolveSettings m_settings;
  Judge m_judge;  ///< from m_settings
  ProgressFn m_progress;
  bool m_open = false;  ///< lights are sought in the open space (beyond the scene's open sides)
  std::unique_ptr<LightCache> m_cache, m_other_cache;  ///< the current space's light cache, the other's
  SolveProducts m_products;  ///< the last solve's hierarchy and cuts
};

} // namespace hilight
