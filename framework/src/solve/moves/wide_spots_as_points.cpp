// A wide spot tried as a point light. Spots are proposed from cones, so a
// bare lamp comes back as a spot as wide as a cone may be; its cone then
// cuts what a point light lights above its rim, and the spots beside it
// bend to make up for it (measured: D̄ 0.5% on the curved models, their own
// lamp 2 mm off; with the bounce their spot 10 cm low, D̄ 2.9%). As a point
// light the refinement moves it to the bottom of its valley. It is the
// simpler light: the spot stays only if its cone improves D̄ by ε_impro
// (eq. 9), so that where the two fit about as well a rounding difference
// does not decide (the models at ×1000 kept the spot while at ×1 the point
// light won).
#include "hilight/solve/moves.hpp"

#include "hilight/solve/solve_context.hpp"
#include "hilight/solve/spot_refinement.hpp"

#include <algorithm>

namespace hilight {

namespace {

bool wide(const Light& l) { return l.type == LightType::Spot && l.cutoff_deg >= kWideSpotDeg; }

class WideSpotsAsPoints final : public Move {
public:
  std::string name() const override { return "wide spots as points"; }
  std::string premise_fails(const SolveContext&, const Fit& fit) const override {
    return std::any_of(fit.lights.begin(), fit.lights.end(), wide) ? std::string() : "no spot is wide";
  }
  Fit run(SolveContext& ctx, const Fit& fit) override {
    return wide_spots_as_points(ctx.judge, fit, [&](const Lighting& trial) {
      return polish_with_reference(ctx, ctx.samples, trial, true);
    });
  }
};

} // namespace

Fit wide_spots_as_points(const Judge& judge, Fit fit, const std::function<Fit(const Lighting& trial)>& refit,
                         const std::function<void()>& kept) {
  for (size_t j = 0; j < fit.lights.size(); ++j) {
    const Light& light = fit.lights[j];
    if (!wide(light)) continue;
    Lighting trial = fit.lights;
    trial[j] = Light::point(light.position, light.intensity);
    Fit as_point = refit(trial);
    if (!judge.fewer_will_do(fit.dbar, as_point.dbar)) continue;
    fit = std::move(as_point);
    if (kept) kept();
  }
  return fit;
}

std::shared_ptr<Move> wide_spots_as_points_move() { return std::make_shared<WideSpotsAsPoints>(); }

} // namespace hilight
