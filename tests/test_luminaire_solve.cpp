// Solving with a given luminaire (issue 14, `hilight solve --luminaire`):
// seeded luminaires of a measured profile make a target; the solve finds how
// many, where and how dimmed, with and without the light cache, and with
// `--place ceiling` they hang at the offset below the ceiling.
#include "hilight/io/lights_json.hpp"
#include "hilight/units.hpp"
#include "photometry_files.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

using namespace hilight;

namespace {

/// A quadrant-symmetric downlight, batwing-ish: (100 + 40 cos 2C) (0.3 + sin γ) cd up to 90°.
std::string batwing_ies() {
  return test::ies_text(test::angles(0, 90, 5), test::angles(0, 90, 15), [](double c, double g) {
    return (100.0 + 40.0 * std::cos(2.0 * c * kPi / 180.0)) * (0.3 + std::sin(g * kPi / 180.0));
  }, 1, "TILT=NONE", 1, 1, 2000, 24);
}

struct Case {
  std::filesystem::path dir, profile, target;
  std::vector<std::pair<Vec3, double>> truth;  ///< position, dimming
};

Case make_case(const std::string& name, uint64_t seed, float height) {
  Case c;
  c.dir = test::output_dir("luminaire_solve_" + name);
  c.profile = c.dir / "batwing.ies";
  std::ofstream(c.profile) << batwing_ies();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> x(0.8f, 5.2f), z(0.8f, 4.2f);
  std::uniform_real_distribution<double> dim(0.3, 0.9);
  nlohmann::json lights = nlohmann::json::array();
  for (int i = 0; i < 2; ++i) {
    Vec3 p(x(rng), height, z(rng));
    if (i == 1 && glm::length(p - c.truth[0].first) < 2.f) p.x = c.truth[0].first.x < 3.f ? 5.2f : 0.8f;  // apart: two lamps, not one
    const double d = dim(rng);
    c.truth.push_back({p, d});
    lights.push_back({{"type", "luminaire"}, {"profile", "batwing.ies"}, {"position", {p.x, p.y, p.z}}, {"dimming", d}});
  }
  std::ofstream(c.dir / "truth.json") << nlohmann::json{{"lights", lights}}.dump();
  c.target = c.dir / "target.ply";
  const auto r = test::run_hilight({"render", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj", "--lights",
                                    (c.dir / "truth.json").string(), "-o", c.target.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return c;
}

void check_found(const Case& c, const Lighting& found, float position_tolerance) {
  REQUIRE(found.size() == c.truth.size());
  for (const auto& [p, d] : c.truth) {
    const Light* match = nullptr;
    for (const auto& l : found)
      if (!match || glm::length(l.position - p) < glm::length(match->position - p)) match = &l;
    INFO("true luminaire at " << p.x << ", " << p.y << ", " << p.z);
    CHECK(match->type == LightType::Luminaire);
    CHECK(glm::length(match->position - p) < position_tolerance);
    CHECK(luminaire_dimming(*match) == Approx(d).epsilon(0.03));
  }
}

} // namespace

TEST_CASE("solve --luminaire finds the count, places and dimming of seeded luminaires", "[photometry][solve]") {
  const Case c = make_case("free", 81, 2.5f);
  for (const bool cache : {true, false}) {
    INFO((cache ? "light cache" : "no cache"));
    std::vector<std::string> args = {"solve", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj", "--target", c.target.string(),
                                     "-o", (c.dir / "found.json").string(), "--luminaire", c.profile.string(), "--report",
                                     (c.dir / "report.json").string()};
    if (cache) args.insert(args.end(), {"--cache-dir", (c.dir / "cache").string()});
    else args.push_back("--no-cache");
    const auto r = test::run_hilight(args);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.err, Catch::Contains("(batwing.ies)"));
    check_found(c, read_lights_json(c.dir / "found.json"), 0.05f);
    std::ifstream in(c.dir / "report.json");
    const auto report = nlohmann::json::parse(in);
    CHECK(report["dbar"].get<double>() < 0.015);
    CHECK(report["dimming"].size() == 2);
    // 24 W each at full output, dimmed.
    CHECK(report["electrical_power_w"].get<double>() == Approx(24.0 * (c.truth[0].second + c.truth[1].second)).epsilon(0.05));
  }
}

TEST_CASE("solve --luminaire with --place ceiling hangs each luminaire at its offset below the ceiling", "[photometry][solve][placement]") {
  const Case c = make_case("ceiling", 82, 2.9f);  // the bundled room's ceiling is at y = 3
  const auto r = test::run_hilight({"solve", std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj", "--target", c.target.string(), "-o",
                                    (c.dir / "found.json").string(), "--luminaire", c.profile.string(), "--place", "ceiling:0.1",
                                    "--cache-dir", (c.dir / "cache").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Lighting found = read_lights_json(c.dir / "found.json");
  check_found(c, found, 0.05f);
  for (const auto& l : found) CHECK(std::abs(l.position.y - 2.9f) < 1e-3f);  // within 1 mm of 0.1 below the ceiling
}
