// The painter reads and writes glTF targets and lights as the CLI does
// (docs/interchange.md): a painted target saved as .glb reads back through
// read_target and load_target unchanged, and lights through KHR_lights_punctual.
#include "hilight/io/gltf.hpp"
#include "core/brush.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace painter_test;
using namespace hilight::painter;

TEST_CASE("painter: a target and lights saved as glTF load back exactly", "[painter][gltf]") {
  auto world = make_world(builders::box_room({3.f, 2.f, 3.f}), 0.4f);
  auto doc = world.document();
  BrushSettings brush;
  brush.radius = 0.5f;
  brush.colour = Rgb(0.9f, 0.6f, 0.3f);
  brush.brightness = 4.f;  // above 1: kept through the file's colour scale
  brush.hardness = 0.3f;
  paint_stroke(*doc, brush, BrushMode::Paint, {{1.f, 0.f, 1.f}, {1.5f, 0.f, 1.2f}, {0.f, 1.f, 1.5f}});
  const size_t n = doc->painted_count();
  REQUIRE(n > 10);
  const auto dir = test::output_dir("painter_gltf");
  doc->save_target(dir / "target.glb");
  const Target direct = doc->target(), read = read_target(dir / "target.glb", *world.scene, *world.rays);
  REQUIRE(read.size() == n);
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) CHECK(read.value[i][c] == Approx(direct.value[i][c]).epsilon(1e-6));
    CHECK(read.weight[i] == Approx(direct.weight[i]).epsilon(1e-6));
  }
  auto other = world.document();
  other->load_target(dir / "target.glb");
  CHECK(other->painted_count() == n);

  const Lighting lights = {Light::point({1.f, 1.5f, 1.f}, Rgb(3.f, 2.f, 1.f)),
                           Light::spot({1.5f, 1.9f, 1.5f}, {0.f, -1.f, 0.f}, 25.f, Rgb(4.f), 5.f)};
  doc->set_lights(lights, "lights");
  doc->save_lights(dir / "lights.gltf");
  other->load_lights(dir / "lights.gltf");
  REQUIRE(other->state().lights.size() == 2);
  CHECK(other->state().lights[1].type == LightType::Spot);
  CHECK(glm::length(other->state().lights[0].position - lights[0].position) < 1e-5f);
  CHECK(other->state().lights[0].intensity.g == Approx(2.f));
}
