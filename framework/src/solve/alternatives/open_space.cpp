// The open space: lights inside cannot explain the target, so perhaps it is
// lit from outside (a product, a facade). The point solve again with lights
// allowed beyond the scene's open sides (open_light_bounds(), a light cache
// of its own); the better answer is kept, a near tie stays inside (the
// judge's open_space_wins: a larger box coarsens the seeding and the cache).
#include "hilight/solve/alternatives.hpp"

namespace hilight {

namespace {

class OpenSpace final : public Alternative {
public:
  std::string name() const override { return "open space"; }
  std::string premise_fails(const AlternativeContext& ctx, const Answer& current) const override {
    if (!(current.report.dbar > ctx.settings().open_space_dbar)) return "the lights inside fit (D̄ at most open_space_dbar)";
    if (!ctx.can_open_space()) return "the space is open already, or the scene has no open side";
    return {};
  }
  Lighting propose(AlternativeContext& ctx, const Answer&, size_t, SolveReport& report) override {
    ctx.stage("looking beyond the scene's bounds");
    ctx.open_space(true);
    return ctx.solve_points(report);
  }
  bool wins(const Judge& judge, const Answer& candidate, const Answer& current) const override {
    return judge.open_space_wins(candidate.report.dbar, current.report.dbar);
  }
  void kept(AlternativeContext&, Answer& candidate, const Answer& replaced) override {
    candidate.report.dbar_closed = replaced.report.dbar;
    candidate.report.open_space = true;
  }
  void rejected(AlternativeContext& ctx, Answer& current) override {
    current.report.dbar_closed = current.report.dbar;
    ctx.open_space(false);
  }
};

} // namespace

std::shared_ptr<Alternative> open_space_alternative() { return std::make_shared<OpenSpace>(); }

} // namespace hilight
