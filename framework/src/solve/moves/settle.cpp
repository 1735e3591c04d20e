// Fine-tune's settling (spot_proposals.hpp, settle_lights): with the bounce
// the polish's slopes run through the gathers and stall centimetres off;
// the settling holds the bounce, adds a simplex and leaves the bounce's
// spikes out. Kept where the reference says the lights fit better.
#include "hilight/solve/moves.hpp"

#include "hilight/solve/solve_context.hpp"
#include "hilight/solve/spot_proposals.hpp"

namespace hilight {

namespace {

class Settle final : public Move {
public:
  std::string name() const override { return "settle"; }
  std::string premise_fails(const SolveContext& ctx, const Fit& fit) const override {
    if (fit.lights.empty()) return "no lights";
    if (ctx.judge.settled(fit.dbar)) return "settled already (D̄ at most kSettledDbar)";
    return {};
  }
  Fit run(SolveContext& ctx, const Fit& fit) override {
    const Fit settled = settle_lights(ctx.samples, ctx.space, ctx.renderer, ctx.reference, fit.lights);
    Fit polished = polish_with_reference(ctx, ctx.samples, settled.lights, true, 0);  // the reference's D̄, intensities fitted
    return polished.dbar < fit.dbar ? polished : fit;
  }
};

} // namespace

std::shared_ptr<Move> settle_move() { return std::make_shared<Settle>(); }

} // namespace hilight
