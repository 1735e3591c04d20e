// Placement rules (--place, hilight/light_space.hpp): every rule holds in
// every result; a floor patch solved "on the ceiling" gives ceiling lights
// above it; an impossible rule is a clear input error.
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/light_space.hpp"
#include "hilight/solve/solve_renderers.hpp"
#include "hilight/solve/solver.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

namespace {
const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";

struct PatchSolve {
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const RayScene> rays;
  Target target;
  Vec3 centre{2.2f, 0.f, 3.0f};
  float radius = 0.5f;
};

/// A designer's target: a bright disc painted on the floor, the rest "don't care".
PatchSolve floor_patch() {
  PatchSolve p;
  p.scene = std::make_shared<const Scene>(load_scene(kRoom));
  p.rays = std::make_shared<const RayScene>(*p.scene);
  std::vector<Rgb> values(p.scene->positions.size(), Rgb(0.f));
  std::vector<float> weights(values.size(), 0.f);
  for (size_t v = 0; v < values.size(); ++v) {
    const Vec3& q = p.scene->positions[v];
    if (q.y < 1e-3f && p.scene->normals[v].y > 0.9f && glm::length(Vec3(q.x, 0.f, q.z) - p.centre) < p.radius)
      values[v] = Rgb(0.5f), weights[v] = 1.f;
  }
  p.target = bind_target("painted patch", p.scene->positions, values, weights, *p.scene, *p.rays, p.scene->normals);
  return p;
}

Lighting solve(const PatchSolve& p, PlacementRules rules, SolveReport& report) {
  auto renderer = test::make_renderer("embree", p.scene, fast_renderer_settings(test::registry().renderer_traits("embree"), {}));
  auto reference = test::make_renderer("embree", p.scene, reference_renderer_settings({}, 1));
  auto sampler = test::registry().create_sampler("importance", {});
  auto optimizer = test::registry().create_optimizer("varpro", {});
  SolveSettings s;
  s.placement = std::move(rules);
  Solver solver(p.scene, p.rays, *renderer, *reference, *sampler, *optimizer, nullptr, s);
  return solver.solve(p.target, report);
}
} // namespace

TEST_CASE("placement: a floor patch solved on the ceiling gives ceiling lights above it", "[placement]") {
  const PatchSolve p = floor_patch();
  PlacementRules rules;
  rules.add("ceiling:0.1");
  SolveReport report;
  const Lighting lights = solve(p, rules, report);
  REQUIRE_FALSE(lights.empty());
  const LightSpace space(*p.rays, rules);
  for (const auto& l : lights) {
    INFO("light at " << l.position.x << ", " << l.position.y << ", " << l.position.z);
    CHECK(l.position.y == Approx(3.0f - 0.1f).margin(1e-3));  // the room's ceiling is at y = 3
    CHECK(space.admissible(l.position));
  }
  // The patch is lit directly from the ceiling (the rest of the room is
  // "don't care": a far light lighting the room, and the patch by the bounce,
  // may help to make the disc even).
  auto renderer = test::make_renderer("embree", p.scene, {"bounces=0"});
  SurfacePoints centre;
  centre.positions = {p.centre};
  centre.normals = {Vec3(0.f, 1.f, 0.f)};
  centre.albedo = {Rgb(0.7f)};
  size_t lighting_it = 0;
  for (const auto& l : lights) lighting_it += renderer->illuminate(centre, Lighting{l})[0].g > 0.f;
  CHECK(lighting_it >= 1);
  CHECK(report.dbar < 0.3);  // an even disc is not exactly a lamp's pool, but most of it
}

TEST_CASE("placement: height ranges, boxes and exclusions hold in every result", "[placement]") {
  const PatchSolve p = floor_patch();
  for (const std::string rule : {"height:1.0:1.8", "box:0.2,0.2,0.2,3.5,2.8,4.8", "exclude:1.2,0,2.0,3.2,3,4.0"}) {
    INFO(rule);
    PlacementRules rules;
    rules.add(rule);
    SolveReport report;
    const Lighting lights = solve(p, rules, report);
    REQUIRE_FALSE(lights.empty());
    const LightSpace space(*p.rays, rules);
    for (const auto& l : lights) CHECK(space.admissible(l.position));
  }
}

TEST_CASE("placement: rules that make the target impossible or that do not parse are input errors", "[placement][bad-input]") {
  const PatchSolve p = floor_patch();
  PlacementRules outside;
  outside.add("box:100,100,100,101,101,101");  // nowhere in the room
  SolveReport report;
  CHECK_THROWS_AS(solve(p, outside, report), InputError);
  PlacementRules rules;
  CHECK_THROWS_WITH(rules.add("ceiling:-1"), Catch::Contains("offset"));
  CHECK_THROWS_WITH(rules.add("height:3:1"), Catch::Contains("MIN <= MAX"));
  CHECK_THROWS_WITH(rules.add("box:1,2,3"), Catch::Contains("6 numbers"));
  CHECK_THROWS_WITH(rules.add("floor"), Catch::Contains("unknown rule"));
  // Through the CLI: one line, exit 2.
  auto dir = test::output_dir("placement_cli");
  auto r = test::run_hilight({"solve", kRoom, "--target", (dir / "missing.ply").string(), "-o", (dir / "l.json").string(), "--place", "wall"});
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("unknown rule"));
}

namespace {
/// The bundled room lit by its four lamps, as `hilight render` writes it.
PatchSolve four_lamp_room() {
  PatchSolve p;
  p.scene = std::make_shared<const Scene>(load_scene(kRoom));
  p.rays = std::make_shared<const RayScene>(*p.scene);
  auto reference = test::make_renderer("embree", p.scene, reference_renderer_settings({}, 1));
  const Lighting truth = read_lights_json(std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json");
  const std::vector<Rgb> values = reference->illuminate(SurfacePoints::from_vertices(*p.scene), truth);
  p.target = bind_target("four lamps", p.scene->positions, values, std::vector<float>(values.size(), 1.f), *p.scene, *p.rays,
                         p.scene->normals);
  return p;
}
} // namespace

TEST_CASE("placement: count bounds hold, and a count beyond the seeding's candidates still solves", "[placement]") {
  const PatchSolve p = four_lamp_room();
  struct Case {
    const char* rule;
    size_t least, most;
  };
  for (const Case& c : {Case{"count:2:3", 2, 3}, Case{"count:6", 6, 6}}) {
    INFO(c.rule);
    PlacementRules rules;
    rules.add(c.rule);
    SolveReport report;
    const Lighting lights = solve(p, rules, report);
    CHECK(lights.size() >= c.least);
    CHECK(lights.size() <= c.most);
    if (c.least > 4) CHECK(report.dbar < 0.01);  // more lights than lamps: still the target
  }
  PlacementRules rules;
  CHECK_THROWS_WITH(rules.add("count:3:2"), Catch::Contains("MIN <= MAX"));
  CHECK_THROWS_WITH(rules.add("count:0"), Catch::Contains("whole numbers"));
  CHECK_THROWS_WITH(rules.add("count:1.5"), Catch::Contains("whole numbers"));
}
