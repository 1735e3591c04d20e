// The painter's `place` rules are in the scene file's coordinates, as
// `hilight solve --place` takes them (issue 34): the bundled room written
// 10⁴ away is moved home when loaded, and a box and heights given in the
// file's coordinates still hold every light the session's solves place.
#include "core/session_player.hpp"
#include "hilight/error.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/scene_origin.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace hilight;
using namespace hilight::painter;
namespace fs = std::filesystem;

namespace {

const glm::dvec3 kFar(10240.0, 512.0, -12288.0);

/// scenes/room.obj with every vertex moved by kFar.
fs::path write_far_room(const fs::path& dir) {
  std::ifstream in(std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj");
  const fs::path path = dir / "room_far.obj";
  std::ofstream out(path);
  out << std::setprecision(17);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) != 0) {
      out << line << "\n";
      continue;
    }
    std::istringstream v(line.substr(2));
    double x, y, z;
    v >> x >> y >> z;
    out << "v " << x + kFar.x << ' ' << y + kFar.y << ' ' << z + kFar.z << "\n";
  }
  fs::copy_file(std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.mtl", dir / "room.mtl", fs::copy_options::overwrite_existing);
  return path;
}

std::string numbers(std::initializer_list<double> values) {
  std::ostringstream s;
  s << std::setprecision(10);
  bool first = true;
  for (double v : values) s << (first ? "" : ",") << v, first = false;
  return s.str();
}

} // namespace

TEST_CASE("painter place: boxes and heights are in the scene file's coordinates, for a scene moved home from far off", "[painter][placement]") {
  const fs::path dir = test::output_dir("painter_place_frame");
  const auto scene = std::make_shared<const Scene>(load_scene(write_far_room(dir)));
  REQUIRE_FALSE(scene->frame.identity());  // moved home: hilight's coordinates are not the file's
  const auto rays = std::make_shared<const RayScene>(*scene);
  painter::Document doc(scene, rays);
  SolveJob job(test::registry(), scene, rays, painter_test::quick_options());
  SessionPlayer player(doc, job, {}, {});
  // Two bright patches on the floor (stroke points are hilight's own coordinates).
  auto local = [&](double x, double y, double z) { return to_local(glm::dvec3(x, y, z) + kFar, scene->frame); };
  const Vec3 a = local(4.5, 0, 1.5), b = local(1.5, 0, 3.2);
  player.apply({"brush", {{"radius", 0.7}, {"brightness", 0.5}, {"hardness", 0.8}}});
  player.apply({"stroke", {{"world", {{a.x, a.y, a.z}}}}});
  player.apply({"stroke", {{"world", {{b.x, b.y, b.z}}}}});

  // A box over the first patch's corner of the room, in the file's coordinates.
  const glm::dvec3 lo = kFar + glm::dvec3(3.5, 2.0, 0.4), hi = kFar + glm::dvec3(5.5, 2.7, 2.6);
  player.apply({"place", {{"rules", "box:" + numbers({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z})}}}, 3);
  player.apply({"solve", nlohmann::json::object()});
  REQUIRE_FALSE(doc.state().lights.empty());
  for (const Light& light : doc.state().lights) {
    const glm::dvec3 w = to_world(light.position, scene->frame);
    INFO("light at " << w.x << " " << w.y << " " << w.z << " (file)");
    CHECK(w.x >= lo.x - 1e-2);
    CHECK(w.x <= hi.x + 1e-2);
    CHECK(w.y >= lo.y - 1e-2);
    CHECK(w.y <= hi.y + 1e-2);
    CHECK(w.z >= lo.z - 1e-2);
    CHECK(w.z <= hi.z + 1e-2);
  }

  // Heights, too: the file's y, 512 above hilight's.
  player.apply({"place", {{"rules", "height:" + numbers({kFar.y + 1.2}) + ":" + numbers({kFar.y + 1.6})}}}, 5);
  player.apply({"solve", nlohmann::json::object()});
  REQUIRE_FALSE(doc.state().lights.empty());
  for (const Light& light : doc.state().lights) {
    const double y = to_world(light.position, scene->frame).y - kFar.y;
    INFO("light " << y << " over the floor");
    CHECK(y >= 1.2 - 1e-2);
    CHECK(y <= 1.6 + 1e-2);
  }
  // Heights in hilight's own coordinates (0 to 3 here) are now below the file's floor: no place keeps them.
  player.apply({"place", {{"rules", "height:1.2:1.6"}}}, 7);
  CHECK_THROWS_AS(player.apply({"solve", nlohmann::json::object()}, 8), InputError);
}
