#pragma once
/// The solve's whole-answer alternatives (issue 33): after the point lights
/// are found, "solve again another way, keep it if the judge says it is
/// better" — the luminaire turned, the space beyond the scene's open sides,
/// spotlights from nothing. A move (move.hpp) edits a fit on fixed samples
/// in one light space; an alternative makes a whole new answer (its own
/// samples, light space, cache and report) and competes with the answer so
/// far. Each is a class in a file of its own under
/// framework/src/solve/alternatives/; which ones run, in which order, is
/// data (answer_alternatives in solve_plans.hpp); run_alternatives runs them
/// and logs each in SolveReport::stages.
#include "hilight/solve/judge.hpp"
#include "hilight/solve/solver.hpp"

#include <memory>
#include <string>
#include <vector>

namespace hilight {

/// A whole answer of the solve: its lights, and the report of the solve that found them.
struct Answer {
  Lighting lights;
  SolveReport report;
};

/// What an alternative may do, and nothing more: ask the judge, read the
/// settings, say its stage, solve again from nothing (points or spots) in
/// the current light space, and change that space or the luminaire's turn.
/// The Solver provides it, bound to the target being solved.
class AlternativeContext {
public:
  virtual ~AlternativeContext() = default;
  virtual const Judge& judge() const = 0;
  virtual const SolveSettings& settings() const = 0;
  /// Reports a stage to the progress line; SolveCancelled once stop is requested.
  virtual void stage(const std::string& name) const = 0;
  /// The point-light plan (point_plan) from nothing in the current light
  /// space, its light cache and samples; `report` gets its D̄ over the target.
  virtual Lighting solve_points(SolveReport& report) = 0;
  /// The spotlight plan (spot_plan) from nothing in the current light space,
  /// against point lights that reached `points_dbar` at their samples; empty
  /// when no spot helps (then `report`'s D̄ is not measured).
  virtual Lighting solve_spots(double points_dbar, SolveReport& report) = 0;
  /// Lights may still be sought beyond the scene's open sides: the space is
  /// closed now and the scene has open sides (open_light_bounds()).
  virtual bool can_open_space() const = 0;
  /// From now on lights stand beyond the open sides (true) or within the
  /// scene's bounds (false); each space keeps its own light cache.
  virtual void open_space(bool open) = 0;
  /// The template luminaire (--luminaire) turned to `spin_deg` about its aim;
  /// the renderers and the light caches follow.
  virtual void turn_luminaire(float spin_deg) = 0;
};

class Alternative {
public:
  virtual ~Alternative() = default;
  /// Its name in the report's stages (a skipped alternative's line).
  virtual std::string name() const = 0;
  /// Why it need not be tried on the answer so far (empty: it is tried).
  /// The reason is a line of the report's stages ("spot search: the point
  /// lights fit"), so a report says of every alternative what became of it.
  virtual std::string premise_fails(const AlternativeContext& ctx, const Answer& current) const = 0;
  /// The stage names of the candidates it tries, in order: one by default
  /// (the luminaire's turns: one per spin its profile tells apart). Each
  /// competes with the best answer so far.
  virtual std::vector<std::string> candidates() const { return {name()}; }
  /// Candidate `i`: its lights; its report is filled in `report`, which
  /// starts with the answer's log (stages, seconds) and where it was sought.
  virtual Lighting propose(AlternativeContext& ctx, const Answer& current, size_t i, SolveReport& report) = 0;
  /// The judge's verdict: `candidate` replaces `current`.
  virtual bool wins(const Judge& judge, const Answer& candidate, const Answer& current) const = 0;
  /// After the verdict, what it means beyond the lights and the report
  /// (the light space and the luminaire's turn follow the answer kept):
  /// `candidate` won over `replaced`...
  virtual void kept(AlternativeContext&, Answer& /*candidate*/, const Answer& /*replaced*/) {}
  /// ...or `current` stays (it has the candidate's log already).
  virtual void rejected(AlternativeContext&, Answer& /*current*/) {}
};

using Alternatives = std::vector<std::shared_ptr<Alternative>>;

/// Runs `alternatives` in order on `answer`: each whose premise holds tries
/// its candidates, each judged against the best answer so far; every try is
/// a line of the stages (D̄ over the target points, kept when it won), and
/// what a losing candidate's solve logged is carried into the answer kept.
Answer run_alternatives(const Alternatives& alternatives, AlternativeContext& ctx, Answer answer);

} // namespace hilight
