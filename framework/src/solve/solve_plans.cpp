// The solve's plans as data: every choice of which moves run, in one place.
#include "hilight/solve/solve_plans.hpp"

#include "hilight/photometry.hpp"
#include "hilight/solve/alternatives.hpp"
#include "hilight/solve/moves.hpp"

namespace hilight {

namespace {

/// After a fit from nothing: the count edited by eq. 9 backward (merges)
/// and forward (splits), then the residual polish. The seconds keep the
/// report's long-standing names.
void append_count_edits(Plan& plan) {
  plan.steps.push_back({merge_pairs_move(), "reference polish"});
  plan.steps.push_back({split_lamps_move(), "reference polish"});
  plan.steps.push_back({residual_polish_move(false), ""});
}

/// A --luminaire whose profile tells its turns apart (an asymmetric one).
bool turns_apart(const SolveSettings& settings) {
  return settings.luminaire && settings.luminaire->profile && distinct_spins(*settings.luminaire->profile).size() > 1;
}

} // namespace

Plan point_plan(const SolveSettings&) {
  Plan plan{"point lights", {}};
  plan.steps.push_back({seed_and_cut_move(), ""});  // times its own parts: seeding, hierarchy, refinement
  plan.steps.push_back({reference_polish_move(false, 3), "reference polish"});
  plan.steps.push_back({add_missing_move(), "reference polish"});
  plan.steps.push_back({add_missing_spot_move(), "spots"});
  append_count_edits(plan);
  return plan;
}

Plan spot_plan(const SolveSettings&, double points_dbar) {
  Plan plan{"spotlights", {}};
  plan.stop_when_empty = true;  // no spot helped: nothing to edit
  plan.steps.push_back({spots_move(points_dbar), "spots"});
  plan.steps.push_back({wide_spots_as_points_move(), "spots"});
  plan.steps.push_back({add_missing_move(), "spots"});
  append_count_edits(plan);
  return plan;
}

Plan fine_tune_plan(const SolveSettings& settings) {
  // Anchored at the reference from the start: lights that already produce
  // the target have a zero objective and stay exactly where they are. One
  // round, and no residual polish: fine-tune follows the painter's strokes.
  Plan plan{"fine-tune", {}};
  plan.steps.push_back({reference_polish_move(true, 1), "refinement"});
  // Settling renders the direct light hundreds of times: seconds with a
  // renderer whose direct light is cheap, and only with the bounce (the
  // frontend says so in settle_fine_tune), never the painter's quick step.
  if (settings.settle_fine_tune) plan.steps.push_back({settle_move(), "refinement"});
  return plan;
}

Plan add_plan(const SolveSettings&) {
  Plan plan{"add", {}};
  plan.steps.push_back({seed_and_cut_move(), ""});
  plan.steps.push_back({reference_polish_move(false, 3), ""});
  return plan;
}

Alternatives answer_alternatives(const SolveSettings& settings) {
  Alternatives alternatives;
  if (turns_apart(settings)) alternatives.push_back(luminaire_turns_alternative(*settings.luminaire));
  // Lights hung under the ceiling have nowhere to go beyond the open sides.
  if (settings.open_space_dbar > 0 && !settings.placement.ceiling_offset) alternatives.push_back(open_space_alternative());
  // Spot hints and a fixed count are the user's choice of lights, and a
  // --luminaire the designer's: no spots instead.
  if (settings.propose_spots && settings.spot_hints.empty() && settings.fixed_count == 0 && !settings.luminaire)
    alternatives.push_back(spot_search_alternative());
  return alternatives;
}

Plan aim_plan(const SolveSettings& settings) {
  Plan plan{"luminaire aim", {}};
  if (turns_apart(settings)) plan.steps.push_back({luminaire_aim_move(), "aim"});
  return plan;
}

} // namespace hilight
