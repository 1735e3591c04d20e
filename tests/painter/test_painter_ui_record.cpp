// A session the painter records replays to the same result: the starting
// lights file, brush settings, a stroke and a fine-tune are all in the file.
#include "../support.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoomLights = HILIGHT_SOURCE_DIR "/scenes/room-4lights.json";

} // namespace

TEST_CASE("painter ui: a recorded session replays to the same lights", "[painter-ui]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_record");
  const std::string lights_out = (dir / "tuned.json").string();
  const nlohmann::json session = {
      {"actions",
       {{{"type", "brush"}, {"radius", 0.5}, {"colour", {1.0, 0.9, 0.8}}, {"brightness", 0.4}},
        {{"type", "stroke"}, {"world", {{2.0, 0.0, 2.0}, {2.6, 0.0, 2.2}}}},
        {{"type", "camera"}, {"orbit", {20, 5}}, {"zoom", 0.8}},
        {{"type", "fine_tune"}},
        {{"type", "save_lights"}, {"path", lights_out}}}}};
  test::write_text(dir / "session.json", session.dump());
  const std::vector<std::string> common = {"--size", "320x240", "--set", "bounce_samples=16", "--samples", "800",
                                           "--cache-cells", "6", "--cache-dir", (dir / "cache").string(), "--exit"};

  std::vector<std::string> first = {"paint", kRoom, "--lights", kRoomLights, "--script", (dir / "session.json").string(),
                                    "--record", (dir / "recorded.json").string()};
  first.insert(first.end(), common.begin(), common.end());
  const test::RunResult a = test::run_hilight(first);
  INFO(a.err);
  REQUIRE(a.exit_code == 0);
  const std::string tuned = test::read_file(lights_out);
  REQUIRE(!tuned.empty());
  CHECK(tuned != test::read_file(kRoomLights));

  // The recording starts with the lights file and holds every action.
  const nlohmann::json recorded = nlohmann::json::parse(test::read_file(dir / "recorded.json"));
  REQUIRE(recorded["actions"].size() == session["actions"].size() + 1);
  CHECK(recorded["actions"][0]["type"] == "load_lights");
  CHECK(fs::path(recorded["actions"][0]["path"].get<std::string>()).is_absolute());

  // Replayed alone (no --lights), it makes the same lights.
  fs::remove(lights_out);
  std::vector<std::string> second = {"paint", kRoom, "--script", (dir / "recorded.json").string()};
  second.insert(second.end(), common.begin(), common.end());
  const test::RunResult b = test::run_hilight(second);
  INFO(b.err);
  REQUIRE(b.exit_code == 0);
  CHECK(test::read_file(lights_out) == tuned);
}
