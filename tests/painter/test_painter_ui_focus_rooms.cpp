// In a building the painter's room focus takes rooms only (issue 34 §5), as
// `hilight solve --place region:K` does: the void under a raised floor (too
// low to stand in) and the outside of the IFC house are refused, saying why;
// the room over the raised floor is focused and lit.
#include "../support.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "hilight/io/lights_json.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace hilight;

namespace {

/// A closed 6 x 3 x 5 m room whose floor is raised 0.8 m on a slab filling it
/// (0.8 to 0.9 m): under the slab, a closed void 0.8 m high (a service void).
fs::path write_raised_floor_room(const fs::path& dir) {
  Scene scene = builders::box_room(Vec3(6.f, 3.f, 5.f));
  builders::add_box(scene, Vec3(0.f, 0.8f, 0.f), Vec3(6.f, 0.9f, 5.f), Rgb(0.6f), false, "slab");
  const fs::path path = dir / "raised-floor.obj";
  std::ofstream out(path);
  for (const Vec3& p : scene.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (const auto& t : scene.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  return path;
}

test::RunResult run_session(const fs::path& scene, const fs::path& dir, const nlohmann::json& actions) {
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  return test::run_hilight({"paint", scene.string(), "--size", "320x240", "--set", "bounce_samples=16", "--samples", "800", "--no-cache",
                            "--no-record", "--exit", "--script", (dir / "session.json").string()});
}

} // namespace

TEST_CASE("painter ui: a focus on the void under a raised floor is refused and the room over it is focused and lit", "[painter-ui][focus][rooms]") {
  if (test::skip_without_display()) return;
  test::CliOwnPlacement own;  // a closed interior: the building's rules
  const fs::path dir = test::output_dir("painter_ui_focus_void");
  const fs::path room = write_raised_floor_room(dir);
  // The floor under the slab looks into the void.
  const test::RunResult refused = run_session(room, dir, {{{"type", "focus"}, {"world", {3.0, 0.0, 2.5}}}});
  INFO(refused.err);
  CHECK(refused.exit_code == 2);
  CHECK(test::line_count(refused.err) == 2);  // the building's note, and the one-line error
  CHECK_THAT(refused.err, Catch::Contains("hilight: error: " + (dir / "session.json").string() + ": action 0 (focus): region "));
  CHECK_THAT(refused.err, Catch::Contains("is not a room of an interior, closed on every side (too low to stand in); focus a room"));
  // The raised floor's top looks into the room: focused, painted and solved, the lights stand over it.
  const test::RunResult lit = run_session(room, dir,
                                          {{{"type", "focus"}, {"world", {3.0, 0.9, 2.5}}},
                                           {{"type", "brush"}, {"radius", 0.8}, {"brightness", 0.5}},
                                           {{"type", "stroke"}, {"world", {{3.0, 0.9, 2.5}}}},
                                           {{"type", "solve"}},
                                           {{"type", "save_lights"}, {"path", (dir / "lights.json").string()}}});
  INFO(lit.err);
  REQUIRE(lit.exit_code == 0);
  const Lighting lights = read_lights_json(dir / "lights.json");
  REQUIRE_FALSE(lights.empty());
  for (const Light& l : lights) CHECK(l.position.y > 0.9f);
}

TEST_CASE("painter ui: the IFC house's outside is no room to focus", "[painter-ui][focus][rooms][real]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_focus_outside");
  const fs::path house = builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc";
  // hilight info numbers the house's regions: 0 is the outside (tests/painter/test_painter_ui_building.cpp).
  const test::RunResult refused = run_session(house, dir, {{{"type", "focus"}, {"regions", {0}}}});
  INFO(refused.err);
  CHECK(refused.exit_code == 2);
  CHECK(test::line_count(refused.err) == 1);
  CHECK_THAT(refused.err, Catch::Contains("region 0 is not a room of an IFC building with storeys (it is outside); focus a room"));
}
