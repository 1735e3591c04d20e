// Eq. 9 upward on the fit: one light more at the residual candidate that
// explains most of what the fit leaves, refined and polished, kept while the
// judge says it pays (or while below the count asked for).
#include "hilight/solve/moves.hpp"

#include "hilight/solve/seeder.hpp"
#include "hilight/solve/solve_context.hpp"

#include <limits>
#include <optional>

namespace hilight {

namespace {

class AddMissing final : public Move {
public:
  std::string name() const override { return "add missing lights"; }
  std::string premise_fails(const SolveContext& ctx, const Fit& fit) const override;
  Fit run(SolveContext& ctx, const Fit& fit) override;
};

std::string AddMissing::premise_fails(const SolveContext& ctx, const Fit& fit) const {
  const Judge& judge = ctx.judge;
  const size_t n = fit.lights.size();
  if (fit.lights.empty()) return "no lights";
  if (judge.count_fixed() && n >= judge.min_lights()) return "the count is fixed and reached";
  if (judge.max_lights() != 0 && n >= judge.max_lights()) return "the count is at its maximum";
  if (!judge.light_more_visible(fit.dbar) && n >= judge.min_lights()) return "D̄ is below what a light more could show";
  return {};
}

Fit AddMissing::run(SolveContext& ctx, const Fit& start) {
  const Judge& judge = ctx.judge;
  const SampleSet& samples = ctx.samples;
  const size_t least = judge.min_lights(), most = judge.max_lights();
  const size_t m = samples.size();
  const auto view = ctx.cache_view(samples);
  ResponseModel model(ctx.renderer, samples, view.get()), exact(ctx.renderer, samples, nullptr);
  const float cell = ctx.seeding_cell();
  // `base` plus the residual candidate that explains most of what `base`
  // leaves unexplained (by NNLS with the rest), refined and polished.
  // `quick`: the light is only placed and fitted (below the count asked for,
  // lights are added regardless; one polish follows).
  auto with_best_candidate = [&](const Lighting& base, bool quick) -> std::optional<Fit> {
    std::vector<Rgb> phi = model.responses(base);
    const std::vector<Rgb> l0 = fit_intensities(phi, base.size(), samples);
    const Lighting candidates = residual_candidates(combine(phi, l0, m), samples, ctx.space, cell, 8);
    if (candidates.empty()) return std::nullopt;
    const std::vector<Rgb> candidate_phi = model.responses(candidates);
    size_t best = 0;
    double best_dbar = std::numeric_limits<double>::max();
    for (size_t c = 0; c < candidates.size(); ++c) {
      std::vector<Rgb> with = phi;
      with.insert(with.end(), candidate_phi.begin() + std::ptrdiff_t(c * m), candidate_phi.begin() + std::ptrdiff_t((c + 1) * m));
      const std::vector<Rgb> l = fit_intensities(with, base.size() + 1, samples);
      const double d = normalized_difference(combine(with, l, m), samples);
      if (d < best_dbar) best_dbar = d, best = c;
    }
    Lighting more = base;
    more.push_back(candidates[best]);
    if (quick) {
      const std::vector<Rgb> l = fit_intensities(model.responses(more), more.size(), samples);
      for (size_t j = 0; j < more.size(); ++j) more[j].intensity = l[j];
      return Fit{std::move(more), best_dbar};
    }
    return polish_with_reference(ctx, samples, refine_anchored(ctx, model, exact, more).lights, false);
  };
  Fit fit = start;
  for (int round = 0; round < 8 + int(least) && (judge.light_more_visible(fit.dbar) || fit.lights.size() < least) &&
                      (most == 0 || fit.lights.size() < most);
       ++round) {
    // One light more, kept by eq. 9 (either clause: with several lamps
    // missing each explains only its share). Below the count asked for it
    // is kept anyway.
    const bool forced = fit.lights.size() < least;
    auto more = with_best_candidate(fit.lights, forced && fit.lights.size() + 1 < least);
    const bool pays = more && more->lights.size() > fit.lights.size() &&
                      (fit.lights.size() < least || judge.light_more_pays(fit.dbar, more->dbar));
    if (!pays) return fit;
    fit = std::move(*more);
  }
  return fit;
}

} // namespace

std::shared_ptr<Move> add_missing_move() { return std::make_shared<AddMissing>(); }

} // namespace hilight
