// The fit from nothing: seeding (eq. 6), the light hierarchy (eq. 7–8),
// cuts refined as the count walk (eq. 9) needs them.
#include "hilight/solve/moves.hpp"

#include "hilight/error.hpp"
#include "hilight/solve/cuts.hpp"
#include "hilight/solve/seeder.hpp"
#include "hilight/solve/solve_context.hpp"
#include "../solver_internal.hpp"

#include <tbb/task_group.h>

namespace hilight {

using solver_detail::Stopwatch;

namespace {

/// Lights of cut `k` (positions and summed intensities) followed by the spots.
Lighting lights_of_cut(const LightHierarchy& h, size_t k, const Lighting& spots, std::vector<Rgb>& phi) {
  Lighting lights;
  phi.clear();
  for (int node : h.cut(k)) {
    const Cluster& c = h.nodes()[node];
    lights.push_back(Light::point(c.position, c.intensity));
    phi.insert(phi.end(), c.phi.begin(), c.phi.end());
  }
  lights.insert(lights.end(), spots.begin(), spots.end());
  return lights;
}

class SeedAndCut final : public Move {
public:
  std::string name() const override { return "seeding and cuts"; }
  std::string premise_fails(const SolveContext&, const Fit&) const override { return {}; }
  Fit run(SolveContext& ctx, const Fit&) override;
};

Fit SeedAndCut::run(SolveContext& ctx, const Fit&) {
  const SampleSet& samples = ctx.samples;
  SolveReport& report = ctx.report;
  const LightSpace& space = ctx.space;
  const size_t m = samples.size();
  ctx.products.cuts.clear();
  ctx.products.hierarchy.reset();
  const auto view = ctx.cache_view(samples);
  ResponseModel model(ctx.renderer, samples, view.get());

  ctx.stage("seeding");
  Stopwatch seed_watch;
  SeedResult seed = seed_lights(model, space, ctx.settings.spot_hints, ctx.settings.seeding);
  report.seconds["seeding"] += seed_watch.seconds();
  const size_t n_points = seed.lights.size() - seed.spot_count;
  report.seed_lights = n_points;
  report.seeds_tried = seed.lights_tried;
  if (n_points == 0 && seed.spot_count == 0)
    throw InputError(space.rules().any() ? "--place " + space.rules().describe() +
                                               ": no light allowed there brightens the target (the rules exclude the lit region, or no place satisfies them)"
                                         : std::string("the seeding found no light that brightens the target"));
  if (n_points == 0) {  // only the requested spotlights: no hierarchy, refine them alone
    Stopwatch refine_watch;
    ResponseModel exact(ctx.renderer, samples, nullptr);
    Fit spots_only = refine_anchored(ctx, model, exact, seed.lights);
    report.dbar_samples = spots_only.dbar;
    report.seconds["refinement"] += refine_watch.seconds();
    return spots_only;
  }

  ctx.stage("building the light hierarchy");
  Stopwatch hierarchy_watch;
  Lighting leaves(seed.lights.begin(), seed.lights.begin() + std::ptrdiff_t(n_points));
  std::vector<Rgb> leaf_phi(seed.phi.begin(), seed.phi.begin() + std::ptrdiff_t(n_points * m));
  std::vector<Rgb> spot_phi(seed.phi.begin() + std::ptrdiff_t(n_points * m), seed.phi.end());
  Lighting spots(seed.lights.begin() + std::ptrdiff_t(n_points), seed.lights.end());
  std::vector<Rgb> spot_l;
  for (const auto& s : spots) spot_l.push_back(s.intensity);
  // A merged light stands in free space, in the room of one of the two.
  auto may_stand_at = [&space](const Vec3& x, const Vec3& a, const Vec3& b) {
    if (!space.admissible(x)) return false;
    const int room = space.regions().at(x);
    return room == space.regions().at(a) || room == space.regions().at(b);
  };
  ctx.products.hierarchy = LightHierarchy::build(model, leaves, leaf_phi, spot_phi, spot_l, ctx.settings.hierarchy, may_stand_at);
  const LightHierarchy& hierarchy = *ctx.products.hierarchy;
  report.seconds["hierarchy"] += hierarchy_watch.seconds();

  // Every cut's D̄ with intensities re-fitted (a better start than the sums).
  report.cuts.assign(n_points, {});
  std::vector<Lighting> starts(n_points);
  for (size_t k = 1; k <= n_points; ++k) {
    std::vector<Rgb> phi;
    Lighting lights = lights_of_cut(hierarchy, k, spots, phi);
    phi.insert(phi.end(), spot_phi.begin(), spot_phi.end());
    std::vector<Rgb> l = fit_intensities(phi, lights.size(), samples);
    for (size_t j = 0; j < lights.size(); ++j) lights[j].intensity = l[j];
    report.cuts[k - 1].lights = k;
    report.cuts[k - 1].dbar_initial = normalized_difference(combine(phi, l, m), samples);
    starts[k - 1] = std::move(lights);
  }

  // Which cuts to refine and how many lights (cuts.cpp, by the judge's rule).
  // A count the seeding cannot reach (--lights N, count:MIN) takes every
  // seeded light here; the add-missing move adds the rest where the fit is worst.
  const Judge rule = ctx.judge.for_leaves(n_points);
  std::vector<double> initial;
  for (const auto& c : report.cuts) initial.push_back(c.dbar_initial);
  const std::vector<size_t> chosen = choose_cuts(initial, rule);

  Stopwatch refine_watch;
  ResponseModel exact(ctx.renderer, samples, nullptr);
  auto refine_cut = [&](size_t k) {
    if (report.cuts[k - 1].refined) return;
    ctx.stage("refining the cut with " + std::to_string(k) + " lights");
    CutRecord& rec = report.cuts[k - 1];
    Fit refined = refine_anchored(ctx, model, exact, starts[k - 1]);
    rec.refined_lights = std::move(refined.lights);
    rec.dbar_refined = refined.dbar;
    rec.refined = true;
  };
  auto dbar_of = [&](size_t k) { return report.cuts[k - 1].refined ? report.cuts[k - 1].dbar_refined : report.cuts[k - 1].dbar_initial; };
  {
    // The walk always needs a neighbour of the first cut: refine both at
    // once (each refinement has serial stretches; two fill both cores).
    const size_t first = chosen.front();
    const FirstNeighbour neighbour = first_neighbour(initial, chosen, rule);
    tbb::task_group group;
    group.run([&] { refine_cut(first); });
    if (neighbour == FirstNeighbour::Below) group.run([&] { refine_cut(first - 1); });
    if (neighbour == FirstNeighbour::Above) group.run([&] { refine_cut(first + 1); });
    group.wait();
  }
  // Cuts are refined lazily, only as the walk needs them.
  const size_t count = walk_count(initial, chosen, rule, [&](size_t k) {
    refine_cut(k);
    return report.cuts[k - 1].dbar_refined;
  });
  report.seconds["refinement"] += refine_watch.seconds();
  for (size_t k = 1; k < n_points; ++k) {
    double next = dbar_of(k + 1);
    report.improvement.push_back(next > 0 ? dbar_of(k) / next : 0.0);
  }
  report.dbar_samples = report.cuts[count - 1].dbar_refined;
  // Kept for cut_lights(): every cut, refined where the solve refined it.
  for (size_t k = 1; k <= n_points; ++k)
    ctx.products.cuts.push_back(report.cuts[k - 1].refined ? report.cuts[k - 1].refined_lights : starts[k - 1]);
  return {report.cuts[count - 1].refined_lights, report.dbar_samples};
}

} // namespace

std::shared_ptr<Move> seed_and_cut_move() { return std::make_shared<SeedAndCut>(); }

} // namespace hilight
