// The `view` action (issue 12): a replayed session shows the result, the
// target and their difference, so scripted screenshots can show each; the
// keys 1/2/3 record it. A view that does not exist is an input error.
#include "../support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

TEST_CASE("painter ui: view actions switch what screenshots show (result, target, difference)", "[painter-ui][view]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_view");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  nlohmann::json actions = {
      {{"type", "camera"}, {"eye", {3.0, 6.0, 9.0}}, {"target", {3.0, 0.0, 2.5}}, {"fov", 60}},
      {{"type", "brush"}, {"radius", 0.8}, {"colour", 1.0}, {"brightness", 0.8}, {"hardness", 0.7}},
      {{"type", "stroke"}, {"world", {{2.2, 0, 3.0}}}},
      {{"type", "solve"}}};
  for (const char* show : {"result", "target", "difference"}) {
    actions.push_back({{"type", "view"}, {"show", show}});
    actions.push_back({{"type", "screenshot"}, {"path", (dir / (std::string(show) + ".png")).string()}});
  }
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", room, "--size", "320x240", "--set", "bounce_samples=16", "--samples", "800",
                                                 "--no-cache", "--no-record", "--exit", "--script", (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const std::string result = test::read_file(dir / "result.png"), target = test::read_file(dir / "target.png"),
                    difference = test::read_file(dir / "difference.png");
  REQUIRE(!result.empty());
  CHECK(result != target);
  CHECK(result != difference);
  CHECK(target != difference);

  test::write_text(dir / "bad.json", nlohmann::json{{"actions", {{{"type", "view"}, {"show", "wireframe"}}}}}.dump());
  const test::RunResult bad = test::run_hilight({"paint", room, "--size", "320x240", "--no-record", "--exit", "--script", (dir / "bad.json").string()});
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
  CHECK(bad.err.find("wireframe") != std::string::npos);
}
