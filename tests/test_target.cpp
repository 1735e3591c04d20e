// Targets: a PLY written by `hilight render` is a valid target, bound to the
// surface so exactly that the same renderer reproduces it; bad targets are
// refused with the file and the number of wrong points named.
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply.hpp"
#include "hilight/target.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

using namespace hilight;

namespace {
const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
const std::string kLights = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json";
} // namespace

TEST_CASE("a rendered PLY is a target that the same renderer reproduces point for point", "[target]") {
  auto scene = std::make_shared<const Scene>(load_scene(kRoom));
  RayScene rays(*scene);
  Lighting lights = read_lights_json(kLights);
  auto renderer = test::make_renderer("embree", scene, {"bounce_samples=32"});
  auto rendered = renderer->illuminate(SurfacePoints::from_vertices(*scene), lights);
  auto dir = test::output_dir("target_roundtrip");
  write_illuminated_ply(dir / "t.ply", *scene, rendered);

  Target target = read_target(dir / "t.ply", *scene, rays);
  REQUIRE(target.size() == scene->positions.size());
  for (size_t i = 0; i < target.size(); ++i) {
    REQUIRE(target.points.positions[i] == scene->positions[i]);
    REQUIRE(glm::dot(target.points.normals[i], scene->normals[i]) > 0.9999f);
    REQUIRE(target.value[i] == rendered[i]);
  }
  auto again = renderer->illuminate(target.points, lights);
  size_t differ = 0;
  for (size_t i = 0; i < target.size(); ++i) differ += glm::length(again[i] - target.value[i]) > 1e-5f * (glm::length(target.value[i]) + 1e-6f);
  CHECK(differ == 0);
}
