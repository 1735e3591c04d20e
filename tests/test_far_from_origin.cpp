// Where a scene sits does not change its light (issue 15): a real model
// scene written at home and moved 10⁴ away, lights moved with it, renders the
// same per-vertex values and solves to the same lights, moved. The scene is
// moved home when loaded (scene_origin.hpp), so both are computed alike.
// Coordinates are on a 2⁻¹⁰ grid so that the far copy is exact in float
// (at 10⁴ a float steps by 2⁻¹⁰): the comparison is of hilight, not of rounding.
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply_reader.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/scene_origin.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>

using namespace hilight;
namespace fs = std::filesystem;

namespace {

const glm::dvec3 kFar(10240.0, 0.0, -12288.0);  // where a float steps by 2⁻¹⁰

double on_grid(double v) { return std::round(v * 1024.0) / 1024.0; }

/// The scene as OBJ (positions and normals), its vertices on the 2⁻¹⁰ grid, moved by `by`.
void write_obj(const fs::path& path, const Scene& scene, const glm::dvec3& by) {
  std::ofstream obj(path);
  obj << std::setprecision(17);
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    const Vec3& p = scene.positions[v];
    const Vec3& n = scene.normals[v];
    obj << "v " << on_grid(p.x) + by.x << ' ' << on_grid(p.y) + by.y << ' ' << on_grid(p.z) + by.z << "\nvn " << n.x << ' ' << n.y
        << ' ' << n.z << "\n";
  }
  for (const auto& t : scene.triangles)
    obj << "f " << t[0] + 1 << "//" << t[0] + 1 << ' ' << t[1] + 1 << "//" << t[1] + 1 << ' ' << t[2] + 1 << "//" << t[2] + 1 << "\n";
}

void write_lights(const fs::path& path, const glm::dvec3& by) {
  std::ofstream out(path);
  out << std::setprecision(17) << R"({"lights": [{"type": "point", "position": [)" << 1.25 + by.x << ", " << 2.5 + by.y << ", "
      << 0.75 + by.z << R"(], "intensity": [2, 2, 2]}, {"type": "point", "position": [)" << -1.0 + by.x << ", " << 1.75 + by.y
      << ", " << 1.5 + by.z << R"(], "intensity": [1, 0.8, 0.6]}]})";
}

struct Copies {
  fs::path dir, home_obj, far_obj, home_lights, far_lights;
};

Copies make_copies(const std::string& name) {
  Copies c;
  c.dir = test::output_dir(name);
  const Scene scene = builders::curved_models_on_floor();
  c.home_obj = c.dir / "home.obj";
  c.far_obj = c.dir / "far.obj";
  write_obj(c.home_obj, scene, glm::dvec3(0.0));
  write_obj(c.far_obj, scene, kFar);
  c.home_lights = c.dir / "home-lights.json";
  c.far_lights = c.dir / "far-lights.json";
  write_lights(c.home_lights, glm::dvec3(0.0));
  write_lights(c.far_lights, kFar);
  return c;
}

} // namespace

TEST_CASE("a scene 10^4 away is moved home when loaded, exactly", "[far][scene]") {
  if (!fs::exists(builders::testmodels_dir())) {
    std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
    return;
  }
  const Copies c = make_copies("far_load");
  const Scene home = load_scene(c.home_obj), far = load_scene(c.far_obj);
  CHECK(home.frame.origin == glm::dvec3(0.0));
  CHECK(far.frame.origin == kFar);
  REQUIRE(far.positions.size() == home.positions.size());
  CHECK(far.positions == home.positions);  // the same local scene, bit for bit
  const auto info = test::run_hilight({"info", c.far_obj.string()});
  CHECK(info.exit_code == 0);
  CHECK(info.out.find("origin     [10240, 0, -12288]") != std::string::npos);
}

TEST_CASE("a scene 10^4 away renders as it does at home, and writes world positions", "[far][render][cli]") {
  if (!fs::exists(builders::testmodels_dir())) {
    std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
    return;
  }
  const Copies c = make_copies("far_render");
  for (const std::string bounces : {"0", "1"}) {
    INFO("bounces " << bounces);
    const auto home = test::run_hilight({"render", c.home_obj.string(), "--lights", c.home_lights.string(), "-o",
                                         (c.dir / ("home" + bounces + ".ply")).string(), "--bounces", bounces});
    const auto far = test::run_hilight({"render", c.far_obj.string(), "--lights", c.far_lights.string(), "-o",
                                        (c.dir / ("far" + bounces + ".ply")).string(), "--bounces", bounces});
    INFO(home.err << far.err);
    REQUIRE(home.exit_code == 0);
    REQUIRE(far.exit_code == 0);
    const auto a = test::ply_colours(c.dir / ("home" + bounces + ".ply")), b = test::ply_colours(c.dir / ("far" + bounces + ".ply"));
    REQUIRE(a.size() == b.size());
    CHECK(test::dbar(b, a) == 0.0);
    // The far render's positions are the world's, in doubles: where the file put them.
    const PlyVertices h = read_ply_vertices(c.dir / ("home" + bounces + ".ply")), f = read_ply_vertices(c.dir / ("far" + bounces + ".ply"));
    CHECK(f.types.at("x") == "double");
    for (size_t i = 0; i < h.count; i += 97) {
      CHECK(f.properties.at("x")[i] == h.properties.at("x")[i] + kFar.x);
      CHECK(f.properties.at("z")[i] == h.properties.at("z")[i] + kFar.z);
    }
  }
}

TEST_CASE("a scene 10^4 away solves to the lights found at home, moved", "[far][solve][cli]") {
  if (!fs::exists(builders::testmodels_dir())) {
    std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
    return;
  }
  const Copies c = make_copies("far_solve");
  Lighting found[2];
  for (int k = 0; k < 2; ++k) {
    const fs::path obj = k ? c.far_obj : c.home_obj, lights = k ? c.far_lights : c.home_lights;
    const fs::path target = c.dir / (std::string(k ? "far" : "home") + "-target.ply");
    REQUIRE(test::run_hilight({"render", obj.string(), "--lights", lights.string(), "-o", target.string()}).exit_code == 0);
    const fs::path out = c.dir / (std::string(k ? "far" : "home") + "-found.json");
    const auto r = test::run_hilight({"solve", obj.string(), "--target", target.string(), "-o", out.string(), "--no-cache"});
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    found[k] = read_lights_json(out);
  }
  REQUIRE(found[0].size() == 2);
  REQUIRE(found[1].size() == found[0].size());
  for (size_t j = 0; j < found[0].size(); ++j) {
    const glm::dvec3 moved = glm::dvec3(found[1][j].position) - kFar;
    INFO("light " << j);
    // The solve is the same computation: only the files' float rounding at 10^4 (2^-10) tells them apart.
    CHECK(glm::length(moved - glm::dvec3(found[0][j].position)) < 2e-3);
    CHECK(found[1][j].intensity == found[0][j].intensity);
  }
}
