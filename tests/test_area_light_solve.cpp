// Solving with a given area source (`hilight solve --area-light`, and
// `--luminaire FILE --luminaire-size auto`): a target rendered from area
// sources comes back as those sources — position within 1% of the scene's
// size, intensity within 2% (the fixed point of issue 32, item 2).
#include "hilight/io/gltf.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/photometry_io.hpp"
#include "photometry_files.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace hilight;

namespace {

const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
constexpr float kRoomSize = 8.37f;  // its diagonal, m

/// Renders `lights` on the bundled room into a target, then solves it with `extra` options.
Lighting solve_back(const std::string& name, const nlohmann::json& lights, const std::vector<std::string>& extra) {
  const auto dir = test::output_dir("area_light_solve_" + name);
  std::ofstream(dir / "truth.json") << nlohmann::json{{"lights", lights}}.dump();
  const auto target = dir / "target.ply";
  auto r = test::run_hilight({"render", kRoom, "--lights", (dir / "truth.json").string(), "-o", target.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::vector<std::string> args = {"solve", kRoom, "--target", target.string(), "-o", (dir / "found.json").string(), "--no-cache"};
  args.insert(args.end(), extra.begin(), extra.end());
  r = test::run_hilight(args);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return read_lights_json(dir / "found.json");
}

void check_fixed_point(const Lighting& found, LightType type, const Vec3& position, float intensity) {
  REQUIRE(found.size() == 1);
  CHECK(found[0].type == type);
  INFO("found at " << found[0].position.x << ", " << found[0].position.y << ", " << found[0].position.z << ", intensity "
                   << found[0].intensity.r);
  WARN(to_string(type) << ": position off by " << glm::length(found[0].position - position) / kRoomSize
                       << " of the size, intensity by " << found[0].intensity.r / intensity - 1.f);
  CHECK(glm::length(found[0].position - position) < 0.01f * kRoomSize);
  CHECK(found[0].intensity.r == Approx(intensity).epsilon(0.02));
}

} // namespace

TEST_CASE("solve --area-light finds a Lambertian panel's place and intensity", "[area][solve]") {
  const nlohmann::json truth = {{{"type", "rectangle"}, {"position", {2.2, 2.6, 1.8}}, {"direction", {0, -1, 0}}, {"up", {1, 0, 0}},
                                 {"size", {0.6, 0.6}}, {"intensity", {4, 4, 4}}}};
  const Lighting found = solve_back("panel", truth, {"--area-light", "rectangle:0.6x0.6", "--lights", "1"});
  check_fixed_point(found, LightType::Rectangle, {2.2f, 2.6f, 1.8f}, 4.f);
  CHECK(found[0].size == glm::vec2(0.6f, 0.6f));
}

TEST_CASE("solve --area-light line finds a strip's place and intensity", "[area][solve]") {
  const nlohmann::json truth = {{{"type", "line"}, {"position", {3.5, 2.5, 3.0}}, {"direction", {0, -1, 0}}, {"up", {1, 0, 0}},
                                 {"size", {1.2}}, {"intensity", {3, 3, 3}}}};
  const Lighting found = solve_back("strip", truth, {"--area-light", "line:1.2", "--lights", "1"});
  check_fixed_point(found, LightType::Line, {3.5f, 2.5f, 3.f}, 3.f);
}

TEST_CASE("the --luminaire-size auto option takes the luminous opening from the IES file", "[area][photometry]") {
  const auto dir = test::output_dir("area_light_opening");
  // A Lambertian panel file: 0.6 m (length, C0–C180) × 0.3 m (width), metres (units 2).
  std::string text = test::ies_text(test::angles(0, 90, 5), test::angles(0, 0, 1),
                                    [](double, double g) { return 1000.0 * std::cos(g * kPi / 180.0); }, 1, "TILT=NONE", 1, 1, 2000, 24);
  // ies_text writes width 0.1, length 0.2, height 0.05 m: make it a flat 0.3 × 0.6 panel.
  const std::string sizes = " 2 0.1 0.2 0.05\n";
  const size_t at = text.find(sizes);
  REQUIRE(at != std::string::npos);
  text.replace(at, sizes.size(), " 2 0.3 0.6 0\n");
  std::ofstream(dir / "panel.ies") << text;
  const Photometry p = read_photometry(dir / "panel.ies");
  CHECK(p.opening_length == Approx(0.6));
  CHECK(p.opening_width == Approx(0.3));
  CHECK_FALSE(p.opening_round);
  Light lum;
  lum.type = LightType::Luminaire;
  lum.profile = std::make_shared<const Photometry>(p);
  REQUIRE(with_luminous_opening(lum));
  CHECK(lum.type == LightType::Rectangle);
  CHECK(lum.size == glm::vec2(0.6f, 0.3f));
  CHECK(lum.up == Vec3(1.f, 0.f, 0.f));  // C0 of a luminaire aimed down is world +X
  // EULUMDAT: the luminous area's length and width in mm (ldt_text writes 100 for every dimension).
  const Photometry ldt = parse_ldt(test::ldt_text(1, {0}, test::angles(0, 90, 10), {std::vector<double>(10, 100.0)}, 1000), "t.ldt");
  CHECK(ldt.opening_length == Approx(0.1));
  CHECK(ldt.opening_width == Approx(0.1));

  const nlohmann::json truth = {{{"type", "rectangle"}, {"profile", (dir / "panel.ies").string()}, {"position", {3.0, 2.7, 2.5}},
                                 {"direction", {0, -1, 0}}, {"up", {1, 0, 0}}, {"size", {0.6, 0.3}}, {"dimming", 0.7}}};
  const Lighting found = solve_back("opening", truth, {"--luminaire", (dir / "panel.ies").string(), "--luminaire-size", "auto", "--lights", "1"});
  check_fixed_point(found, LightType::Rectangle, {3.f, 2.7f, 2.5f}, float(0.7 * 1000.0 / kCandelaPerWattPerSr));
}
