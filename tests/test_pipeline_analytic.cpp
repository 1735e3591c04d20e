// The pipeline's stages on their own: the solve, fine-tune and add driven by
// an analytic test double (tests/analytic_renderer.hpp: direct light in
// closed form, nothing occludes) instead of a ray-traced renderer, so a
// failure here is the pipeline's (seeding, hierarchy, cuts, refinement,
// polish), not a renderer's. Random lights, seeded.
#include "analytic_renderer.hpp"
#include "hilight/light_space.hpp"
#include "hilight/solve/hierarchy.hpp"
#include "hilight/solve/responses.hpp"
#include "hilight/solve/seeder.hpp"
#include "hilight/solve/solver.hpp"
#include "hilight/target.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cstdio>
#include <random>

using namespace hilight;

namespace {

/// A 10 x 10 floor with two walls meeting behind it: an open corner.
struct Corner {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const RayScene> rays;
  test::AnalyticRenderer renderer;

  Corner() {
    scene = test::open_corner();
    rays = std::make_shared<const RayScene>(*scene);
    renderer.set_scene(scene);
  }

  Lighting random_lights(std::mt19937_64& rng, size_t count) const {
    std::uniform_real_distribution<float> x(1.5f, 8.5f), y(1.f, 4.f), intensity(2.f, 6.f);
    Lighting lights;
    while (lights.size() < count) {
      const Vec3 p(x(rng), y(rng), x(rng));
      bool apart = true;
      for (const auto& l : lights) apart &= glm::length(l.position - p) > 2.f;
      if (apart) lights.push_back(Light::point(p, Rgb(intensity(rng), intensity(rng), intensity(rng))));
    }
    return lights;
  }

  /// Every vertex a sample, for stages tested on their own.
  SampleSet samples(const Lighting& lights) { return all_samples(target(lights)); }

  Target target(const Lighting& lights) {
    const std::vector<Rgb> values = renderer.illuminate(SurfacePoints::from_vertices(*scene), lights);
    return bind_target("analytic", scene->positions, values, std::vector<float>(values.size(), 1.f), *scene, *rays, scene->normals);
  }

  std::unique_ptr<Solver> solver() {
    static auto sampler = test::registry().create_sampler(PluginDefaults::sampler, {});
    static auto optimizer = test::registry().create_optimizer(PluginDefaults::optimizer, {});
    SolveSettings s;
    s.evaluation_points = 0;
    return std::make_unique<Solver>(scene, rays, renderer, renderer, *sampler, *optimizer, nullptr, s);
  }
};

float nearest(const Lighting& lights, const Vec3& p) {
  float best = 1e30f;
  for (const auto& l : lights) best = std::min(best, glm::length(l.position - p));
  return best;
}

} // namespace

TEST_CASE("pipeline alone (analytic test double): the solve finds random lights in an open corner", "[pipeline][analytic]") {
  Corner corner;
  std::mt19937_64 rng(1201);
  for (size_t trial = 0; trial < 3; ++trial) {
    const Lighting truth = corner.random_lights(rng, 1 + trial);
    INFO("trial " << trial << ", " << truth.size() << " lights");
    SolveReport report;
    const Lighting found = corner.solver()->solve(corner.target(truth), report);
    CHECK(found.size() == truth.size());
    CHECK(report.dbar < 1e-3);
    for (const auto& t : truth) CHECK(nearest(found, t.position) < 1e-3f * corner.scene->diagonal());
  }
}

TEST_CASE("pipeline alone (analytic test double): the true lights are a fixed point of fine-tune", "[pipeline][analytic][fixed-point]") {
  Corner corner;
  std::mt19937_64 rng(1202);
  const Lighting truth = corner.random_lights(rng, 3);
  SolveReport report;
  const Lighting tuned = corner.solver()->fine_tune(corner.target(truth), truth, report);
  CHECK(report.dbar < 1e-6);
  REQUIRE(tuned.size() == truth.size());
  for (size_t j = 0; j < truth.size(); ++j) {
    CHECK(glm::length(tuned[j].position - truth[j].position) < 1e-5f * corner.scene->diagonal());
    for (int c = 0; c < 3; ++c) CHECK(tuned[j].intensity[c] == Approx(truth[j].intensity[c]).epsilon(1e-4));
  }
}

TEST_CASE("pipeline alone (analytic test double): add finds the light the designer's set misses", "[pipeline][analytic]") {
  Corner corner;
  std::mt19937_64 rng(1203);
  const Lighting truth = corner.random_lights(rng, 2);
  SolveReport report;
  const Lighting added = corner.solver()->add_lights(corner.target(truth), {truth[0]}, report);
  REQUIRE(added.size() == 2);
  CHECK(glm::length(added[0].position - truth[0].position) < 1e-3f * corner.scene->diagonal());  // kept first
  CHECK(nearest(added, truth[1].position) < 1e-3f * corner.scene->diagonal());
  CHECK(report.dbar < 1e-3);
}

TEST_CASE("pipeline alone (analytic test double): the seeding keeps a light near each true one, eq. 6 deletes the rest",
          "[pipeline][analytic][seeding]") {
  Corner corner;
  std::mt19937_64 rng(1204);
  const Lighting truth = corner.random_lights(rng, 3);
  const SampleSet samples = corner.samples(truth);
  ResponseModel model(corner.renderer, samples, nullptr);
  const LightSpace space(*corner.rays);
  const SeedResult seeds = seed_lights(model, space, {}, SeedSettings{});
  CAPTURE(seeds.lights.size(), seeds.lights_tried, seeds.dbar);
  std::printf("analytic seeding: %zu of %zu unit lights kept, D-bar %.4f\n", seeds.lights.size(), seeds.lights_tried, seeds.dbar);
  CHECK(seeds.lights.size() >= truth.size());
  CHECK(seeds.lights.size() < seeds.lights_tried / 4);  // weak lights deleted (eq. 6)
  // The seeding's cells are 10/6 wide at the first level, half that at the second.
  for (const auto& t : truth) CHECK(nearest(seeds.lights, t.position) < 1.2f);
  CHECK(seeds.dbar < 0.1);
}

TEST_CASE("pipeline alone (analytic test double): the hierarchy's cut of the true count sits on the true lights",
          "[pipeline][analytic][hierarchy]") {
  Corner corner;
  std::mt19937_64 rng(1205);
  const Lighting truth = corner.random_lights(rng, 2);
  const SampleSet samples = corner.samples(truth);
  ResponseModel model(corner.renderer, samples, nullptr);
  // Leaves: each true light split into three nearby copies of a third of it.
  Lighting leaves;
  for (const auto& t : truth)
    for (const Vec3 offset : {Vec3(0.1f, 0.f, 0.f), Vec3(-0.1f, 0.05f, 0.f), Vec3(0.f, -0.05f, 0.1f)})
      leaves.push_back(Light::point(t.position + offset, t.intensity / 3.f));
  const std::vector<Rgb> phi = model.responses(leaves);
  const LightHierarchy h = LightHierarchy::build(model, leaves, phi, {}, {});
  const auto cut = h.cut(2);
  REQUIRE(cut.size() == 2);
  Lighting merged;
  for (int node : cut) merged.push_back(Light::point(h.nodes()[size_t(node)].position, h.nodes()[size_t(node)].intensity));
  for (const auto& t : truth) CHECK(nearest(merged, t.position) < 0.15f);
  // l_new = l_a + l_b: each merged light carries its three thirds.
  for (const auto& m : merged) {
    const bool first = glm::length(m.intensity - truth[0].intensity) < 1e-4f * glm::length(truth[0].intensity);
    const bool second = glm::length(m.intensity - truth[1].intensity) < 1e-4f * glm::length(truth[1].intensity);
    CHECK((first || second));
  }
}

TEST_CASE("pipeline alone (analytic test double): a stop token stops a solve at its next stage or renderer batch",
          "[pipeline][analytic][cancel]") {
  Corner corner;
  std::mt19937_64 rng(1206);
  const Target target = corner.target(corner.random_lights(rng, 2));
  {
    std::stop_source stop;
    stop.request_stop();
    SolveReport report;
    CHECK_THROWS_AS(corner.solver()->solve(target, report, stop.get_token()), SolveCancelled);
  }
  // Requested mid-solve (here from the seeding's stage report): no result, then a new call runs.
  static auto sampler = test::registry().create_sampler(PluginDefaults::sampler, {});
  static auto optimizer = test::registry().create_optimizer(PluginDefaults::optimizer, {});
  std::stop_source stop;
  SolveSettings s;
  Solver solver(corner.scene, corner.rays, corner.renderer, corner.renderer, *sampler, *optimizer, nullptr, s, [&](const std::string& stage) {
    if (stage == "seeding") stop.request_stop();
  });
  SolveReport report;
  CHECK_THROWS_AS(solver.solve(target, report, stop.get_token()), SolveCancelled);
  SolveReport again;
  CHECK(solver.solve(target, again).size() == 2);
}
