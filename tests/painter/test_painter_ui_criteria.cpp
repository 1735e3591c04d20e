// The painter takes hilight solve's lux criteria (issue 36 §3): `hilight
// paint SCENE --target C.json --luminaire L` and the criteria options place
// the luminaires as `hilight solve` does with the same options (one function:
// solve/criteria_in_scene.hpp), every bounce unless --bounces says otherwise;
// the recording starts with a `criteria` action, so its replay places the
// same; fine-tune has nothing painted to work on; bad input is one line.
#include "../photometry_files.hpp"
#include "../support.hpp"
#include "hilight/io/lights_file.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace hilight;

namespace {

const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";

/// A 600 × 600 mm panel: Lambertian below, dark above, 3600 lm, 36 W.
fs::path panel(const fs::path& dir) {
  std::string text = test::ies_text(test::angles(0, 90, 5), {0.0}, [](double, double g) {
    return 3600.0 / kPi * std::cos(g * kPi / 180.0);
  }, 1, "TILT=NONE", 1, 1, 3600, 36);
  const std::string opening = "2 0.1 0.2 0.05";
  text.replace(text.find(opening), opening.size(), "2 0.6 0.6 0.0");
  test::write_text(dir / "panel.ies", text);
  return dir / "panel.ies";
}

/// The criteria options both commands are given.
const std::vector<std::string> kOptions = {"--margin", "0.05", "--ugr-max", "22", "--set", "bounce_samples=32"};

std::vector<std::string> paint_args(const fs::path& dir, const fs::path& script, std::vector<std::string> more) {
  std::vector<std::string> args = {"paint", kRoom, "--luminaire", (dir / "panel.ies").string(), "--size", "480x360", "--exit",
                                   "--script", script.string()};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

std::string lights_text(const fs::path& path) { return nlohmann::json::parse(test::read_file(path)).dump(); }

/// One line on stderr, an error, saying `what`.
bool one_error_line(const std::string& err, const std::string& what) {
  return test::line_count(err) == 1 && err.rfind("hilight: error: ", 0) == 0 && err.find(what) != std::string::npos;
}

} // namespace

TEST_CASE("painter ui: --target criteria.json places the luminaires as hilight solve does, and its recording replays them",
          "[painter-ui][painter-criteria]") {
  if (test::skip_without_display()) return;
  // Each command's own defaults: every bounce for criteria in both, no --place.
  const test::CliOwnBounces own_bounces;
  const test::CliOwnPlacement own_placement;
  const fs::path dir = test::output_dir("painter_ui_criteria");
  panel(dir);
  const fs::path criteria = dir / "desks.json";
  REQUIRE(test::run_hilight({"target", "workplane", kRoom, "-o", criteria.string(), "--lux", "500", "--u0", "0.6"}).exit_code == 0);

  std::vector<std::string> cli = {"solve", kRoom, "--target", criteria.string(), "--luminaire", (dir / "panel.ies").string(), "-o",
                                  (dir / "cli.json").string()};
  cli.insert(cli.end(), kOptions.begin(), kOptions.end());
  const test::RunResult solved = test::run_hilight(cli);
  INFO(solved.err);
  REQUIRE(solved.exit_code == 0);

  const nlohmann::json actions = {{{"type", "solve"}}, {{"type", "save_lights"}, {"path", (dir / "painter.json").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  std::vector<std::string> more = {"--target", criteria.string(), "--record", (dir / "recorded.json").string()};
  more.insert(more.end(), kOptions.begin(), kOptions.end());
  const test::RunResult painted = test::run_hilight(paint_args(dir, dir / "session.json", more));
  INFO(painted.err);
  REQUIRE(painted.exit_code == 0);
  // The same luminaires, places and dimming, to the digit: one code path.
  const Lighting cli_lights = read_lights_file(dir / "cli.json"), painter_lights = read_lights_file(dir / "painter.json");
  REQUIRE(cli_lights.size() >= 2);
  CHECK(lights_text(dir / "painter.json") == lights_text(dir / "cli.json"));
  // The window says what hilight solve says of the grid.
  CHECK(painted.err.find("workplane: maintained Ē") != std::string::npos);
  CHECK(painted.err.find("criteria met") != std::string::npos);

  // The recording starts with the criteria and their options; replayed with
  // the luminaire alone, it places the same luminaires.
  const nlohmann::json recorded = nlohmann::json::parse(test::read_file(dir / "recorded.json"));
  REQUIRE(recorded["actions"].size() >= 2);
  const nlohmann::json& first = recorded["actions"][0];
  CHECK(first["type"] == "criteria");
  CHECK(fs::path(first["path"].get<std::string>()) == fs::absolute(criteria).lexically_normal());
  CHECK(first["margin"].get<double>() == 0.05);
  CHECK(first["ugr_max"].get<double>() == 22.0);
  fs::remove(dir / "painter.json");
  const test::RunResult replayed = test::run_hilight(paint_args(dir, dir / "recorded.json", {"--no-record", "--bounces", "all", "--set", "bounce_samples=32"}));
  INFO(replayed.err);
  REQUIRE(replayed.exit_code == 0);
  CHECK(lights_text(dir / "painter.json") == lights_text(dir / "cli.json"));
}

TEST_CASE("painter ui: lux criteria without a luminaire, criteria options without criteria, and a fine-tune of criteria are refused in one line",
          "[painter-ui][painter-criteria]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_criteria_bad");
  panel(dir);
  const fs::path criteria = dir / "desks.json";
  REQUIRE(test::run_hilight({"target", "workplane", kRoom, "-o", criteria.string()}).exit_code == 0);
  test::write_text(dir / "solve.json", R"({"actions": [{"type": "solve"}]})");
  test::write_text(dir / "fine_tune.json", R"({"actions": [{"type": "fine_tune"}]})");

  const test::RunResult no_luminaire =
      test::run_hilight({"paint", kRoom, "--target", criteria.string(), "--exit", "--no-record", "--script", (dir / "solve.json").string()});
  CHECK(no_luminaire.exit_code == 2);
  CHECK(one_error_line(no_luminaire.err, "desks.json: illuminance criteria need --luminaire"));

  const test::RunResult painted_margin = test::run_hilight(paint_args(dir, dir / "solve.json", {"--no-record", "--margin", "0.1", "--place", "ceiling:0.2"}));
  CHECK(painted_margin.exit_code == 2);
  CHECK(one_error_line(painted_margin.err, "--margin works with illuminance criteria"));

  const test::RunResult fine_tune =
      test::run_hilight(paint_args(dir, dir / "fine_tune.json", {"--no-record", "--target", criteria.string(), "--place", "ceiling:0.2"}));
  CHECK(fine_tune.exit_code == 2);
  CHECK(one_error_line(fine_tune.err, "fine-tune works on painted targets"));

  test::write_text(dir / "bad_layout.json",
                   nlohmann::json{{"actions", {{{"type", "criteria"}, {"path", criteria.string()}, {"layout", "hexagonal"}}}}}.dump());
  const test::RunResult bad_layout = test::run_hilight(paint_args(dir, dir / "bad_layout.json", {"--no-record", "--place", "ceiling:0.2"}));
  CHECK(bad_layout.exit_code == 2);
  CHECK(one_error_line(bad_layout.err, "criteria: 'layout' must be auto, array or free"));
}
