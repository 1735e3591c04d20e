// The inverse of a merge: the point light that owns the worst-explained
// samples split in two (along each axis), polished, kept when the light
// more pays by eq. 9; again, up to 4 times (two close lamps the seeding found as one).
#include "hilight/solve/moves.hpp"

#include "hilight/solve/solve_context.hpp"

#include <algorithm>

namespace hilight {

namespace {

/// Splits tried one after the other, each kept only if it pays.
constexpr int kSplitRounds = 4;
/// The light tried is one that owns at least this share of the squared error.
constexpr double kOwnedShare = 0.25;

/// Point lights of `lights` that eq. 6 calls weak at the samples.
size_t weak_lights(const SolveContext& ctx, ResponseModel& exact, const Lighting& lights) {
  const std::vector<Rgb> phi = exact.responses(lights);
  const double norm = exact.samples().target_norm();
  size_t weak = 0;
  for (size_t j = 0; j < lights.size(); ++j)
    weak += lights[j].type == LightType::Point && ctx.judge.weak(contribution(phi, j, lights[j].intensity, exact.samples()), norm);
  return weak;
}

class SplitLamps final : public Move {
public:
  std::string name() const override { return "split lamps"; }
  std::string premise_fails(const SolveContext& ctx, const Fit& fit) const override;
  Fit run(SolveContext& ctx, const Fit& fit) override;

private:
  Fit split_once(SolveContext& ctx, const Fit& fit) const;
};

std::string SplitLamps::premise_fails(const SolveContext& ctx, const Fit& fit) const {
  const Judge& judge = ctx.judge;
  if (judge.count_fixed()) return "the count is fixed";
  if (!judge.split_lamps(fit.dbar)) return "the fit is good enough (D̄ at most kSplitLampDbar)";
  if (judge.max_lights() != 0 && fit.lights.size() >= judge.max_lights()) return "the count is at its maximum";
  return {};
}

Fit SplitLamps::run(SolveContext& ctx, const Fit& start) {
  Fit fit = start;
  for (int round = 0; round < kSplitRounds; ++round) {  // each split must pay (eq. 9)
    const size_t before = fit.lights.size();
    if (!premise_fails(ctx, fit).empty()) break;
    fit = split_once(ctx, fit);
    if (fit.lights.size() == before) break;
  }
  return fit;
}

Fit SplitLamps::split_once(SolveContext& ctx, const Fit& fit) const {
  const SampleSet& samples = ctx.samples;
  const Lighting& lights = fit.lights;
  const size_t m = samples.size();
  const auto view = ctx.cache_view(samples);
  ResponseModel model(ctx.renderer, samples, view.get()), exact(ctx.renderer, samples, nullptr);
  // Each sample's residual goes to the light that gives it the most light.
  const std::vector<Rgb> phi = model.responses(lights);
  const std::vector<Rgb> l = fit_intensities(phi, lights.size(), samples);
  const std::vector<Rgb> lit = combine(phi, l, m);
  std::vector<double> share(lights.size(), 0.0);
  double total = 0;
  for (size_t i = 0; i < m; ++i) {
    const DVec3 d = DVec3(samples.target[i]) - DVec3(lit[i]);
    const double r = double(samples.weight[i]) * glm::dot(d, d);
    size_t owner = 0;
    float brightest = -1.f;
    for (size_t j = 0; j < lights.size(); ++j) {
      const Rgb c = phi[j * m + i] * l[j];
      if (c.r + c.g + c.b > brightest) brightest = c.r + c.g + c.b, owner = j;
    }
    share[owner] += r, total += r;
  }
  const size_t j = size_t(std::max_element(share.begin(), share.end()) - share.begin());
  if (lights[j].type != LightType::Point || !(share[j] > kOwnedShare * total)) return fit;
  // Two halves a quarter of a seeding cell to either side, along each axis.
  const float offset = 0.25f * ctx.seeding_cell();
  Fit best{{}, fit.dbar};
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 step(0.f);
    step[axis] = offset;
    Lighting trial;
    for (size_t k = 0; k < lights.size(); ++k)
      if (k != j) trial.push_back(lights[k]);
    for (float side : {-1.f, 1.f}) {
      const Vec3 p = lights[j].position + side * step;
      if (!ctx.space.admissible(p)) break;
      trial.push_back(Light::point(p, 0.5f * lights[j].intensity));
    }
    if (trial.size() != lights.size() + 1) continue;
    Fit polished = polish_with_reference(ctx, samples, refine_anchored(ctx, model, exact, trial, RefineEffort::Polish).lights, false);
    if (polished.lights.size() == lights.size() + 1 && polished.dbar < best.dbar) best = std::move(polished);
  }
  // Eq. 9: the light more must pay — by the ratio clause alone, as the
  // split has always been judged (its sweeps were measured so); not ε_w's
  // share of light_more_pays: two halves of one light always share its
  // light, so the share says nothing about a second lamp.
  if (best.lights.empty() || !ctx.judge.ratio_pays(fit.dbar, best.dbar)) return fit;
  // ...and be a lamp (eq. 6): a half the polish turned down to nothing and
  // pressed against a surface fits a few samples' bounce noise, not a second
  // lamp (the home's seed 914: 6·10⁻⁵ of its partner under the ceiling).
  if (weak_lights(ctx, exact, best.lights) > weak_lights(ctx, exact, lights)) return fit;
  return best;
}

} // namespace

std::shared_ptr<Move> split_lamps_move() { return std::make_shared<SplitLamps>(); }

} // namespace hilight
