// Regions (hilight/regions.hpp): the connected parts of free space. Two
// rooms behind a closed wall are two regions, a door joins them; the IFC
// house from assimp-testmodels splits into its closed rooms and the outside;
// --place region:K / not-region:K hold in every result.
#include "hilight/error.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/light_space.hpp"
#include "hilight/solve/diagnosis.hpp"
#include "hilight/solve/solve_renderers.hpp"
#include "hilight/solve/solver.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

namespace {

/// A 6 x 3 x 4 room split at x = 3 by a wall 0.2 thick; `door`: a 1 m wide,
/// 2.1 m high opening in it.
Scene two_rooms(bool door) {
  Scene s = builders::box_room(Vec3(6.f, 3.f, 4.f));
  if (door) {
    builders::add_box(s, Vec3(2.9f, 0.f, 0.f), Vec3(3.1f, 3.f, 1.5f), Rgb(0.8f), false, "wall");
    builders::add_box(s, Vec3(2.9f, 0.f, 2.5f), Vec3(3.1f, 3.f, 4.f), Rgb(0.8f), false, "wall");
    builders::add_box(s, Vec3(2.9f, 2.1f, 1.5f), Vec3(3.1f, 3.f, 2.5f), Rgb(0.8f), false, "lintel");
  } else {
    builders::add_box(s, Vec3(2.9f, 0.f, 0.f), Vec3(3.1f, 3.f, 4.f), Rgb(0.8f), false, "wall");
  }
  return finish_scene(std::move(s), {});
}

} // namespace

TEST_CASE("regions: a closed wall makes two rooms, a door joins them", "[regions]") {
  const Scene closed = two_rooms(false), open = two_rooms(true);
  const RayScene closed_rays(closed), open_rays(open);
  const Regions apart(closed_rays), joined(open_rays);
  REQUIRE(apart.list().size() == 2);
  CHECK(apart.at(Vec3(1.5f, 1.5f, 2.f)) != apart.at(Vec3(4.5f, 1.5f, 2.f)));
  CHECK(apart.list()[0].volume == Approx(apart.list()[1].volume).epsilon(0.1));  // two equal rooms
  REQUIRE(joined.list().size() == 1);
  CHECK(joined.at(Vec3(1.5f, 1.5f, 2.f)) == joined.at(Vec3(4.5f, 1.5f, 2.f)));
  CHECK(joined.at(Vec3(2.87f, 1.5f, 0.5f)) == 0);  // 3 cm from the wall, in its voxels: the room's region
  CHECK(joined.at(Vec3(30.f, 1.5f, 2.f)) == -1);  // outside the light bounds
}

TEST_CASE("regions: the IFC house splits into the outside, its storeys and its closed rooms", "[regions][real]") {
  const Scene house = load_scene(builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc");
  const RayScene rays(house);
  const Regions regions(rays);
  CHECK(regions.list().size() >= 3);
  for (size_t r = 1; r < regions.list().size(); ++r) CHECK(regions.list()[r].volume <= regions.list()[r - 1].volume);
}

TEST_CASE("regions: region:K and not-region:K hold in every result", "[regions][placement]") {
  auto scene = std::make_shared<const Scene>(two_rooms(false));
  auto rays = std::make_shared<const RayScene>(*scene);
  const Regions regions(*rays);
  const int left = regions.at(Vec3(1.5f, 1.5f, 2.f)), right = regions.at(Vec3(4.5f, 1.5f, 2.f));
  REQUIRE(left >= 0);
  REQUIRE(right >= 0);
  auto reference = test::make_renderer("embree", scene, reference_renderer_settings({}, 1));
  auto fast = test::make_renderer("embree", scene, fast_renderer_settings(test::registry().renderer_traits("embree"), {}));
  const Lighting truth = {Light::point({1.4f, 2.5f, 1.8f}, Rgb(2.f)), Light::point({4.4f, 2.4f, 2.3f}, Rgb(1.5f, 1.8f, 2.f))};
  const std::vector<Rgb> values = reference->illuminate(SurfacePoints::from_vertices(*scene), truth);
  const Target target = bind_target("two rooms", scene->positions, values, std::vector<float>(values.size(), 1.f), *scene, *rays, scene->normals);
  auto sampler = test::registry().create_sampler("importance", {});
  auto optimizer = test::registry().create_optimizer("varpro", {});
  for (const std::string& rule : {"not-region:" + std::to_string(right), "region:" + std::to_string(left)}) {
    INFO(rule);
    SolveSettings s;
    s.placement.add(rule);
    Solver solver(scene, rays, *fast, *reference, *sampler, *optimizer, nullptr, s);
    SolveReport report;
    const Lighting lights = solver.solve(target, report);
    REQUIRE_FALSE(lights.empty());
    for (const auto& l : lights) CHECK(regions.at(l.position) == left);
    CHECK(report.dbar > 0.2);  // the right room's light is excluded: its half of the target stays dark
    CHECK(report.unreachable > 0.25);  // ...and the report says why: no allowed place sees it
  }
  // Unlimited, both lights are found.
  SolveSettings s;
  Solver solver(scene, rays, *fast, *reference, *sampler, *optimizer, nullptr, s);
  SolveReport report;
  CHECK(solver.solve(target, report).size() == 2);
  CHECK(report.dbar < 0.01);
  CHECK(unreachable_share(target, LightSpace(*rays)) < 0.05);  // lit points are seen from somewhere (but corners a coarse grid misses)
  // A region that does not exist, or a malformed one, is an input error.
  PlacementRules missing;
  missing.add("region:9");
  CHECK_THROWS_WITH(LightSpace(*rays, missing), Catch::Contains("2 regions"));
  PlacementRules rules;
  CHECK_THROWS_WITH(rules.add("not-region:-1"), Catch::Contains("region number"));
  CHECK_THROWS_WITH(rules.add("region:1.5"), Catch::Contains("region number"));
}

TEST_CASE("regions: the hierarchy merges a split lamp within its room first, and every merged light stands in a child's room",
          "[regions][hierarchy]") {
  auto scene = std::make_shared<const Scene>(two_rooms(false));
  const RayScene rays(*scene);
  const LightSpace space(rays);
  auto renderer = test::make_renderer("embree", scene, {"bounces=0"});
  // Room A's lamp found as two lights (a seeding's split), room B's as one;
  // the target: one lamp in each room.
  const Lighting leaves = {Light::point({1.3f, 2.5f, 2.f}, Rgb(1.f)), Light::point({4.5f, 2.5f, 2.f}, Rgb(1.f)),
                           Light::point({1.7f, 2.5f, 2.1f}, Rgb(1.f))};
  const Lighting truth = {Light::point({1.5f, 2.5f, 2.05f}, Rgb(2.f)), Light::point({4.5f, 2.5f, 2.f}, Rgb(1.f))};
  const std::vector<Rgb> values = renderer->illuminate(SurfacePoints::from_vertices(*scene), truth);
  const Target target = bind_target("two rooms", scene->positions, values, std::vector<float>(values.size(), 1.f), *scene, rays, scene->normals);
  const SampleSet samples = all_samples(target);
  ResponseModel model(*renderer, samples, nullptr);
  const auto phi = model.responses(leaves);
  auto may_stand_at = [&](const Vec3& x, const Vec3& a, const Vec3& b) {
    const int room = space.regions().at(x);
    return space.admissible(x) && (room == space.regions().at(a) || room == space.regions().at(b));
  };
  const LightHierarchy h = LightHierarchy::build(model, leaves, phi, {}, {}, {}, may_stand_at);
  REQUIRE(h.nodes().size() == 5);
  CHECK(std::minmax(h.nodes()[3].left, h.nodes()[3].right) == std::minmax(0, 2));  // the split lamp first
  const std::vector<int> two = h.cut(2);
  REQUIRE(two.size() == 2);
  CHECK(space.regions().at(h.nodes()[two[0]].position) != space.regions().at(h.nodes()[two[1]].position));
  for (size_t k = leaves.size(); k < h.nodes().size(); ++k) {
    const Cluster& c = h.nodes()[k];
    const Vec3 a = h.nodes()[c.left].position, b = h.nodes()[c.right].position;
    INFO("merge " << k);
    CHECK(may_stand_at(c.position, a, b));
  }
}
