#pragma once
/// The solve's plans, as data (move.hpp): which moves run in which order,
/// and which whole-answer alternatives (alternative.hpp) compete after the
/// point lights, decided from the settings in one place (solve_plans.cpp).
#include "hilight/solve/alternative.hpp"
#include "hilight/solve/move.hpp"
#include "hilight/solve/solver.hpp"

namespace hilight {

/// Point lights from nothing: seeding and cuts, the reference polish, eq. 9
/// upward, merges, splits, the residual polish.
Plan point_plan(const SolveSettings& settings);
/// Spotlights from nothing, competing with point lights that reached
/// `points_dbar` at the samples: the spot search, then as point_plan after its fit.
Plan spot_plan(const SolveSettings& settings, double points_dbar);
/// Fine-tune: one reference round (the count kept); then the settling where
/// the settings ask for it (SolveSettings::settle_fine_tune: the bounce on
/// and a renderer whose direct light is cheap).
Plan fine_tune_plan(const SolveSettings& settings);
/// Add: the missing light from nothing (seeding and cuts) and the reference polish.
Plan add_plan(const SolveSettings& settings);
/// The whole-answer alternatives of a solve, in order, after its point
/// lights: the luminaire's turns (a --luminaire whose profile tells turns
/// apart), the open space (open_space_dbar > 0, no --place ceiling), the
/// spot search (propose_spots, no spot hints, no --lights N, no
/// --luminaire). Each still checks its premise on the answer so far.
Alternatives answer_alternatives(const SolveSettings& settings);
/// After the solve, with a luminaire whose profile tells turns apart
/// (distinct_spins): each luminaire's own turn. Empty otherwise.
Plan aim_plan(const SolveSettings& settings);

} // namespace hilight
