// A painter that explains (issue 36 §3): a poor fit says why in the window,
// in hilight solve's words, and the painted points no allowed place can see
// are striped magenta in the view. The bundled room, lights held on the
// ceiling: the underside of the table is painted bright, and no ceiling lamp
// can see it. With HILIGHT_UPDATE_DOC_IMAGES=1 the window's screenshot is
// copied to docs/images/ for docs/painter.md.
#include "../support.hpp"
#include "hilight/io/image_io.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <regex>

namespace fs = std::filesystem;
using namespace hilight;

namespace {

/// The share the unreachable warning names ("35% of the target's light ..."); -1 if none.
int unreachable_percent(const std::string& err) {
  std::smatch m;
  static const std::regex said("poor fit, [^\\n]*: ([0-9]+)% of the target's light is on points that no place a light may stand can see");
  return std::regex_search(err, m, said) ? std::stoi(m[1]) : -1;
}

/// Pixels of the magenta stripes (display (1, 0.1, 0.85) in sRGB: 255, 89, 239).
size_t magenta_pixels(const fs::path& png) {
  const PngPixels image = read_png(png);
  size_t n = 0;
  for (size_t i = 0; i < size_t(image.width) * size_t(image.height); ++i) {
    const int r = image.rgb[3 * i], g = image.rgb[3 * i + 1], b = image.rgb[3 * i + 2];
    n += r > 230 && g > 60 && g < 120 && b > 215;
  }
  return n;
}

} // namespace

TEST_CASE("painter ui: a poor fit says why in the window and stripes the painted points no light may reach", "[painter-ui][diagnosis]") {
  if (test::skip_without_display()) return;
  test::CliOwnPlacement own;  // the rules are the session's: lights on the ceiling
  const fs::path dir = test::output_dir("painter_ui_diagnosis");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const nlohmann::json actions = {
      // From low beside the table, looking at its underside.
      {{"type", "camera"}, {"eye", {2.0, 0.2, 3.9}}, {"target", {2.0, 0.7, 1.9}}, {"fov", 70}},
      {{"type", "brush"}, {"radius", 0.6}, {"colour", 1.0}, {"brightness", 2.0}, {"hardness", 1.0}},
      {{"type", "stroke"}, {"world", {{2.0, 0.72, 1.9}}}, {"normals", {{0.0, -1.0, 0.0}}}},
      {{"type", "brush"}, {"radius", 0.7}, {"brightness", 0.5}},
      {{"type", "stroke"}, {"world", {{4.5, 0.0, 1.5}}}},
      {{"type", "place"}, {"rules", "ceiling:0.2"}},
      {{"type", "solve"}},
      {{"type", "save_target"}, {"path", (dir / "target.ply").string()}},
      // A fine-tune's answer is diagnosed too (the solve's own look covers only solves).
      {{"type", "stroke"}, {"world", {{4.0, 0.0, 2.0}}}},
      {{"type", "fine_tune"}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run =
      test::run_hilight({"paint", room, "--size", "1100x820", "--set", "bounce_samples=16", "--samples", "800", "--no-cache", "--no-record",
                         "--exit", "--script", (dir / "session.json").string(), "--screenshot", (dir / "view.png").string(),
                         "--window-screenshot", (dir / "window.png").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  // The window's log (stderr in a replay) says what hilight solve says.
  const int painter_share = unreachable_percent(run.err);
  CHECK(painter_share >= 10);
  size_t warnings = 0;
  for (size_t at = 0; (at = run.err.find("hilight: warning: poor fit", at)) != std::string::npos; ++at) ++warnings;
  CHECK(warnings == 2);  // the solve's and the fine-tune's
  // The underside shows striped in the view, and the panels say what the stripes are.
  const size_t striped = magenta_pixels(dir / "view.png");
  INFO("magenta pixels " << striped);
  CHECK(striped > 500);
  CHECK(magenta_pixels(dir / "window.png") > 200);  // the panels cover part of the view
  // The same target solved by hilight solve under the same rule: the same reason, the same share.
  const test::RunResult cli = test::run_hilight({"solve", room, "--target", (dir / "target.ply").string(), "--place", "ceiling:0.2",
                                                 "--set", "bounce_samples=16", "--samples", "800", "--no-cache", "-o",
                                                 (dir / "lights.json").string()});
  INFO(cli.err);
  REQUIRE(cli.exit_code == 0);
  CHECK(unreachable_percent(cli.err) == painter_share);
  if (const char* update = std::getenv("HILIGHT_UPDATE_DOC_IMAGES"); update && std::string(update) == "1")
    fs::copy_file(dir / "window.png", fs::path(HILIGHT_SOURCE_DIR) / "docs/images/painter-poor-fit.png", fs::copy_options::overwrite_existing);
}
