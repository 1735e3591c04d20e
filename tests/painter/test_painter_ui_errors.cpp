// The painter fails cleanly: one `hilight: error:` line and a non-zero exit,
// no crash, when there is no display, no OpenGL 3.3, bad geometry or a bad
// session script.
#include "../support.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";

/// Sets (or, with nullopt, removes) an environment variable for one scope:
/// the launcher child inherits the test's environment.
class ScopedEnv {
public:
  ScopedEnv(const char* name, std::optional<std::string> value) : m_name(name) {
    if (const char* old = std::getenv(name)) m_old = old;
    if (value) ::setenv(name, value->c_str(), 1);
    else ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (m_old) ::setenv(m_name, m_old->c_str(), 1);
    else ::unsetenv(m_name);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
  const char* m_name;
  std::optional<std::string> m_old;
};

void check_one_line_error(const test::RunResult& r, const std::string& mentions) {
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, StartsWith("hilight: error: "));
  CHECK_THAT(r.err, Contains(mentions));
}

} // namespace

TEST_CASE("painter ui: no display gives one clear error line", "[painter-ui]") {
  ScopedEnv no_x("DISPLAY", std::nullopt);
  ScopedEnv no_wayland("WAYLAND_DISPLAY", std::nullopt);
  check_one_line_error(test::run_hilight({"paint", kRoom, "--no-record"}), "no display");
  // A display name that leads nowhere.
  ScopedEnv nowhere("DISPLAY", std::string(":987"));
  check_one_line_error(test::run_hilight({"paint", kRoom, "--no-record"}), "cannot open the display ':987'");
}

TEST_CASE("painter ui: no OpenGL 3.3 core context gives one clear error line", "[painter-ui]") {
  if (test::skip_without_display()) return;
  // Mesa can be told to offer OpenGL 2.1 only: the 3.3 core context is then refused.
  ScopedEnv old_gl("MESA_GL_VERSION_OVERRIDE", std::string("2.1"));
  const fs::path dir = test::output_dir("painter_ui_no_gl");
  test::write_text(dir / "empty.json", R"({"actions": []})");
  const test::RunResult r = test::run_hilight({"paint", kRoom, "--script", (dir / "empty.json").string(), "--exit", "--no-record"});
  if (r.exit_code == 0) {
    std::cout << "SKIPPED: this OpenGL is not Mesa's (it ignores MESA_GL_VERSION_OVERRIDE)" << std::endl;
    return;
  }
  check_one_line_error(r, "no OpenGL 3.3 core context");
}

TEST_CASE("painter ui: bad geometry and bad scripts give one clear error line", "[painter-ui]") {
  const fs::path dir = test::output_dir("painter_ui_bad_input");
  test::write_text(dir / "nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  check_one_line_error(test::run_hilight({"paint", (dir / "nan.obj").string(), "--no-record"}), "nan.obj");
  check_one_line_error(test::run_hilight({"paint", (dir / "missing.obj").string(), "--no-record"}), "missing.obj");

  test::write_text(dir / "not_json.json", "{\"actions\": [");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--script", (dir / "not_json.json").string(), "--exit"}),
                       "not_json.json: not valid JSON");
  test::write_text(dir / "bad_action.json", R"({"actions": [{"type": "brush", "radius": 0.2}, {"type": "stroke"}]})");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--script", (dir / "bad_action.json").string(), "--exit"}),
                       "bad_action.json: action 1: stroke: needs exactly one of world, screen");
  test::write_text(dir / "unknown.json", R"({"actions": [{"type": "teleport"}]})");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--script", (dir / "unknown.json").string(), "--exit"}),
                       "unknown type 'teleport'");
  test::write_text(dir / "lights.json", R"({"lamps": []})");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--lights", (dir / "lights.json").string(), "--no-record"}), "lights.json");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--target", (dir / "none.ply").string(), "--no-record"}), "none.ply");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--size", "10x10"}), "--size");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--renderer", "nosuch"}), "nosuch");
}

TEST_CASE("painter ui: a script action that fails names the action", "[painter-ui]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_failing_action");
  // Valid JSON, but fine-tune needs lights and there are none.
  test::write_text(dir / "fine_tune.json", R"({"actions": [{"type": "fine_tune"}]})");
  check_one_line_error(
      test::run_hilight({"paint", kRoom, "--script", (dir / "fine_tune.json").string(), "--exit", "--no-record", "--size", "320x240"}),
      "action 0 (fine_tune)");
  // A screen point that hits nothing: the room opens seen from inside, so the camera first looks away from it.
  test::write_text(dir / "miss.json", R"({"actions": [{"type": "camera", "eye": [20, 20, 20], "target": [40, 40, 40], "fov": 50},
                                                     {"type": "erase_shadow", "screen": [2, 2]}]})");
  check_one_line_error(
      test::run_hilight({"paint", kRoom, "--script", (dir / "miss.json").string(), "--exit", "--no-record", "--size", "320x240"}),
      "nothing under the screen point");
}

TEST_CASE("painter ui: huge coordinates are input errors, never a crash in the ray tracer", "[painter-ui]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_huge_coordinates");
  auto run = [&](const std::string& name, const std::string& script) {
    test::write_text(dir / name, script);
    return test::run_hilight({"paint", kRoom, "--script", (dir / name).string(), "--exit", "--no-record", "--size", "320x240"});
  };
  // inf as a float: refused when the script is read.
  check_one_line_error(run("pan_inf.json", R"({"actions": [{"type": "camera", "pan": [1e300, 0]}]})"), "pan_inf.json: action 0: camera: 'pan'");
  check_one_line_error(run("eye.json", R"({"actions": [{"type": "camera", "eye": [1e19, 1e19, 1e19], "target": [0, 0, 0]},
                                                       {"type": "stroke", "screen": [[160, 120]]}]})"),
                       "eye.json: action 0 (camera): camera: eye");
  check_one_line_error(run("spot.json", R"({"actions": [{"type": "spot_region", "world": [[0, 0, 0]], "eye": [1e30, 2, 1], "direction": [-1, 0, 0]}]})"),
                       "spot.json: action 0 (spot_region): spot_region: eye");
  // Finite as a float: the camera stays near the scene, whatever the pan.
  const test::RunResult far_pan = run("pan_far.json", R"({"actions": [{"type": "camera", "pan": [1e30, 0]}, {"type": "camera", "zoom": 1e30},
                                                                    {"type": "stroke", "screen": [[160, 120]]}]})");
  INFO(far_pan.err);
  CHECK((far_pan.exit_code == 0 || far_pan.exit_code == 2));
  if (far_pan.exit_code == 2) check_one_line_error(far_pan, "pan_far.json: action 2 (stroke)");
}

TEST_CASE("painter ui: output paths are checked before anything runs", "[painter-ui]") {
  const fs::path dir = test::output_dir("painter_ui_output_paths");
  test::write_text(dir / "save.json", R"({"actions": [{"type": "save_lights", "path": ")" + (dir / "lights.json").string() + R"("}]})");
  const std::string script = (dir / "save.json").string();
  check_one_line_error(test::run_hilight({"paint", kRoom, "--script", script, "--exit", "--no-record", "--screenshot", (dir / "shot.bmp").string()}),
                       "--screenshot: unknown image type");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--script", script, "--exit", "--no-record", "--window-screenshot",
                                          (dir / "no" / "shot.png").string()}),
                       "shot.png");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--script", script, "--exit", "--no-record", "--timings",
                                          (dir / "no" / "timings.json").string()}),
                       "timings.json");
  // An unwritable --record is an input error up front, not a warning and exit 0.
  check_one_line_error(test::run_hilight({"paint", kRoom, "--script", script, "--exit", "--record", (dir / "no" / "session.json").string()}),
                       "session.json");
  check_one_line_error(test::run_hilight({"paint", kRoom, "--record", dir.string()}), dir.string());
  // None of them ran the script's save.
  CHECK_FALSE(fs::exists(dir / "lights.json"));
}

TEST_CASE("painter ui: no Vulkan device gives one clean error line", "[painter-ui]") {
  const test::RunResult r = test::run_hilight({"paint", kRoom, "--renderer", "ism-vulkan", "--no-record"}, {{"VK_ICD_FILENAMES", "/nonexistent"},
                                                                                                            {"VK_DRIVER_FILES", "/nonexistent"}});
  check_one_line_error(r, "ism-vulkan");
}
