// Spotlights from nothing (spot_proposals.hpp), polished by the reference.
// Spots that explain less than the point lights did are not what the target
// lacks (a painted patch no light makes): the reference polish and the
// point lights beside them would cost 5x the proposal to lose.
#include "hilight/solve/moves.hpp"

#include "hilight/solve/solve_context.hpp"
#include "hilight/solve/spot_proposals.hpp"

namespace hilight {

namespace {

class Spots final : public Move {
public:
  explicit Spots(double give_up_dbar) : m_give_up_dbar(give_up_dbar) {}
  std::string name() const override { return "spots"; }
  std::string premise_fails(const SolveContext&, const Fit&) const override { return {}; }
  Fit run(SolveContext& ctx, const Fit&) override {
    ctx.stage("screening spotlights");
    const Fit spots = propose_spots(ctx.samples, ctx.space, ctx.renderer, ctx.reference, {ctx.judge});
    if (spots.lights.empty() || spots.dbar >= m_give_up_dbar) return {};
    return polish_with_reference(ctx, ctx.samples, spots.lights, false);
  }

private:
  double m_give_up_dbar;
};

} // namespace

std::shared_ptr<Move> spots_move(double give_up_dbar) { return std::make_shared<Spots>(give_up_dbar); }

} // namespace hilight
