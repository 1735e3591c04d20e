#pragma once
/// What a move of the solve (move.hpp) may touch, and nothing more: the
/// samples it fits, the renderers and light cache that give responses, the
/// light space where lights may stand, the optimizer, the judge, the
/// settings, the stop token and the progress line; and what it may write:
/// the report and the products later calls read (the hierarchy and its cuts).
/// The Solver builds one per plan it runs.
#include "hilight/light_cache.hpp"
#include "hilight/light_space.hpp"
#include "hilight/optimizer.hpp"
#include "hilight/solve/fit.hpp"
#include "hilight/solve/hierarchy.hpp"
#include "hilight/solve/judge.hpp"
#include "hilight/solve/responses.hpp"
#include "hilight/solve/solver.hpp"
#include "hilight/target.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

namespace hilight {

struct SolveContext {
  const Scene& scene;
  const Target& target;       ///< what the plan solves for (add: the light the given lights leave)
  const SampleSet& samples;   ///< the samples every Fit's D̄ is measured at
  const LightSpace& space;    ///< where lights may stand (closed or open)
  Renderer& renderer;         ///< the fast twin: φ for the search (stops with `stop`)
  Renderer& reference;        ///< the user's renderer: the last word on every D̄ (stops with `stop`)
  const LightCache* cache;    ///< the current space's light cache (nullptr: every φ from the renderer)
  Optimizer& optimizer;       ///< the refinement plugin
  const Judge& judge;
  const SolveSettings& settings;
  std::stop_token stop;
  const ProgressFn& progress;
  SolveReport& report;        ///< moves fill its cuts, seeds, residual samples and timings
  SolveProducts& products;

  /// Reports a stage to the progress line; SolveCancelled once stop is requested.
  void stage(const std::string& name) const;
  /// The light cache restricted to `on` (nullptr without a cache).
  std::unique_ptr<LightCacheView> cache_view(const SampleSet& on) const;
  /// The edge of a seeding cell (the light space's longest side over 2·coarse cells).
  float seeding_cell() const;
  /// Points D̄ over the target is measured on (all, or evenly spaced: SolveSettings::evaluation_points).
  SampleSet evaluation_set() const;
};

/// Points of `target` D̄ is measured on: every point up to `evaluation_points`
/// (0: always every point), else that many evenly spaced, unless the
/// target's light is concentrated where the spacing does not look.
SampleSet evaluation_set(const Target& target, size_t evaluation_points);

// The two refinements every move builds on (refine/anchored.cpp).

/// `start` refined by the optimizer over `model` (the fast twin, the light
/// cache), anchored at `exact` where a cache is in use, then re-anchored at
/// the result and polished; Gauss–Newton steps; weak lights (eq. 6)
/// dropped and the rest polished again (not with --lights N). Never worse
/// than `start` by the anchored objective.
Fit refine_anchored(const SolveContext& ctx, ResponseModel& model, ResponseModel& exact, const Lighting& start,
                    RefineEffort effort = RefineEffort::Full);
/// The reference's last word on `lights` at `samples`: anchored at the
/// reference, intensities re-fitted (lights the fit switches off dropped
/// unless `keep_count` or --lights N), then Gauss–Newton `rounds`, each
/// re-anchored. The Fit's D̄ is the reference's.
Fit polish_with_reference(const SolveContext& ctx, const SampleSet& samples, const Lighting& lights, bool keep_count,
                          int rounds = 3);

} // namespace hilight
