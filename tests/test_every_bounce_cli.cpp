// The commands' own default, every diffuse bounce (issue 32): a target
// rendered by `hilight render` is a fixed point of `hilight solve`, both at
// their defaults; the report names the bounce model; ism-vulkan carries
// every bounce too. (A renderer whose traits carry fewer would lower "all"
// with a note and refuse a larger count: RendererOptions::bounces_for.)
#include "hilight/io/lights_json.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace hilight;

namespace {
const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
const std::string kLights = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json";

double mean_red(const std::filesystem::path& ply) {
  double s = 0.0;
  const auto colours = test::ply_colours(ply);
  for (const Rgb& c : colours) s += c.r;
  return s / double(std::max<size_t>(1, colours.size()));
}
} // namespace

TEST_CASE("at the commands' default (every bounce) the bundled room's lights are a fixed point of the solve",
          "[bounce][solve][cli]") {
  const test::CliOwnBounces own;  // the CLI's defaults, not the suite's one bounce
  auto dir = test::output_dir("every_bounce_cli");
  auto all = test::run_hilight({"render", kRoom, "--lights", kLights, "-o", (dir / "all.ply").string()});
  REQUIRE(all.exit_code == 0);
  CHECK(all.err.find("(bounces all)") != std::string::npos);
  auto one = test::run_hilight({"render", kRoom, "--lights", kLights, "-o", (dir / "one.ply").string(), "--bounces", "1"});
  REQUIRE(one.exit_code == 0);
  // The room's surfaces reflect 0.6-0.8: every bounce adds well over a tenth.
  CHECK(mean_red(dir / "all.ply") > 1.1 * mean_red(dir / "one.ply"));

  auto solve = test::run_hilight({"solve", kRoom, "--target", (dir / "all.ply").string(), "-o", (dir / "found.json").string(),
                                  "--report", (dir / "report.json").string(), "--cache-dir", (dir / "cache").string(), "-q"});
  INFO(solve.err);
  REQUIRE(solve.exit_code == 0);
  std::ifstream in(dir / "report.json");
  const auto report = nlohmann::json::parse(in);
  CHECK(report["bounces"] == "all");
  CHECK(report["bounce_model"] == "every diffuse bounce");
  CHECK(report["dbar"].get<double>() <= 0.001);
  const Lighting found = read_lights_json(dir / "found.json"), truth = read_lights_json(kLights);
  REQUIRE(found.size() == truth.size());
  for (const Light& t : truth) {
    float best = 1e9f;
    for (const Light& f : found) best = std::min(best, glm::length(f.position - t.position));
    CHECK(best < 0.01f);  // metres, in an 8.4 m room
  }
}

TEST_CASE("ism-vulkan carries every bounce from the command line: all and counts, no note", "[bounce][cli][ism]") {
  if (test::skip_without_renderer("ism-vulkan")) return;
  const test::CliOwnBounces own;
  auto dir = test::output_dir("every_bounce_ism");
  auto all = test::run_hilight({"render", kRoom, "--lights", kLights, "-o", (dir / "all.ply").string(), "--renderer", "ism-vulkan",
                                "--max-edge", "0.6"});
  INFO(all.err);
  REQUIRE(all.exit_code == 0);
  CHECK(all.err.find("note: renderer ism-vulkan carries at most") == std::string::npos);
  auto two = test::run_hilight({"render", kRoom, "--lights", kLights, "-o", (dir / "two.ply").string(), "--renderer", "ism-vulkan",
                                "--max-edge", "0.6", "--bounces", "2"});
  REQUIRE(two.exit_code == 0);
  auto one = test::run_hilight({"render", kRoom, "--lights", kLights, "-o", (dir / "one.ply").string(), "--renderer", "ism-vulkan",
                                "--max-edge", "0.6", "--bounces", "1"});
  REQUIRE(one.exit_code == 0);
  // The room reflects 0.6-0.8: each further bounce adds light.
  CHECK(mean_red(dir / "two.ply") > 1.05 * mean_red(dir / "one.ply"));
  CHECK(mean_red(dir / "all.ply") > 1.05 * mean_red(dir / "two.ply"));
}

TEST_CASE("a --bounces outside all and 0..1000 is refused in one line", "[bounce][cli][bad-input]") {
  auto dir = test::output_dir("every_bounce_bad");
  for (const char* bad : {"-1", "1001", "some", "2.5", ""}) {
    auto r = test::run_hilight({"render", kRoom, "--lights", kLights, "-o", (dir / "x.ply").string(), "--bounces", bad});
    INFO("--bounces '" << bad << "': " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(test::line_count(r.err) == 1);
    CHECK_FALSE(std::filesystem::exists(dir / "x.ply"));
  }
}
