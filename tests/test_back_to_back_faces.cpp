// A back-to-back duplicate face (issue 35, item 11): a floor quad plus a
// flipped copy of one of its triangles. Counted in which way the surface
// faces, the copy made the floor face "both ways", the light bounds reached
// only a quarter diagonal above it, and the solve of the quad's own 1-light
// render ended with 3-4 lights at D̄ 3-8% after 30 s (the plain quad: 1
// light, 0.6 s). A two-sided sheet faces neither way (light_bounds.cpp).
#include "hilight/io/lights_json.hpp"
#include "hilight/io/scene_io.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>

namespace fs = std::filesystem;
using namespace hilight;

namespace {
const std::string kQuad = "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 4 3\nf 1 3 2\n";  // facing +y
const Vec3 kLight(0.3f, 1.2f, -0.2f);  // above a quarter diagonal (0.71)
} // namespace

TEST_CASE("a back-to-back duplicate face leaves the light bounds of the face it doubles", "[light-bounds][scene]") {
  const fs::path dir = test::output_dir("back_to_back_bounds");
  test::write_text(dir / "quad.obj", kQuad);
  test::write_text(dir / "doubled.obj", kQuad + "f 1 2 3\n");  // the second triangle, flipped
  const Bounds plain = load_scene(dir / "quad.obj").light_bounds(), doubled = load_scene(dir / "doubled.obj").light_bounds();
  CHECK(doubled.hi.y == Approx(plain.hi.y));
  CHECK(doubled.lo.y == Approx(plain.lo.y));
  CHECK(doubled.hi.y > kLight.y);
}

TEST_CASE("a quad with a back-to-back duplicate triangle solves to its one light", "[solve][cli][light-bounds]") {
  const fs::path dir = test::output_dir("back_to_back_solve");
  test::write_text(dir / "doubled.obj", kQuad + "f 1 2 3\n");
  write_lights_json(dir / "one.json", {Light::point(kLight, Rgb(1.f))});
  REQUIRE(test::run_hilight({"render", (dir / "doubled.obj").string(), "--lights", (dir / "one.json").string(), "-o",
                             (dir / "target.ply").string()})
              .exit_code == 0);
  const auto r = test::run_hilight({"solve", (dir / "doubled.obj").string(), "--target", (dir / "target.ply").string(), "-o",
                                    (dir / "found.json").string(), "--no-cache"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Lighting found = read_lights_json(dir / "found.json");
  REQUIRE(found.size() == 1);
  CHECK(glm::length(found[0].position - kLight) < 1e-2f);
  CHECK(r.err.find("warning") == std::string::npos);
  CHECK(r.err.find("D̄ 0.0") != std::string::npos);  // under 0.1%
}
