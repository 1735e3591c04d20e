#pragma once
/// The solve as a plan of moves over a fit (issue 33). A Move is one
/// strategy ("try X, keep it if the judge says it pays"): it says whether
/// its premise holds on a fit, and runs on it, touching only what the
/// SolveContext gives it. A Plan is data: the moves in order, each with the
/// report.seconds key its time goes to. run_plan logs every move in
/// SolveReport::stages, skipped ones with the premise that failed.
#include "hilight/solve/fit.hpp"

#include <memory>
#include <string>
#include <vector>

namespace hilight {

struct SolveContext;

class Move {
public:
  virtual ~Move() = default;
  virtual std::string name() const = 0;
  /// Why the move need not run on `fit` (empty: its premise holds).
  virtual std::string premise_fails(const SolveContext& ctx, const Fit& fit) const = 0;
  /// The move on `fit`: a better fit, or `fit` itself when its proposal does not pay.
  virtual Fit run(SolveContext& ctx, const Fit& fit) = 0;
};

struct PlanStep {
  std::shared_ptr<Move> move;
  std::string seconds_key;  ///< report.seconds entry its time adds to (empty: the move times itself)
};

struct Plan {
  std::string name;
  std::vector<PlanStep> steps;
  /// Stop after the first move that leaves no lights (a spot search that found none).
  bool stop_when_empty = false;
};

/// Runs `plan` from `fit`: each move whose premise holds, timed and logged;
/// report.dbar_samples follows the fit.
Fit run_plan(const Plan& plan, SolveContext& ctx, Fit fit);

} // namespace hilight
