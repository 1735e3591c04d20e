// Aiming asymmetric luminaires for a painted target (issue 14 §2): seeded
// luminaires of a profile wide along its C0 plane, turned 90° from the
// template; the solve (template spin 0) finds their turn, count and places.
#include "hilight/io/lights_json.hpp"
#include "hilight/units.hpp"
#include "photometry_files.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

using namespace hilight;

TEST_CASE("solve --luminaire turns asymmetric luminaires to the painted target's light", "[photometry][solve][aim]") {
  const auto dir = test::output_dir("luminaire_aim");
  const auto profile = dir / "linear.ies";
  std::ofstream(profile) << test::linear_ies();  // wide in C0–C180, narrow across it
  std::mt19937_64 rng(1401);
  std::uniform_real_distribution<float> x(1.0f, 2.4f), z(1.0f, 4.0f);
  nlohmann::json lights = nlohmann::json::array();
  std::vector<Vec3> truth;
  for (int i = 0; i < 2; ++i) {
    const Vec3 p(x(rng) + 2.6f * float(i), 2.8f, z(rng));  // one in each half of the room
    truth.push_back(p);
    lights.push_back({{"type", "luminaire"}, {"profile", "linear.ies"}, {"position", {p.x, p.y, p.z}}, {"dimming", 0.7}, {"spin_deg", 90}});
  }
  std::ofstream(dir / "truth.json") << nlohmann::json{{"lights", lights}}.dump();
  const std::string room = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
  const auto t = test::run_hilight({"render", room, "--lights", (dir / "truth.json").string(), "-o", (dir / "target.ply").string()});
  INFO(t.err);
  REQUIRE(t.exit_code == 0);
  const auto r = test::run_hilight({"solve", room, "--target", (dir / "target.ply").string(), "-o", (dir / "found.json").string(),
                                    "--luminaire", profile.string(), "--report", (dir / "report.json").string(), "--cache-dir",
                                    (dir / "cache").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Lighting found = read_lights_json(dir / "found.json");
  REQUIRE(found.size() == 2);
  for (const Vec3& p : truth) {
    const Light* match = &found[0];
    for (const auto& l : found)
      if (glm::length(l.position - p) < glm::length(match->position - p)) match = &l;
    CHECK(glm::length(match->position - p) < 0.05f);
    CHECK(std::fmod(match->spin_deg, 180.f) == Approx(90.f));
    CHECK(luminaire_dimming(*match) == Approx(0.7).epsilon(0.03));
  }
  const auto report = nlohmann::json::parse(test::read_file(dir / "report.json"));
  CHECK(report["dbar"].get<double>() < 0.015);
}
