// The solve's moves one at a time (solve/moves.hpp) on the analytic test
// double (tests/analytic_renderer.hpp: direct light in closed form, nothing
// occludes), each given a fit it should repair and the exact SolveContext a
// plan gives it; and the plan runner's log, and the plans as data.
#include "analytic_renderer.hpp"
#include "hilight/light_space.hpp"
#include "hilight/solve/moves.hpp"
#include "hilight/solve/solve_context.hpp"
#include "hilight/solve/solve_plans.hpp"
#include "hilight/target.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

namespace {

/// A 10 x 10 floor with two walls meeting behind it, lit by the analytic
/// double; every vertex a sample.
struct World {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const RayScene> rays;
  test::AnalyticRenderer renderer;
  std::optional<LightSpace> space;
  std::optional<Target> target;
  SampleSet samples;
  SolveSettings settings;
  Judge judge;
  SolveReport report;
  SolveProducts products;
  ProgressFn progress;

  explicit World(const Lighting& truth, SolveSettings s = {}) : settings(std::move(s)) {
    scene = test::open_corner();
    rays = std::make_shared<const RayScene>(*scene);
    renderer.set_scene(scene);
    space.emplace(*rays, settings.placement, scene->light_bounds());
    const std::vector<Rgb> values = renderer.illuminate(SurfacePoints::from_vertices(*scene), truth);
    target = bind_target("analytic", scene->positions, values, std::vector<float>(values.size(), 1.f), *scene, *rays, scene->normals);
    samples = all_samples(*target);
    settings.evaluation_points = 0;
    judge = Judge(judge_settings(settings));
  }

  SolveContext context() {
    static auto optimizer = test::registry().create_optimizer(PluginDefaults::optimizer, {});
    return SolveContext{*scene, *target, samples, *space, renderer, renderer, nullptr, *optimizer,
                        judge,  settings, {},     progress, report, products};
  }

  /// `lights` with intensities fitted and their D̄, by the reference polish's fit alone.
  Fit fitted(const Lighting& lights) {
    SolveContext ctx = context();
    return polish_with_reference(ctx, samples, lights, true, 0);
  }
};

float nearest(const Lighting& lights, const Vec3& p) {
  float best = 1e30f;
  for (const auto& l : lights) best = std::min(best, glm::length(l.position - p));
  return best;
}

const Lighting kTwoLamps = {Light::point({3.f, 3.f, 4.f}, Rgb(4.f)), Light::point({7.f, 2.5f, 6.f}, Rgb(3.f, 4.f, 5.f))};

} // namespace

TEST_CASE("moves: add missing puts the second lamp where the fit is worst", "[moves]") {
  World world(kTwoLamps);
  SolveContext ctx = world.context();
  const Fit one = world.fitted({Light::point({3.f, 3.f, 4.f}, Rgb(1.f))});
  REQUIRE(one.dbar > 0.05);
  const auto move = add_missing_move();
  REQUIRE(move->premise_fails(ctx, one).empty());
  const Fit two = move->run(ctx, one);
  REQUIRE(two.lights.size() == 2);
  CHECK(nearest(two.lights, kTwoLamps[1].position) < 1e-3f * world.scene->diagonal());
  CHECK(two.dbar < 1e-3);
  // On the right fit there is nothing left a light more could show.
  CHECK_FALSE(move->premise_fails(ctx, two).empty());
}

TEST_CASE("moves: a lamp found as two close halves is merged back into one", "[moves]") {
  const Lighting truth = {kTwoLamps[0]};
  World world(truth);
  SolveContext ctx = world.context();
  const Fit halves = world.fitted({Light::point({2.8f, 3.f, 4.f}, Rgb(2.f)), Light::point({3.2f, 3.f, 4.f}, Rgb(2.f))});
  const auto move = merge_pairs_move();
  REQUIRE(move->premise_fails(ctx, halves).empty());
  const Fit merged = move->run(ctx, halves);
  REQUIRE(merged.lights.size() == 1);
  CHECK(glm::length(merged.lights[0].position - truth[0].position) < 1e-3f * world.scene->diagonal());
  // --lights N: the count is the designer's, no merge.
  SolveSettings fixed;
  fixed.fixed_count = 2;
  World counted(truth, fixed);
  SolveContext counted_ctx = counted.context();
  CHECK(move->premise_fails(counted_ctx, halves) == "the count is fixed");
}

TEST_CASE("moves: two close lamps found as one are split in two", "[moves]") {
  const Lighting truth = {Light::point({4.2f, 3.f, 5.f}, Rgb(4.f)), Light::point({5.8f, 3.f, 5.f}, Rgb(4.f))};
  World world(truth);
  SolveContext ctx = world.context();
  const Fit one = world.fitted({Light::point({5.f, 3.f, 5.f}, Rgb(8.f))});
  REQUIRE(one.dbar > Judge::kSplitLampDbar);
  const auto move = split_lamps_move();
  REQUIRE(move->premise_fails(ctx, one).empty());
  const Fit two = move->run(ctx, one);
  REQUIRE(two.lights.size() == 2);
  CHECK(nearest(two.lights, truth[0].position) < 1e-3f * world.scene->diagonal());
  CHECK(nearest(two.lights, truth[1].position) < 1e-3f * world.scene->diagonal());
  CHECK(world.judge.ratio_pays(one.dbar, two.dbar));
}

TEST_CASE("moves: a wide spot over a bare lamp becomes a point light", "[moves]") {
  const Lighting truth = {kTwoLamps[0]};
  World world(truth);
  SolveContext ctx = world.context();
  const Light cone = Light::spot({3.f, 3.f, 4.f}, {0.f, -1.f, 0.f}, 80.f, Rgb(4.f), 0.f);
  const Fit spot = world.fitted({cone});
  const auto move = wide_spots_as_points_move();
  REQUIRE(move->premise_fails(ctx, spot).empty());
  const Fit point = move->run(ctx, spot);
  REQUIRE(point.lights.size() == 1);
  CHECK(point.lights[0].type == LightType::Point);
  CHECK(point.dbar <= spot.dbar);
  // A narrow spot is not tried.
  const Fit narrow = world.fitted({Light::spot({3.f, 3.f, 4.f}, {0.f, -1.f, 0.f}, 30.f, Rgb(4.f), 0.f)});
  CHECK(move->premise_fails(ctx, narrow) == "no spot is wide");
}

TEST_CASE("moves: a plan logs every move, and skips a move whose premise fails", "[moves]") {
  World world(kTwoLamps);
  SolveContext ctx = world.context();
  const Fit right = world.fitted(kTwoLamps);
  REQUIRE(right.dbar < 1e-4);
  Plan plan{"edits", {{split_lamps_move(), "reference polish"}, {merge_pairs_move(), "reference polish"}}};
  const Fit after = run_plan(plan, ctx, right);
  CHECK(after.lights.size() == 2);
  REQUIRE(world.report.stages.size() == 2);
  const StageRecord& split = world.report.stages[0];
  CHECK(split.name == "split lamps");
  CHECK_FALSE(split.skipped.empty());  // the fit is good enough: no split tried
  CHECK_FALSE(split.kept);
  const StageRecord& merge = world.report.stages[1];
  CHECK(merge.name == "merge pairs");
  CHECK(merge.skipped.empty());  // it ran (the lamps are far apart: nothing merged)
  CHECK_FALSE(merge.kept);
  CHECK(merge.dbar_after == merge.dbar_before);
  CHECK(world.report.dbar_samples == after.dbar);
}

TEST_CASE("moves: the plans are data, decided from the settings", "[moves]") {
  auto names = [](const Plan& plan) {
    std::vector<std::string> out;
    for (const auto& step : plan.steps) out.push_back(step.move->name());
    return out;
  };
  SolveSettings s;
  CHECK(names(point_plan(s)) == std::vector<std::string>{"seeding and cuts", "reference polish", "add missing lights",
                                                         "add a missing spot", "merge pairs", "split lamps", "residual polish"});
  CHECK(names(spot_plan(s, 0.1)).front() == "spots");
  CHECK(spot_plan(s, 0.1).stop_when_empty);
  CHECK(names(fine_tune_plan(s)) == std::vector<std::string>{"reference polish"});
  s.settle_fine_tune = true;  // the bounce on and a renderer whose direct light is cheap
  CHECK(names(fine_tune_plan(s)) == std::vector<std::string>{"reference polish", "settle"});
  CHECK(names(add_plan(s)) == std::vector<std::string>{"seeding and cuts", "reference polish"});
  CHECK(aim_plan(s).steps.empty());  // no luminaire: nothing to turn
}
