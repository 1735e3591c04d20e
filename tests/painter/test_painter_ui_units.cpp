// The painter takes hilight solve's --luminaire and --units (issue 36 §3):
// with a downlight's IES file every solved light is that luminaire; with
// --units photometric the brush paints cd/m² (lux with --target-quantity
// illuminance), the lights file is in candela (and says so) and the saved
// target in the painted unit, as `hilight solve` with the same options reads them.
#include "../photometry_files.hpp"
#include "../support.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/units.hpp"
#include "core/session.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fs = std::filesystem;
using namespace hilight;

namespace {

const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";

/// A downlight: Lambertian below, dark above, 1200 lm.
fs::path downlight(const fs::path& dir) {
  test::write_text(dir / "down.ies", test::ies_text(test::angles(0, 90, 5), {0.0}, [](double, double g) {
                     return 1200.0 / kPi * std::cos(g * kPi / 180.0);
                   }, 1, "TILT=NONE", 1, 1, 1200, 12));
  return dir / "down.ies";
}

/// Paints two floor patches of `brightness` (in the units given), solves with
/// the downlight on the ceiling, saves dir/lights.json and dir/target.ply.
/// With `record`, the session is recorded there.
test::RunResult paint_and_solve(const fs::path& dir, double brightness, const std::vector<std::string>& units,
                                const fs::path& record = {}) {
  const nlohmann::json actions = {
      {{"type", "brush"}, {"radius", 0.8}, {"colour", 1.0}, {"brightness", brightness}, {"hardness", 0.7}},
      {{"type", "stroke"}, {"world", {{2.0, 0.0, 3.5}}}},
      {{"type", "stroke"}, {"world", {{4.5, 0.0, 1.5}}}},
      {{"type", "solve"}},
      {{"type", "save_lights"}, {"path", (dir / "lights.json").string()}},
      {{"type", "save_target"}, {"path", (dir / "target.ply").string()}}};
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  std::vector<std::string> args = {"paint", kRoom, "--luminaire", downlight(dir).string(), "--place", "ceiling:0.1", "--size", "480x360",
                                   "--set", "bounce_samples=16", "--samples", "800", "--no-cache", "--exit", "--script",
                                   (dir / "session.json").string()};
  if (record.empty()) args.push_back("--no-record");
  else args.insert(args.end(), {"--record", record.string()});
  args.insert(args.end(), units.begin(), units.end());
  return test::run_hilight(args);
}

/// D̄ of the painter's lights on its saved target, as hilight solve reads both with `units`.
double cli_dbar(const fs::path& dir, const std::vector<std::string>& units) {
  std::vector<std::string> args = {"solve", kRoom, "--target", (dir / "target.ply").string(), "--luminaire", (dir / "down.ies").string(),
                                   "--place", "ceiling:0.1", "--mode", "fine-tune", "--initial", (dir / "lights.json").string(), "--set",
                                   "bounce_samples=16", "--samples", "800", "--no-cache", "-o", (dir / "tuned.json").string(), "--report",
                                   (dir / "report.json").string()};
  args.insert(args.end(), units.begin(), units.end());
  const test::RunResult cli = test::run_hilight(args);
  INFO(cli.err);
  REQUIRE(cli.exit_code == 0);
  return nlohmann::json::parse(test::read_file(dir / "report.json"))["dbar"].get<double>();
}

double brightest_luminance(const fs::path& ply) {
  double brightest = 0;
  for (const Rgb& c : test::ply_colours(ply)) brightest = std::max(brightest, luminance(c));
  return brightest;
}

} // namespace

TEST_CASE("painter ui: --luminaire makes every light that luminaire, --units photometric paints and writes candela and cd/m2",
          "[painter-ui][painter-units]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_units");
  const std::vector<std::string> units = {"--units", "photometric"};
  const test::RunResult run = paint_and_solve(dir, 140.0, units);  // cd/m²
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const nlohmann::json file = nlohmann::json::parse(test::read_file(dir / "lights.json"));
  CHECK(file["intensity_unit"] == "cd");
  REQUIRE_FALSE(file["lights"].empty());
  for (const auto& l : file["lights"]) {
    CHECK(l["type"] == "luminaire");
    CHECK(l["profile"].get<std::string>().find("down.ies") != std::string::npos);
  }
  // The paint's 140 cd/m² (its luminance, lamp colour) is what the file holds.
  CHECK(brightest_luminance(dir / "target.ply") == Approx(140.0).epsilon(0.01));
  // hilight solve reads both back in the same units: the painter's lights fit its target.
  CHECK(cli_dbar(dir, units) < 0.15);  // measured 7.2%
}

TEST_CASE("painter ui: with --target-quantity illuminance the brush paints lux, and hilight solve reads the target as lux",
          "[painter-ui][painter-units]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_lux");
  const std::vector<std::string> units = {"--units", "photometric", "--target-quantity", "illuminance"};
  const test::RunResult run = paint_and_solve(dir, 300.0, units);  // lux on the floor
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(brightest_luminance(dir / "target.ply") == Approx(300.0).epsilon(0.01));
  CHECK(cli_dbar(dir, units) < 0.15);
}

TEST_CASE("painter ui: a session started in lux records its units first, and its replay without them paints lux and writes candela",
          "[painter-ui][painter-units][painter-session]") {
  if (test::skip_without_display()) return;
  const fs::path dir = test::output_dir("painter_ui_units_recorded");
  const std::vector<std::string> units = {"--units", "photometric", "--target-quantity", "illuminance"};
  const test::RunResult run = paint_and_solve(dir, 300.0, units, dir / "recorded.json");
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const nlohmann::json recorded = nlohmann::json::parse(test::read_file(dir / "recorded.json"));
  REQUIRE_FALSE(recorded["actions"].empty());
  CHECK(recorded["actions"][0] == nlohmann::json::parse(R"({"type": "units", "units": "photometric", "quantity": "illuminance"})"));
  const nlohmann::json first = nlohmann::json::parse(test::read_file(dir / "lights.json"));
  const std::vector<Rgb> first_target = test::ply_colours(dir / "target.ply");
  fs::remove(dir / "lights.json");
  fs::remove(dir / "target.ply");
  // Replayed with none of the unit options: the script's own say what its numbers mean.
  const test::RunResult replay = test::run_hilight({"paint", kRoom, "--luminaire", (dir / "down.ies").string(), "--place", "ceiling:0.1",
                                                    "--size", "480x360", "--set", "bounce_samples=16", "--samples", "800", "--no-cache",
                                                    "--no-record", "--exit", "--script", (dir / "recorded.json").string()});
  INFO(replay.err);
  REQUIRE(replay.exit_code == 0);
  const nlohmann::json again = nlohmann::json::parse(test::read_file(dir / "lights.json"));
  CHECK(again["intensity_unit"] == "cd");
  REQUIRE(again["lights"].size() == first["lights"].size());
  for (size_t j = 0; j < first["lights"].size(); ++j)
    for (int k = 0; k < 3; ++k) {  // the same candela: a replay in W/sr would be 683 times less
      CHECK(again["lights"][j]["intensity"][k].get<double>() == Approx(first["lights"][j]["intensity"][k].get<double>()).epsilon(1e-4));
      CHECK(again["lights"][j]["position"][k].get<double>() == Approx(first["lights"][j]["position"][k].get<double>()).margin(1e-4));
    }
  const std::vector<Rgb> replayed_target = test::ply_colours(dir / "target.ply");
  REQUIRE(replayed_target.size() == first_target.size());
  size_t differ = 0;  // lux again, painted and written alike
  for (size_t i = 0; i < first_target.size(); ++i) differ += std::abs(luminance(replayed_target[i]) - luminance(first_target[i])) > 1e-3;
  CHECK(differ == 0);
  CHECK(brightest_luminance(dir / "target.ply") == Approx(300.0).epsilon(0.01));
}

TEST_CASE("painter session: a units action with a bad unit or lux without photometric is refused, naming the script",
          "[painter][painter-session][bad-input]") {
  using hilight::painter::Action;
  CHECK_THROWS_WITH(hilight::painter::validate_action(Action{"units", {{"units", "lumens"}}}, "s.json", 0),
                    Catch::Contains("s.json: action 0: units: 'units' must be radiometric or photometric"));
  CHECK_THROWS_WITH(hilight::painter::validate_action(Action{"units", {{"units", "radiometric"}, {"quantity", "illuminance"}}}, "s.json", 2),
                    Catch::Contains("s.json: action 2: units: illuminance is in lux"));
}

// hilight solve's --unit (the scene file's length unit) in the painter: the
// bundled room written in millimetres and read with --unit mm is the metre
// room, so the same strokes (the script's points are in the painter's own
// metres) solve to the same lights, their positions in millimetres and their
// intensities the same (W/sr: at 1000× the distance read as metres they
// would be 10⁶ times stronger).
TEST_CASE("painter ui: --unit mm reads a millimetre room as the metre room: the same lights, positions in millimetres",
          "[painter-ui][painter-units]") {
  if (test::skip_without_display()) return;
  const test::CliOwnPlacement own_placement;  // each run's own --place, in its file's unit
  const fs::path dir = test::output_dir("painter_ui_length_unit");
  // The room in millimetres: every vertex × 1000, the same materials.
  std::istringstream in(test::read_file(kRoom));
  std::ostringstream mm;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("v ", 0) == 0) {
      std::istringstream v(line.substr(2));
      double x = 0, y = 0, z = 0;
      v >> x >> y >> z;
      mm << "v " << 1000 * x << ' ' << 1000 * y << ' ' << 1000 * z << '\n';
    } else {
      mm << line << '\n';
    }
  }
  test::write_text(dir / "room.obj", mm.str());
  fs::copy_file(fs::path(kRoom).replace_extension(".mtl"), dir / "room.mtl", fs::copy_options::overwrite_existing);

  auto paint = [&](const std::string& scene, const std::string& lights, std::vector<std::string> more) {
    const nlohmann::json actions = {{{"type", "brush"}, {"radius", 0.8}, {"colour", 1.0}, {"brightness", 0.05}},
                                    {{"type", "stroke"}, {"world", {{2.0, 0.0, 3.5}, {2.6, 0.0, 3.5}}}},
                                    {{"type", "stroke"}, {"world", {{4.5, 0.0, 1.5}}}},
                                    {{"type", "solve"}},
                                    {{"type", "save_lights"}, {"path", (dir / lights).string()}}};
    test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
    std::vector<std::string> args = {"paint", scene, "--size", "480x360", "--set", "bounce_samples=16", "--samples", "800", "--no-cache",
                                     "--no-record", "--exit", "--script", (dir / "session.json").string()};
    args.insert(args.end(), more.begin(), more.end());
    const test::RunResult r = test::run_hilight(args);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(test::read_file(dir / lights));
  };
  const nlohmann::json metres = paint(kRoom, "m.json", {"--place", "ceiling:0.2"});
  const nlohmann::json millimetres = paint((dir / "room.obj").string(), "mm.json", {"--unit", "mm", "--place", "ceiling:200"});
  CHECK(metres["length_unit"] == "m");
  CHECK(millimetres["length_unit"] == "mm");
  REQUIRE(metres["lights"].size() >= 1);
  REQUIRE(millimetres["lights"].size() == metres["lights"].size());
  for (size_t j = 0; j < metres["lights"].size(); ++j)
    for (int k = 0; k < 3; ++k) {
      INFO("light " << j << ", axis " << k);
      // The file's own decimals: the millimetre room's vertices are not the metre room's × 1000 to the bit.
      CHECK(millimetres["lights"][j]["position"][k].get<double>() ==
            Approx(1000 * metres["lights"][j]["position"][k].get<double>()).margin(5.0));
      CHECK(millimetres["lights"][j]["intensity"][k].get<double>() ==
            Approx(metres["lights"][j]["intensity"][k].get<double>()).epsilon(0.02));
    }
}
