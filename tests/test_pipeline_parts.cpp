// Pieces of the solve pipeline on small constructed cases: the hierarchy's
// cuts, the sampler's importance.
#include "hilight/solve/fit.hpp"
#include "hilight/solve/hierarchy.hpp"
#include "hilight/solve/solver.hpp"
#include "hilight/solve/samples.hpp"
#include "hilight/sampler.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

namespace {

Target vertex_target(const Scene& scene, const std::vector<Rgb>& values) {
  RayScene rays(scene);
  std::vector<float> weights(values.size(), 1.f);
  return bind_target("test", scene.positions, values, weights, scene, rays, scene.normals);
}

} // namespace

TEST_CASE("the hierarchy merges nearby lights first and cuts split the latest merge", "[hierarchy]") {
  auto scene = test::finish(builders::box_room({6.f, 3.f, 5.f}), 0.6f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  // Two tight pairs of lights far apart: the first merges must be within pairs.
  Lighting leaves = {Light::point({1.f, 2.f, 1.f}, Rgb(1.f)), Light::point({1.2f, 2.f, 1.1f}, Rgb(1.f)),
                     Light::point({5.f, 2.f, 4.f}, Rgb(1.f)), Light::point({4.8f, 2.1f, 4.f}, Rgb(1.f))};
  auto target_values = renderer->illuminate(SurfacePoints::from_vertices(*scene), leaves);
  Target target = vertex_target(*scene, target_values);
  SampleSet samples = all_samples(target);
  ResponseModel model(*renderer, samples, nullptr);
  auto phi = model.responses(leaves);
  LightHierarchy h = LightHierarchy::build(model, leaves, phi, {}, {});
  REQUIRE(h.nodes().size() == 7);  // 4 leaves + 3 merges
  auto pair_of = [&](int node) { return std::minmax(h.nodes()[node].left, h.nodes()[node].right); };
  CHECK((pair_of(4) == std::minmax(0, 1) || pair_of(4) == std::minmax(2, 3)));
  CHECK((pair_of(5) == std::minmax(0, 1) || pair_of(5) == std::minmax(2, 3)));
  CHECK(h.cut(1) == std::vector<int>{6});
  CHECK(h.cut(2) == std::vector<int>{4, 5});
  CHECK(h.cut(4) == std::vector<int>{0, 1, 2, 3});
  // Merged intensity is the sum (l_new = l_a + l_b).
  CHECK(h.nodes()[6].intensity == Rgb(4.f));
  // Each merge position is one of eq. 7's three candidates: inside its pair's span.
  const Vec3 p = h.nodes()[h.cut(2)[0]].position;
  CHECK((glm::length(p - Vec3(1.1f, 2.f, 1.05f)) < 0.2f || glm::length(p - Vec3(4.9f, 2.05f, 4.f)) < 0.2f));
}

TEST_CASE("the sampler favours shadow edges and keeps each point at most once", "[sampler]") {
  Scene raw = builders::plane(4.f);
  builders::add_box(raw, {-0.5f, 1.f, -0.5f}, {0.5f, 1.05f, 0.5f}, Rgb(0.5f), false, "blocker");
  auto scene = test::finish(std::move(raw), 0.1f);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  Light light = Light::point({0.f, 3.f, 0.f}, Rgb(4.f));
  Target target = vertex_target(*scene, renderer->illuminate(SurfacePoints::from_vertices(*scene), std::span<const Light>(&light, 1)));
  auto importance = test::registry().create_sampler("importance", {});
  auto uniform = test::registry().create_sampler("uniform", {});
  SampleRequest request{target.size() / 10, 0.2f, 1};
  SampleSet s = importance->draw(target, request);
  CHECK(s.size() >= request.count - 1);
  CHECK(s.size() <= request.count);
  std::vector<uint32_t> idx = s.target_index;
  std::sort(idx.begin(), idx.end());
  CHECK(std::adjacent_find(idx.begin(), idx.end()) == idx.end());
  // Near the umbra's edge (|x| or |z| ≈ 0.75) the density of samples is higher than far out.
  auto density = [&](const SampleSet& set, float lo, float hi) {
    size_t all = 0, drawn = 0;
    for (size_t i = 0; i < target.size(); ++i) {
      const Vec3& p = target.points.positions[i];
      float r = std::max(std::abs(p.x), std::abs(p.z));
      if (p.y == 0.f && r >= lo && r < hi) ++all;
    }
    for (size_t i = 0; i < set.size(); ++i) {
      const Vec3& p = set.points.positions[i];
      float r = std::max(std::abs(p.x), std::abs(p.z));
      if (p.y == 0.f && r >= lo && r < hi) ++drawn;
    }
    return double(drawn) / double(std::max<size_t>(1, all));
  };
  SampleSet flat = uniform->draw(target, request);
  INFO("importance: edge density " << density(s, 0.65f, 0.85f) << ", far " << density(s, 2.5f, 3.5f) << "; uniform: edge "
                                   << density(flat, 0.65f, 0.85f) << ", far " << density(flat, 2.5f, 3.5f));
  CHECK(density(s, 0.65f, 0.85f) > 2.0 * density(s, 2.5f, 3.5f));
  // The uniform sampler is the baseline: no such preference.
  CHECK(density(flat, 0.65f, 0.85f) < 1.5 * density(flat, 2.5f, 3.5f));
  // Deterministic for a seed.
  CHECK(importance->draw(target, request).target_index == s.target_index);
}


TEST_CASE("after a solve, the light count moves up and down the hierarchy's cuts without a new solve", "[solver][cuts]") {
  auto scene = test::finish(builders::furnished_room(), 0.4f);
  auto rays = std::make_shared<const RayScene>(*scene);
  Lighting truth = {Light::point({1.5f, 2.5f, 1.1f}, Rgb(2.f)), Light::point({4.6f, 2.4f, 1.4f}, Rgb(2.f)),
                    Light::point({2.3f, 1.6f, 3.9f}, Rgb(1.6f))};
  auto reference = test::make_renderer("embree", scene, {"bounce_samples=32"});
  auto fast = test::make_renderer("embree", scene, {"bounce_samples=32", "bounce_direct=vertex"});
  Target target = vertex_target(*scene, reference->illuminate(SurfacePoints::from_vertices(*scene), truth));
  auto sampler = test::registry().create_sampler("importance", {});
  auto optimizer = test::registry().create_optimizer("varpro", {});
  SolveSettings settings;  // cache in memory only
  auto cache = test::registry().create_cache(PluginDefaults::cache, {});
  Solver solver(scene, rays, *fast, *reference, *sampler, *optimizer, cache.get(), settings);
  CHECK_THROWS(solver.cut_lights(1));
  SolveReport report;
  Lighting found = solver.solve(target, report);
  REQUIRE(found.size() == 3);
  REQUIRE(solver.cut_count() >= 3);
  CHECK(solver.cut_lights(1).size() == 1);
  CHECK(solver.cut_lights(2).size() == 2);
  CHECK(solver.cut_lights(solver.cut_count()).size() >= 3);
  // The chosen cut's lights are where the solve put them (before the final re-fit).
  Lighting three = solver.cut_lights(3);
  for (const auto& t : truth) {
    float best = 1e9f;
    for (const auto& l : three) best = std::min(best, glm::length(l.position - t.position));
    CHECK(best < 0.05f * scene->diagonal());
  }
  CHECK(solver.cut_lights(1000).size() == solver.cut_lights(solver.cut_count()).size());  // clamped
}
