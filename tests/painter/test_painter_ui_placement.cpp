// The painter with a placement rule (`hilight paint --place`): a replayed
// session paints a bright patch on the floor of the bundled room and solves
// with "ceiling lights only"; every light it saves hangs from the ceiling
// (tests/test_placement.cpp checks that they light the patch).
#include "../support.hpp"
#include "hilight/io/lights_json.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace hilight;

namespace {
/// A session that paints one patch on the bundled room's floor, solves and
/// saves the lights to dir/lights.json; written to dir/session.json.
void write_patch_session(const fs::path& dir) {
  const nlohmann::json actions = {
      {{"type", "camera"}, {"eye", {3.0, 6.0, 9.0}}, {"target", {3.0, 0.0, 2.5}}, {"fov", 60}},
      {{"type", "brush"}, {"radius", 0.6}, {"colour", 1.0}, {"brightness", 0.6}, {"hardness", 0.7}},
      {{"type", "stroke"}, {"world", {{2.2, 0, 3.0}}}},
      {{"type", "solve"}},
      {{"type", "save_lights"}, {"path", (dir / "lights.json").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
}
} // namespace

TEST_CASE("painter ui: a replayed session with --place ceiling gives ceiling lights over the painted patch", "[painter-ui][placement]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_placement");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  write_patch_session(dir);
  const test::RunResult run = test::run_hilight({"paint", room, "--size", "480x360", "--set", "bounce_samples=16", "--samples", "800",
                                                 "--no-cache", "--no-record", "--exit", "--place", "ceiling:0.1", "--script",
                                                 (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const Lighting lights = read_lights_json(dir / "lights.json");
  REQUIRE_FALSE(lights.empty());
  for (const auto& l : lights) {
    INFO("light at " << l.position.x << ", " << l.position.y << ", " << l.position.z);
    CHECK(l.position.y == Approx(2.9f).margin(1e-3));  // the room's ceiling is at 3, the table's underside does not count
  }
  // A malformed rule is refused before any window opens.
  const test::RunResult bad = test::run_hilight({"paint", room, "--place", "ceiling:-2", "--exit", "--screenshot", (dir / "x.png").string()});
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
}

TEST_CASE("painter ui: the placement panel's rules, recorded as a place action, replay", "[painter-ui][placement]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_place_action");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const nlohmann::json actions = {
      {{"type", "camera"}, {"eye", {3.0, 6.0, 9.0}}, {"target", {3.0, 0.0, 2.5}}, {"fov", 60}},
      {{"type", "brush"}, {"radius", 0.6}, {"colour", 1.0}, {"brightness", 0.6}, {"hardness", 0.7}},
      {{"type", "stroke"}, {"world", {{2.2, 0, 3.0}}}},
      {{"type", "stroke"}, {"world", {{4.5, 0, 1.5}}}},
      {{"type", "place"}, {"rules", "ceiling:0.15 count:1:1"}},
      {{"type", "solve"}},
      {{"type", "save_lights"}, {"path", (dir / "ceiling.json").string()}},
      {{"type", "place"}, {"rules", "anywhere"}},
      {{"type", "solve"}},
      {{"type", "save_lights"}, {"path", (dir / "anywhere.json").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", room, "--size", "480x360", "--set", "bounce_samples=16", "--samples", "800",
                                                 "--no-cache", "--no-record", "--exit", "--script", (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const Lighting ceiling = read_lights_json(dir / "ceiling.json");
  REQUIRE(ceiling.size() == 1);  // count:1:1 for two patches
  CHECK(ceiling[0].position.y == Approx(2.85f).margin(1e-3));
  // Anywhere: the lights may stand anywhere free again (two patches, two lights near them).
  const Lighting anywhere = read_lights_json(dir / "anywhere.json");
  REQUIRE_FALSE(anywhere.empty());
  // Not pinned to the rule's mount height (2.85) any more: the solve may put
  // them anywhere, up to the ceiling itself (measured: 2.9997, the light
  // bounds' top) or down in the room.
  bool off_mount = false;
  for (const auto& l : anywhere) off_mount |= std::abs(l.position.y - 2.85f) > 0.01f;
  CHECK(off_mount);
  // A bad rule in a session is an input error naming the action: exit 2, one line.
  test::write_text(dir / "bad.json", nlohmann::json{{"actions", {{{"type", "place"}, {"rules", "height:2:1"}}}}}.dump());
  const test::RunResult bad = test::run_hilight({"paint", room, "--size", "320x240", "--no-record", "--exit", "--script", (dir / "bad.json").string()});
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
  CHECK_THAT(bad.err, Catch::Contains("MIN <= MAX"));
}

TEST_CASE("painter ui: in a closed room the painter hangs lights from the ceiling by default and says so", "[painter-ui][placement][rooms]") {
  if (test::skip_without_display()) return;
  test::CliOwnPlacement own;  // the building default under test (issue 34 §7)
  const fs::path dir = test::output_dir("painter_ui_building_default");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  write_patch_session(dir);
  const std::vector<std::string> args = {"paint", room, "--size", "480x360", "--set", "bounce_samples=16", "--samples", "800",
                                         "--no-cache", "--no-record", "--exit", "--script", (dir / "session.json").string()};
  const test::RunResult run = test::run_hilight(args);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.find("hilight: lights on the ceiling (an interior, closed on every side; --place anywhere lifts it)") != std::string::npos);
  const Lighting lights = read_lights_json(dir / "lights.json");
  REQUIRE_FALSE(lights.empty());
  for (const auto& l : lights) CHECK(l.position.y == Approx(2.8f).margin(1e-3));  // 0.2 under the 3 m ceiling
  // Lights given on the command line keep their places: no default, no note.
  std::vector<std::string> given = args;
  given.insert(given.end(), {"--lights", (dir / "lights.json").string()});
  const test::RunResult with_lights = test::run_hilight(given);
  REQUIRE(with_lights.exit_code == 0);
  CHECK(with_lights.err.find("lights on the ceiling") == std::string::npos);
}
