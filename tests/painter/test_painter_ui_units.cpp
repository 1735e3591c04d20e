// The painter takes hilight solve's --luminaire and --units (issue 36 §3):
// with a downlight's IES file every solved light is that luminaire, and with
// --units photometric the lights file is in candela (and says so) and the
// saved target in cd/m², as `hilight solve --units photometric` reads them.
#include "../photometry_files.hpp"
#include "../support.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/units.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
using namespace hilight;

TEST_CASE("painter ui: --luminaire makes every light that luminaire, --units photometric writes candela and cd/m2", "[painter-ui][painter-units]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_units");
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  // A downlight: Lambertian below, dark above, 1200 lm.
  test::write_text(dir / "down.ies", test::ies_text(test::angles(0, 90, 5), {0.0}, [](double, double g) {
                     return 1200.0 / kPi * std::cos(g * kPi / 180.0);
                   }, 1, "TILT=NONE", 1, 1, 1200, 12));
  const nlohmann::json actions = {
      {{"type", "brush"}, {"radius", 0.8}, {"colour", 1.0}, {"brightness", 0.2}, {"hardness", 0.7}},
      {{"type", "stroke"}, {"world", {{2.0, 0.0, 3.5}}}},
      {{"type", "stroke"}, {"world", {{4.5, 0.0, 1.5}}}},
      {{"type", "solve"}},
      {{"type", "save_lights"}, {"path", (dir / "lights.json").string()}},
      {{"type", "save_target"}, {"path", (dir / "target.ply").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", room, "--luminaire", (dir / "down.ies").string(), "--units", "photometric",
                                                 "--place", "ceiling:0.1", "--size", "480x360", "--set", "bounce_samples=16", "--samples",
                                                 "800", "--no-cache", "--no-record", "--exit", "--script", (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const nlohmann::json file = nlohmann::json::parse(test::read_file(dir / "lights.json"));
  CHECK(file["intensity_unit"] == "cd");
  REQUIRE_FALSE(file["lights"].empty());
  for (const auto& l : file["lights"]) {
    CHECK(l["type"] == "luminaire");
    CHECK(l["profile"].get<std::string>().find("down.ies") != std::string::npos);
  }
  // The paint's brightness 0.2 W/(sr m²) (its luminance, lamp colour) is 0.2 × 683 cd/m² in the file.
  double brightest = 0;
  for (const Rgb& c : test::ply_colours(dir / "target.ply")) brightest = std::max(brightest, luminance(c));
  CHECK(brightest == Approx(0.2 * kLumensPerWatt).epsilon(0.01));
  // hilight solve reads both back in the same units: the painter's lights fit its target.
  const test::RunResult cli = test::run_hilight({"solve", room, "--target", (dir / "target.ply").string(), "--units", "photometric",
                                                 "--luminaire", (dir / "down.ies").string(), "--place", "ceiling:0.1", "--mode", "fine-tune",
                                                 "--initial", (dir / "lights.json").string(), "--set", "bounce_samples=16", "--samples", "800",
                                                 "--no-cache", "-o", (dir / "tuned.json").string(), "--report", (dir / "report.json").string()});
  INFO(cli.err);
  REQUIRE(cli.exit_code == 0);
  const nlohmann::json report = nlohmann::json::parse(test::read_file(dir / "report.json"));
  CHECK(report["dbar"].get<double>() < 0.15);  // measured 7.2%
}
