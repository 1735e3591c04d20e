// Eq. 9 upward with a spotlight: what the point lights leave unexplained
// (Ψ − I(L), clipped at 0, as "adding lights" edits it) screened for spots
// from nothing, the spots joined to the lights and polished by the
// reference, kept when the lights more pay. A downlight's pool among point
// lamps: no point light makes it (its light would spill onto walls that are
// dark), and the spot search over the whole target competes spots against
// all the point lights at once, so it lost to the lamps it could not make.
#include "hilight/solve/moves.hpp"

#include "hilight/solve/solve_context.hpp"
#include "hilight/solve/spot_proposals.hpp"

#include <algorithm>
#include <functional>

namespace hilight {

namespace {

/// Share of what the lamps leave that must lie on the twentieth of the
/// samples it is largest at: a pool. Measured: a downlight's pool among the
/// home's lamps 99.2–99.9%; ism-vulkan's bounce against Embree's target
/// (the model, not a lamp) 82%.
constexpr double kPoolShare = 0.95;

/// Nearly all of the residual's energy on a twentieth of the samples: one
/// lamp's pool, not a model's error spread over the scene.
bool pooled(const SampleSet& missing) {
  std::vector<double> energy(missing.size());
  double total = 0;
  for (size_t i = 0; i < energy.size(); ++i) {
    const Rgb& r = missing.target[i];
    energy[i] = double(missing.weight[i]) * (double(r.r) * r.r + double(r.g) * r.g + double(r.b) * r.b);
    total += energy[i];
  }
  const size_t top = std::max<size_t>(1, energy.size() / 20);
  std::partial_sort(energy.begin(), energy.begin() + std::ptrdiff_t(top), energy.end(), std::greater<double>());
  double held = 0;
  for (size_t i = 0; i < top; ++i) held += energy[i];
  return total > 0 && held >= kPoolShare * total;
}

class AddMissingSpot final : public Move {
public:
  std::string name() const override { return "add a missing spot"; }
  std::string premise_fails(const SolveContext& ctx, const Fit& fit) const override;
  Fit run(SolveContext& ctx, const Fit& fit) override;
};

std::string AddMissingSpot::premise_fails(const SolveContext& ctx, const Fit& fit) const {
  const Judge& judge = ctx.judge;
  const SolveSettings& s = ctx.settings;
  if (fit.lights.empty()) return "no lights";
  if (!s.propose_spots || !s.spot_hints.empty() || s.luminaire) return "spots are not proposed here (hints, a luminaire, or off)";
  if (judge.count_fixed()) return "the count is fixed";
  if (judge.max_lights() != 0 && fit.lights.size() >= judge.max_lights()) return "the count is at its maximum";
  // A fit this poor is missing a lamp (Judge::kSplitLampDbar); below it a
  // spot would fit the bounce's remaining error.
  if (!judge.split_lamps(fit.dbar)) return "the fit is good enough (D̄ at most kSplitLampDbar)";
  if (!judge.one_lamp_missing(fit.dbar)) return "the lights miss more than a lamp's pool (D̄ above kMissingLampDbar)";
  return {};
}

Fit AddMissingSpot::run(SolveContext& ctx, const Fit& fit) {
  const SampleSet& samples = ctx.samples;
  ctx.stage("looking for a spot the point lights miss");
  const std::vector<Rgb> lit = ctx.reference.illuminate(samples.points, fit.lights);
  SampleSet missing = samples;
  for (size_t i = 0; i < missing.size(); ++i) missing.target[i] = glm::max(samples.target[i] - lit[i], Rgb(0.f));
  // Nothing a light more could show is left (a downlight's pool may hold
  // less than ε_w of ‖Ψ‖ and still be a lamp: eq. 9 decides below).
  if (!ctx.judge.light_more_visible(missing.target_norm() / samples.target_norm())) return fit;
  if (!pooled(missing)) return fit;
  const Fit spots = propose_spots(missing, ctx.space, ctx.renderer, ctx.reference, {ctx.judge});
  Lighting added;
  for (const Light& l : spots.lights)
    if (l.type == LightType::Spot) added.push_back(l);
  if (added.empty()) return fit;
  Lighting joined = fit.lights;
  joined.insert(joined.end(), added.begin(), added.end());
  // Settled as the spot search settles its answer (the cones' geometry with
  // the bounce re-taken where they went), then the reference's last word.
  const auto settle = [&](const Lighting& lights) {
    return polish_with_reference(ctx, samples, settle_lights(samples, ctx.space, ctx.renderer, ctx.reference, lights).lights, false);
  };
  Fit after = settle(joined);
  bool pruned = false;
  // Eq. 9 backward on the spots added: one that one light fewer will do
  // without (a narrow beam fitting the residual's noise) goes.
  for (size_t j = after.lights.size(); j-- > fit.lights.size();) {
    if (after.lights[j].type != LightType::Spot) continue;
    Lighting without = after.lights;
    without.erase(without.begin() + std::ptrdiff_t(j));
    Fit fewer = polish_with_reference(ctx, samples, without, false);
    if (ctx.judge.count_allowed(fewer.lights.size()) && ctx.judge.fewer_will_do(after.dbar, fewer.dbar)) {
      after = std::move(fewer);
      pruned = true;
    }
  }
  // The spots kept were settled beside the ones that went: settle them again alone.
  if (pruned && after.lights.size() > fit.lights.size()) {
    Fit again = settle(after.lights);
    if (again.dbar < after.dbar && again.lights.size() == after.lights.size()) after = std::move(again);
  }
  // Each light more must pay (eq. 9): together by ε_impro, or by ε_w each.
  // A spot that took a point light's place (the polish switched it off) needs only a lower D̄.
  const size_t n = after.lights.size(), before = fit.lights.size();
  const bool pays = ctx.judge.count_allowed(n) &&
                    (n <= before ? after.dbar < fit.dbar
                                 : ctx.judge.ratio_pays(fit.dbar, after.dbar) || fit.dbar - after.dbar >= double(n - before) * ctx.judge.eps_w());
  return pays ? after : fit;
}

} // namespace

std::shared_ptr<Move> add_missing_spot_move() { return std::make_shared<AddMissingSpot>(); }

} // namespace hilight
