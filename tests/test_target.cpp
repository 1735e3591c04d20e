// Targets: a PLY written by `hilight render` is a valid target, bound to the
// surface so exactly that the same renderer reproduces it; bad targets are
// refused with the file and the number of wrong points named.
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply.hpp"
#include "hilight/target.hpp"
#include "support.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <sstream>

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

namespace {
/// An ASCII target with `x y z red green blue` only (the documented minimal
/// format, as another tool writes it), points in the given order.
void write_plain_target(const std::filesystem::path& path, const Scene& scene, const std::vector<Rgb>& values,
                        const std::vector<size_t>& order) {
  std::ostringstream out;
  out.precision(9);
  out << "ply\nformat ascii 1.0\nelement vertex " << order.size()
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty float red\nproperty float green\nproperty float blue\nend_header\n";
  for (size_t v : order) {
    const Vec3& p = scene.positions[v];
    out << p.x << ' ' << p.y << ' ' << p.z << ' ' << values[v].r << ' ' << values[v].g << ' ' << values[v].b << '\n';
  }
  test::write_text(path, out.str());
}
} // namespace

TEST_CASE("a rendered target without normals still binds each point to the vertex it came from", "[target][vertex]") {
  auto scene = std::make_shared<const Scene>(load_scene(kRoom));
  RayScene rays(*scene);
  auto renderer = test::make_renderer("embree", scene, {"bounce_samples=32"});
  const auto rendered = renderer->illuminate(SurfacePoints::from_vertices(*scene), read_lights_json(kLights));
  const auto dir = test::output_dir("target_no_normals");
  std::vector<size_t> order(scene->positions.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  // Vertex order: point i is vertex i, split crease vertices included.
  write_plain_target(dir / "ordered.ply", *scene, rendered, order);
  Target ordered = read_target(dir / "ordered.ply", *scene, rays);
  REQUIRE(ordered.size() == order.size());
  for (size_t i = 0; i < ordered.size(); ++i) REQUIRE(ordered.vertex[i] == int32_t(i));
  CHECK(test::dbar(renderer->illuminate(ordered.points, read_lights_json(kLights)), ordered.value) < 1e-6);
  // Reversed file order: points at a shared position still pair one to one
  // with its vertices, so no vertex is taken twice.
  std::reverse(order.begin(), order.end());
  write_plain_target(dir / "reversed.ply", *scene, rendered, order);
  Target reversed = read_target(dir / "reversed.ply", *scene, rays);
  std::vector<int> taken(scene->positions.size(), 0);
  for (size_t i = 0; i < reversed.size(); ++i) {
    REQUIRE(reversed.vertex[i] >= 0);
    REQUIRE(scene->positions[size_t(reversed.vertex[i])] == scene->positions[order[i]]);
    ++taken[size_t(reversed.vertex[i])];
  }
  CHECK(std::count(taken.begin(), taken.end(), 1) == long(taken.size()));
}

TEST_CASE("a target point between vertices binds to the nearest surface point", "[target][vertex]") {
  auto scene = std::make_shared<const Scene>(load_scene(kRoom));
  RayScene rays(*scene);
  const auto& tri = scene->triangles[0];
  const Vec3 centre = (scene->positions[tri[0]] + scene->positions[tri[1]] + scene->positions[tri[2]]) / 3.f;
  Target t = bind_target("test", {centre}, {Rgb(1.f)}, {1.f}, *scene, rays);
  REQUIRE(t.vertex[0] == -1);
  CHECK(glm::length(t.points.positions[0] - centre) < 1e-5f * scene->diagonal());
}
