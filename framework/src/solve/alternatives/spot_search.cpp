// The spot search: point lights cannot explain the target, inside or beyond
// (a stage of spots: D̄ 23–36%). Spotlights from nothing (the spot plan:
// spot_proposals.hpp, then point lights beside them where they pay) compete
// with the point lights; the fewer lights win unless the others improve D̄
// by ε_impro (the judge's spots_win, eq. 9). Its skip is logged: on a
// lamp-lit room "the point lights fit" says why no spot was looked for.
#include "hilight/solve/alternatives.hpp"

namespace hilight {

namespace {

class SpotSearch final : public Alternative {
public:
  std::string name() const override { return "spot search"; }
  std::string premise_fails(const AlternativeContext& ctx, const Answer& current) const override {
    return ctx.judge().look_for_spots(current.report.dbar) ? "" : "the point lights fit (D̄ at most kSpotDbar)";
  }
  Lighting propose(AlternativeContext& ctx, const Answer& current, size_t, SolveReport& report) override {
    ctx.stage("looking for spotlights");
    Lighting spots = ctx.solve_spots(current.report.dbar_samples, report);
    if (spots.empty()) report.dbar = current.report.dbar;  // nothing proposed: D̄ as it was
    return spots;
  }
  bool wins(const Judge& judge, const Answer& candidate, const Answer& current) const override {
    return judge.spots_win(candidate.lights.size(), candidate.report.dbar, current.lights.size(), current.report.dbar);
  }
};

} // namespace

std::shared_ptr<Alternative> spot_search_alternative() { return std::make_shared<SpotSearch>(); }

} // namespace hilight
