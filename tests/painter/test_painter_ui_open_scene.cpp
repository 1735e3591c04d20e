// Opening another scene in the painter (the Files panel's "Open scene...",
// an `open_scene` action): the window starts again on it with nothing of
// the old scene left (painted target, lights, history), the script's later
// actions apply there, and the recording holds both scenes, so it replays.
// A scene that cannot be read is an input error in a replay.
#include "../support.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/io/lights_json.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace hilight;

TEST_CASE("painter ui: opening another scene starts afresh on it and the recording replays", "[painter-ui][open-scene]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_open_scene");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const fs::path wuson = builders::testmodels_dir() / "OBJ/WusonOBJ.obj";
  REQUIRE(fs::exists(wuson));
  const nlohmann::json actions = {
      {{"type", "brush"}, {"radius", 0.6}, {"colour", 1.0}, {"brightness", 0.6}, {"hardness", 0.7}},
      {{"type", "stroke"}, {"world", {{2.2, 0, 3.0}}}},
      {{"type", "solve"}},
      {{"type", "open_scene"}, {"path", wuson.string()}},
      // The Wuson's opening view looks at it from outside: the window's middle is on it.
      {{"type", "stroke"}, {"screen", {{240, 180}}}},
      {{"type", "solve"}},
      {{"type", "save_lights"}, {"path", (dir / "wuson-lights.json").string()}},
      {{"type", "save_target"}, {"path", (dir / "wuson-target.ply").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const std::vector<std::string> common = {"--size", "480x360", "--set", "bounce_samples=16", "--samples", "800", "--no-cache", "--exit"};
  std::vector<std::string> args = {"paint", room, "--script", (dir / "session.json").string(), "--record", (dir / "recorded.json").string()};
  args.insert(args.end(), common.begin(), common.end());
  const test::RunResult run = test::run_hilight(args);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  // The second solve was the Wuson's: its lights and its painted target are saved.
  const Lighting lights = read_lights_json(dir / "wuson-lights.json");
  REQUIRE_FALSE(lights.empty());
  const std::string target = test::read_file(dir / "wuson-target.ply");
  REQUIRE_FALSE(target.empty());
  // The recording holds both scenes' actions, the open between them.
  const nlohmann::json recorded = nlohmann::json::parse(test::read_file(dir / "recorded.json"));
  std::vector<std::string> types;
  for (const auto& a : recorded["actions"]) types.push_back(a["type"]);
  REQUIRE(std::count(types.begin(), types.end(), "open_scene") == 1);
  CHECK(std::count(types.begin(), types.end(), "solve") == 2);
  // It replays: the same lights again.
  fs::remove(dir / "wuson-lights.json");
  std::vector<std::string> replay = {"paint", room, "--script", (dir / "recorded.json").string(), "--no-record"};
  replay.insert(replay.end(), common.begin(), common.end());
  const test::RunResult again = test::run_hilight(replay);
  INFO(again.err);
  REQUIRE(again.exit_code == 0);
  const Lighting replayed = read_lights_json(dir / "wuson-lights.json");
  REQUIRE(replayed.size() == lights.size());
  for (size_t i = 0; i < lights.size(); ++i) CHECK(glm::length(replayed[i].position - lights[i].position) < 1e-3f);
  // A scene that is not there: in a replay, an input error naming it, one line.
  test::write_text(dir / "missing.json",
                   nlohmann::json{{"actions", {{{"type", "open_scene"}, {"path", (dir / "nowhere.obj").string()}}}}}.dump());
  std::vector<std::string> bad = {"paint", room, "--script", (dir / "missing.json").string(), "--no-record"};
  bad.insert(bad.end(), common.begin(), common.end());
  const test::RunResult missing = test::run_hilight(bad);
  CHECK(missing.exit_code == 2);
  CHECK(test::line_count(missing.err) == 1);
  CHECK_THAT(missing.err, Catch::Contains("nowhere.obj"));
}
