#pragma once
/// The solve's whole-answer alternatives (alternative.hpp), one strategy
/// each, in framework/src/solve/alternatives/. answer_alternatives
/// (solve_plans.hpp) puts them in order.
#include "hilight/solve/alternative.hpp"

namespace hilight {

/// luminaire_turns.cpp: with a --luminaire whose profile tells turns apart,
/// the whole point solve again with the template turned to each other spin
/// (from `luminaire`'s spin now), when the answer fits worse than kTurnDbar;
/// the lowest D̄ keeps its turn.
std::shared_ptr<Alternative> luminaire_turns_alternative(const Light& luminaire);
/// open_space.cpp: lights inside cannot explain the target (D̄ above
/// SolveSettings::open_space_dbar): perhaps it is lit from outside (a
/// product, a facade); the point solve again beyond the scene's open sides,
/// kept when the judge's open_space_wins.
std::shared_ptr<Alternative> open_space_alternative();
/// spot_search.cpp: point lights cannot explain the target, inside or
/// beyond (D̄ above kSpotDbar): spotlights from nothing, point lights beside
/// them where they pay, kept when the judge's spots_win (eq. 9: the fewer
/// lights win unless the others improve D̄ by ε_impro).
std::shared_ptr<Alternative> spot_search_alternative();

} // namespace hilight
