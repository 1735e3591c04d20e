// The file's own precision (issue 35, item 14): a scene 10⁴ to 10⁶ m from
// the origin, written in full (not on a float grid), renders as it does at
// home. Its positions are read in double and moved home before they are
// rounded to float (far_positions.hpp); read in single precision first, the
// 10⁴ copy was off by 18.6% D̄. Formats assimp reads in single precision
// from a more precise file say so once, with the size of the error.
#include "hilight/fixtures/real_model_scenes.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

using namespace hilight;
namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

/// The scene moved by `by`, every digit kept: OBJ, or ASCII PLY with double positions.
void write_scene(const fs::path& path, const Scene& scene, const glm::dvec3& by) {
  std::ofstream out(path);
  out << std::setprecision(17);
  const bool ply = path.extension() == ".ply";
  if (ply)
    out << "ply\nformat ascii 1.0\nelement vertex " << scene.positions.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nproperty float nx\nproperty float ny\nproperty float nz\n"
        << "element face " << scene.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    const glm::dvec3 p = glm::dvec3(scene.positions[v]) + by;
    const Vec3& n = scene.normals[v];
    if (ply) out << p.x << ' ' << p.y << ' ' << p.z << ' ' << n.x << ' ' << n.y << ' ' << n.z << "\n";
    else out << "v " << p.x << ' ' << p.y << ' ' << p.z << "\nvn " << n.x << ' ' << n.y << ' ' << n.z << "\n";
  }
  for (const auto& t : scene.triangles)
    if (ply) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << "\n";
    else out << "f " << t[0] + 1 << "//" << t[0] + 1 << ' ' << t[1] + 1 << "//" << t[1] + 1 << ' ' << t[2] + 1 << "//" << t[2] + 1 << "\n";
}

/// Two lights at home, to be moved by `by`: millimetres that a float at 10⁶
/// (spacing 6 cm) cannot hold.
const std::vector<glm::dvec3> kLightsAtHome = {{1.2345, 2.5015, 0.7528}, {-1.0073, 1.7462, 1.5091}};

void write_lights(const fs::path& path, const glm::dvec3& by) {
  std::ofstream out(path);
  const glm::dvec3 a = kLightsAtHome[0] + by, b = kLightsAtHome[1] + by;
  out << std::setprecision(17) << R"({"lights": [{"type": "point", "position": [)" << a.x << ", " << a.y << ", " << a.z
      << R"(], "intensity": [2, 2, 2]}, {"type": "point", "position": [)" << b.x << ", " << b.y << ", " << b.z
      << R"(], "intensity": [1, 0.8, 0.6]}]})";
}

std::vector<Rgb> render(const fs::path& scene, const fs::path& lights, const fs::path& out, std::string& err) {
  const auto r = test::run_hilight({"render", scene.string(), "--lights", lights.string(), "-o", out.string()});
  err = r.err;
  if (r.exit_code != 0) return {};
  return test::ply_colours(out);
}

} // namespace

TEST_CASE("a scene 10^4 to 10^6 m away, written in full, renders within 1% of it at home", "[far][scene][precision]") {
  if (!fs::exists(builders::testmodels_dir())) {
    std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
    return;
  }
  const fs::path dir = test::output_dir("file_precision");
  const Scene scene = builders::curved_models_on_floor();
  write_lights(dir / "home.json", glm::dvec3(0.0));
  for (const std::string ext : {".obj", ".ply"}) {
    write_scene(dir / ("home" + ext), scene, glm::dvec3(0.0));
    std::string err;
    const auto home = render(dir / ("home" + ext), dir / "home.json", dir / ("home" + ext + ".out.ply"), err);
    INFO(err);
    REQUIRE(!home.empty());
    for (const glm::dvec3 far : {glm::dvec3(10240.0, 0.0, -12288.0), glm::dvec3(102400.0, 8.0, -131072.0), glm::dvec3(1000000.0, 0.0, -1048576.0)}) {
      const std::string name = "far" + std::to_string(int(far.x)) + ext;
      CAPTURE(name);
      write_scene(dir / name, scene, far);
      write_lights(dir / (name + ".json"), far);
      const auto moved = render(dir / name, dir / (name + ".json"), dir / (name + ".out.ply"), err);
      INFO(err);
      REQUIRE(moved.size() == home.size());
      CHECK(test::dbar(moved, home) < 0.01);
      CHECK(err.find("warning") == std::string::npos);  // nothing was rounded: nothing to say
    }
  }
}

TEST_CASE("lights 10^6 m away keep their millimetres through a solve: read and written in double", "[far][lights][precision]") {
  if (!fs::exists(builders::testmodels_dir())) {
    std::cout << "SKIPPED: assimp-testmodels is not installed" << std::endl;
    return;
  }
  const fs::path dir = test::output_dir("file_precision_lights");
  const glm::dvec3 far(1000000.0, 0.0, -1048576.0);
  write_scene(dir / "far.obj", builders::curved_models_on_floor(), far);
  write_lights(dir / "far.json", far);
  std::string err;
  REQUIRE(!render(dir / "far.obj", dir / "far.json", dir / "target.ply", err).empty());
  // The lights that made the target are the solve's fixed point; what it
  // writes must be where they were, to the millimetre (a float rounds to 3 cm).
  const auto solve = test::run_hilight({"solve", (dir / "far.obj").string(), "--target", (dir / "target.ply").string(), "--initial",
                                        (dir / "far.json").string(), "--mode", "fine-tune", "-o", (dir / "found.json").string(),
                                        "--cache-dir", (dir / "cache").string(), "-q"});
  INFO(solve.err);
  REQUIRE(solve.exit_code == 0);
  std::ifstream in(dir / "found.json");
  const auto found = nlohmann::json::parse(in)["lights"];
  REQUIRE(found.size() == kLightsAtHome.size());
  for (size_t j = 0; j < found.size(); ++j) {
    const auto& p = found[j]["position"];
    const glm::dvec3 written(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
    CAPTURE(j, written.x, written.y, written.z);
    CHECK(glm::length(written - (kLightsAtHome[j] + far)) < 1e-3);
  }
}

TEST_CASE("a far scene that assimp reads in single precision says so once, with the size of the error", "[far][scene][precision]") {
  const fs::path dir = test::output_dir("file_precision_said");
  // OFF: text, read by assimp alone. 10⁵ away: a float steps by 2⁻⁷ there.
  test::write_text(dir / "far.off", "OFF\n4 2 0\n100000.1 0 0\n100001.3 0 0\n100001.3 0 1.7\n100000.1 0 1.7\n3 0 1 2\n3 0 2 3\n");
  const auto r = test::run_hilight({"info", (dir / "far.off").string()});
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Contains("far.off") && Contains("single precision") && Contains("3.9 mm"));
}
