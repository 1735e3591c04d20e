// Regressions from review: solves that once failed silently or crashed.
#include "hilight/error.hpp"
#include "hilight/io/ply_reader.hpp"
#include "hilight/io/lights_json.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace hilight;

namespace {
const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";
const std::string kLights = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room-4lights.json";

std::string cache_dir() { return std::string(HILIGHT_TEST_OUTPUT_DIR) + "/solve-cache"; }

std::filesystem::path render_target(const std::filesystem::path& dir) {
  auto r = test::run_hilight({"render", kRoom, "--lights", kLights, "-o", (dir / "target.ply").string()});
  REQUIRE(r.exit_code == 0);
  return dir / "target.ply";
}
} // namespace

TEST_CASE("add mode on a target the lights already produce refuses instead of adding noise", "[solve][edge]") {
  auto dir = test::output_dir("edge_add_nothing");
  auto target = render_target(dir);
  auto r = test::run_hilight({"solve", kRoom, "--target", target.string(), "--mode", "add", "--initial", kLights, "-o",
                              (dir / "out.json").string(), "--cache-dir", cache_dir()});
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("nothing to add"));
  CHECK_FALSE(std::filesystem::exists(dir / "out.json"));
}

TEST_CASE("spot hints and fine-tune lights outside the scene or inside solids are refused up front", "[solve][edge]") {
  auto dir = test::output_dir("edge_inadmissible");
  auto target = render_target(dir);
  test::write_text(dir / "hint.json", R"({"lights":[{"type":"spot","position":[3,30,2.5],"direction":[0,-1,0],"cutoff_deg":30,"intensity":[1,1,1]}]})");
  auto r = test::run_hilight({"solve", kRoom, "--target", target.string(), "--spot-hints", (dir / "hint.json").string(), "-o",
                              (dir / "out.json").string(), "--cache-dir", cache_dir()});
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("spot hints: light 0") && Catch::Contains("outside"));
  // Inside the cabinet (4.6..5.7, 0..1.9, 0.3..0.9).
  test::write_text(dir / "inside.json", R"({"lights":[{"type":"point","position":[5.1,1,0.6],"intensity":[1,1,1]}]})");
  r = test::run_hilight({"solve", kRoom, "--target", target.string(), "--mode", "fine-tune", "--initial", (dir / "inside.json").string(),
                         "-o", (dir / "out.json").string(), "--cache-dir", cache_dir()});
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("inside solid geometry"));
  CHECK_FALSE(std::filesystem::exists(dir / "out.json"));
}

TEST_CASE("a target lit only in a small patch gets an honest D-bar and no dead lights", "[solve][edge]") {
  auto dir = test::output_dir("edge_small_patch");
  // Every vertex of the room, black except a small patch on the floor.
  Scene scene = load_scene(kRoom);
  std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(scene.positions.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\nproperty float red\nproperty float green\nproperty float blue\nend_header\n";
  size_t lit = 0;
  for (const auto& p : scene.positions) {
    bool on = p.y == 0.f && std::abs(p.x - 3.f) < 0.3f && std::abs(p.z - 2.5f) < 0.3f;
    lit += on;
    ply += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + (on ? " 0.5 0.5 0.5\n" : " 0 0 0\n");
  }
  REQUIRE(lit > 0);
  test::write_text(dir / "patch.ply", ply);
  auto r = test::run_hilight({"solve", kRoom, "--target", (dir / "patch.ply").string(), "-o", (dir / "out.json").string(), "--report",
                              (dir / "report.json").string(), "--cache-dir", cache_dir(), "-q"});
  REQUIRE(r.exit_code == 0);
  for (const auto& l : read_lights_json(dir / "out.json")) CHECK(glm::length(l.intensity) > 0.f);
  auto report = nlohmann::json::parse(std::ifstream(dir / "report.json"));
  // The patch cannot be lit alone (its surroundings must stay black): the
  // report must say so rather than claim a perfect match.
  CHECK(report["dbar"].get<double>() > 0.05);
}

TEST_CASE("a PLY target whose header claims more than the file holds is refused", "[solve][edge][bad-input]") {
  auto dir = test::output_dir("edge_ply_claims");
  test::write_text(dir / "huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 100000000000\nproperty float x\nproperty float y\n"
                                     "property float z\nproperty float red\nproperty float green\nproperty float blue\nend_header\n");
  test::write_text(dir / "list.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty list uchar int idx\nproperty float x\nend_header\nabc 1 2\n");
  for (const char* name : {"huge.ply", "list.ply"}) {
    auto r = test::run_hilight({"solve", kRoom, "--target", (dir / name).string(), "-o", (dir / "out.json").string()});
    INFO(name << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(test::line_count(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(name));
  }
}

TEST_CASE("a PLY element with rows but no properties is refused, not read forever", "[edge][bad-input][ply]") {
  // Found by fuzzing (tools/fuzz.sh): rows that take no bytes were read
  // 2.5·10¹⁵ times. `solve` never got there (its target needs positions).
  auto dir = test::output_dir("edge_ply_empty_rows");
  test::write_text(dir / "empty-rows.ply", "ply\nformat ascii 1.0\nelement vertex 2555555555555550pr30propert\nend_header\n0 0 0 255 0r");
  CHECK_THROWS_AS(hilight::read_ply_vertices(dir / "empty-rows.ply"), hilight::InputError);
}

TEST_CASE("a solve is byte-identical with one thread or two, and the second one loads the light cache", "[solve][determinism]") {
  auto dir = test::output_dir("edge_threads");
  auto target = render_target(dir);
  const std::string cache = (dir / "cache").string();
  auto one = test::run_hilight({"solve", kRoom, "--target", target.string(), "-o", (dir / "one.json").string(), "--threads", "1",
                                "--cache-dir", cache, "--report", (dir / "one-report.json").string(), "-q"});
  auto two = test::run_hilight({"solve", kRoom, "--target", target.string(), "-o", (dir / "two.json").string(), "--threads", "2",
                                "--cache-dir", cache, "--report", (dir / "two-report.json").string(), "-q"});
  REQUIRE(one.exit_code == 0);
  REQUIRE(two.exit_code == 0);
  CHECK(test::read_file(dir / "one.json") == test::read_file(dir / "two.json"));
  auto r1 = nlohmann::json::parse(test::read_file(dir / "one-report.json")), r2 = nlohmann::json::parse(test::read_file(dir / "two-report.json"));
  CHECK(r1["light_cache"] == "built");
  CHECK(r2["light_cache"] == "loaded");
}

TEST_CASE("an ASCII target whose last value has no newline after it is read", "[solve][edge]") {
  auto dir = test::output_dir("edge_ascii_no_newline");
  test::write_text(dir / "one.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                                    "property float red\nproperty float green\nproperty float blue\nend_header\n3 0 2 1 1 1");
  auto r = test::run_hilight({"solve", kRoom, "--target", (dir / "one.ply").string(), "-o", (dir / "out.json").string(),
                              "--cache-dir", cache_dir(), "-q"});
  INFO(r.err);
  CHECK(r.exit_code == 0);
}

TEST_CASE("a solve where no seeding cell is free still returns the requested spotlight", "[solve][edge][spot]") {
  auto dir = test::output_dir("edge_spots_only");
  // A floor with a box whose corner sits at the centre of the light space:
  // with one seeding cell, that cell's centre is on the box, so not free.
  test::write_text(dir / "flat.obj", "v 0 0 0\nv 0 0 10\nv 10 0 10\nv 10 0 0\nf 1 2 3 4\n"
                                     "v 4 0 4\nv 5 0 4\nv 5 0 5\nv 4 0 5\nv 4 1 4\nv 5 1 4\nv 5 1 5\nv 4 1 5\n"
                                     "f 5 6 7 8\nf 9 12 11 10\nf 5 9 10 6\nf 6 10 11 7\nf 7 11 12 8\nf 8 12 9 5\n");
  test::write_text(dir / "spot.json", R"({"lights":[{"type":"spot","position":[2,3,2],"direction":[0.3,-1,0.3],"cutoff_deg":35,"intensity":[3,3,3]}]})");
  auto render = test::run_hilight({"render", (dir / "flat.obj").string(), "--lights", (dir / "spot.json").string(), "-o",
                                   (dir / "target.ply").string()});
  REQUIRE(render.exit_code == 0);
  auto r = test::run_hilight({"solve", (dir / "flat.obj").string(), "--target", (dir / "target.ply").string(), "--spot-hints",
                              (dir / "spot.json").string(), "--seed-cells", "1", "-o", (dir / "out.json").string(), "--no-cache", "-q"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  Lighting found = read_lights_json(dir / "out.json");
  REQUIRE(found.size() >= 1);
  CHECK(found[0].type == LightType::Spot);
}

TEST_CASE("a poor fit is said plainly, and --max-dbar makes it exit 3 with the lights written", "[solve][edge][max-dbar]") {
  auto dir = test::output_dir("edge_max_dbar");
  auto target = render_target(dir);
  // Four lights made the target; one cannot explain it.
  auto r = test::run_hilight({"solve", kRoom, "--target", target.string(), "--lights", "1", "--max-dbar", "0.015", "-o",
                              (dir / "one.json").string(), "--report", (dir / "report.json").string(), "--cache-dir", cache_dir()});
  CHECK(r.exit_code == 3);
  CHECK_THAT(r.err, Catch::Contains("warning: poor fit"));
  CHECK_THAT(r.err, Catch::Contains("above --max-dbar"));
  CHECK(read_lights_json(dir / "one.json").size() == 1);
  std::ifstream report(dir / "report.json");
  CHECK(nlohmann::json::parse(report)["poor_fit"] == true);
  // The full solve meets the same bound: exit 0, no warning.
  auto good = test::run_hilight({"solve", kRoom, "--target", target.string(), "--max-dbar", "0.015", "-o",
                                 (dir / "all.json").string(), "--cache-dir", cache_dir()});
  CHECK(good.exit_code == 0);
  CHECK_THAT(good.err, !Catch::Contains("warning"));
}
