// Radiometric and photometric units (issue 13): candela and cd/m² are 683 ×
// W/sr and W/(sr·m²); lux on a surface is π·L/ρ; lumens integrate a light's
// cone. Round trips between the two systems through render and solve.
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply.hpp"
#include "hilight/io/ply_reader.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/units.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace hilight;

namespace {

const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";


double report_value(const std::filesystem::path& p, const char* key) {
  std::ifstream in(p);
  return nlohmann::json::parse(in)[key].get<double>();
}

} // namespace

TEST_CASE("luminous flux: 4π sr for a point light, the cone for a spot, 683 lm/W, Rec. 709 luminance", "[units]") {
  CHECK(luminous_flux(Light::point({0, 0, 0}, Rgb(1.f))) == Approx(683.0 * 4.0 * kPi));
  CHECK(luminous_flux(Light::point({0, 0, 0}, Rgb(0.f, 1.f, 0.f))) == Approx(683.0 * 4.0 * kPi * 0.7152));
  CHECK(luminous_flux(Light::spot({0, 0, 0}, {0, -1, 0}, 60.f, Rgb(1.f))) == Approx(683.0 * 2.0 * kPi * 0.5));
  // A soft edge counts half: between the hard cones of its inner and outer angles.
  const double soft = luminous_flux(Light::spot({0, 0, 0}, {0, -1, 0}, 60.f, Rgb(1.f), 20.f));
  CHECK(soft > luminous_flux(Light::spot({0, 0, 0}, {0, -1, 0}, 40.f, Rgb(1.f))));
  CHECK(soft < luminous_flux(Light::spot({0, 0, 0}, {0, -1, 0}, 60.f, Rgb(1.f))));
}

TEST_CASE("render and solve give the same light in photometric units as in radiometric ones", "[units][cli]") {
  const auto dir = test::output_dir("units");
  const Lighting truth = {Light::point({1.5f, 2.5f, 1.1f}, Rgb(2.f)), Light::point({4.6f, 2.4f, 1.4f}, Rgb(2.f, 1.9f, 1.7f))};
  write_lights_json(dir / "w.json", truth);
  write_lights_json(dir / "cd.json", lights_to_units(truth, Units::Photometric), "m", nullptr, "cd");
  REQUIRE(test::run_hilight({"render", kRoom, "--lights", (dir / "w.json").string(), "-o", (dir / "w.ply").string()}).exit_code == 0);
  REQUIRE(test::run_hilight({"render", kRoom, "--lights", (dir / "cd.json").string(), "-o", (dir / "cd.ply").string(), "--units",
                             "photometric"}).exit_code == 0);
  const auto radiance = test::ply_colours(dir / "w.ply"), luminance = test::ply_colours(dir / "cd.ply");
  REQUIRE(radiance.size() == luminance.size());
  for (size_t i = 0; i < radiance.size(); i += 7)
    for (int c = 0; c < 3; ++c) CHECK(luminance[i][c] == Approx(683.0 * radiance[i][c]).epsilon(1e-5).margin(1e-9));

  // The same solve from the radiance target and from the luminance target.
  auto solve = [&](std::vector<std::string> extra, const std::string& name) {
    std::vector<std::string> args = {"solve", kRoom, "-o", (dir / (name + ".json")).string(), "--report",
                                     (dir / (name + ".report.json")).string(), "--cache-dir", (dir / "cache").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = test::run_hilight(args);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    return read_lights_json(dir / (name + ".json"));
  };
  const Lighting w = solve({"--target", (dir / "w.ply").string()}, "w");
  const Lighting cd = solve({"--target", (dir / "cd.ply").string(), "--units", "photometric"}, "cd");
  // Lux on the surface: E_v = π L_v / ρ at each vertex.
  auto scene = std::make_shared<const Scene>(load_scene(kRoom, {}));
  const auto albedo = scene->vertex_albedo();
  std::vector<Rgb> lux(luminance.size());
  for (size_t i = 0; i < lux.size(); ++i) lux[i] = float(kPi) * luminance[i] / albedo[i];
  write_illuminated_ply(dir / "lux.ply", *scene, lux);
  const Lighting from_lux = solve({"--target", (dir / "lux.ply").string(), "--units", "photometric", "--target-quantity", "illuminance"}, "lux");
  for (const Lighting* found : {&cd, &from_lux}) {
    REQUIRE(found->size() == w.size());
    for (size_t j = 0; j < w.size(); ++j) {
      CHECK(glm::length((*found)[j].position - w[j].position) < 1e-3f);
      for (int c = 0; c < 3; ++c) CHECK((*found)[j].intensity[c] == Approx(683.0 * w[j].intensity[c]).epsilon(1e-3));
    }
  }
  CHECK(report_value(dir / "cd.report.json", "dbar") == Approx(report_value(dir / "w.report.json", "dbar")).margin(1e-4));
  CHECK(report_value(dir / "cd.report.json", "total_luminous_flux_lm") ==
        Approx(luminous_flux(w[0]) + luminous_flux(w[1])).epsilon(1e-3));
  // Lux without photometric units is a contradiction: said in one line.
  const auto bad = test::run_hilight({"solve", kRoom, "--target", (dir / "lux.ply").string(), "-o", (dir / "x.json").string(),
                                      "--target-quantity", "illuminance"});
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
}
