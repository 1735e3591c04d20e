// The `hilight` launcher on bad input: exactly one stderr line naming the file
// (or option) and the problem, exit code 2, no crash, no (partial) output file.
#include "support.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoomLights = HILIGHT_SOURCE_DIR "/scenes/room-lights.json";
const fs::path kInvalidModels = "/usr/share/assimp/models/invalid";
const fs::path kInvalidOff = "/usr/share/assimp/models/OFF/invalid.off";

/// Temporary files of an interrupted atomic write: ".NAME.tmpPID.EXT".
std::vector<std::string> stray_temp_files(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    std::string name = entry.path().filename().string();
    if (name.size() > 1 && name[0] == '.' && name.find(".tmp") != std::string::npos) out.push_back(name);
  }
  return out;
}

/// The contract for every bad input: code 2, one stderr line that mentions `mention`.
void check_one_line_error(const test::RunResult& r, const std::string& mention) {
  CAPTURE(r.exit_code, r.out, r.err, mention);
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Contains(mention));
}

/// None of `names` exists in `dir`, and no temporary file was left there.
void check_no_output(const fs::path& dir, const std::vector<std::string>& names) {
  for (const auto& n : names) {
    CAPTURE(dir / n);
    CHECK_FALSE(fs::exists(dir / n));
  }
  CAPTURE(dir);
  CHECK(stray_temp_files(dir).empty());
}

/// Address space granted to `hilight` on assimp's invalid models. OutOfMemory.off
/// makes assimp allocate and touch ~16 GB (about 20 s) when nothing stops it;
/// capped, the allocation fails at once, as it would on a smaller machine.
/// AddressSanitizer reserves terabytes of address space for its shadow memory
/// at start, so under it (tools/sanitize.sh) no cap can be set: there the
/// script's ASAN_OPTIONS (max_allocation_size_mb=8192, allocator_may_return_null=1)
/// fail any one larger allocation instead.
#if defined(__SANITIZE_ADDRESS__)
constexpr rlim_t kAddressSpaceCap = 0;
#else
constexpr rlim_t kAddressSpaceCap = rlim_t(8) << 30;
#endif

/// `hilight render SCENE --lights LIGHTS -o DIR/out -o DIR/out.exr` (small and
/// direct-light only), checking that nothing was written. `address_space`: see
/// test::run_hilight.
test::RunResult bad_render(const fs::path& dir, const std::string& scene, const std::string& lights,
                           const std::vector<std::string>& extra = {}, rlim_t address_space = 0) {
  std::vector<std::string> args = {"render", scene, "--lights", lights, "-o", (dir / "out").string(), "-o",
                                   (dir / "out.exr").string(), "--bounces", "0", "--width", "64", "--height", "48"};
  args.insert(args.end(), extra.begin(), extra.end());
  test::RunResult r = test::run_hilight(args, address_space);
  check_no_output(dir, {"out.ply", "out.png", "out.exr"});
  return r;
}

} // namespace

TEST_CASE("render: a missing scene file is named", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_missing_scene");
  std::string scene = (dir / "MISSING.obj").string();
  auto r = bad_render(dir, scene, kRoomLights);
  check_one_line_error(r, scene);
  CHECK_THAT(r.err, Contains("no such file"));
}

TEST_CASE("render: an unreadable scene is named", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_unreadable_scene");
  SECTION("a folder passed as the scene") {
    fs::path folder = dir / "scene.obj";
    fs::create_directories(folder);
    auto r = bad_render(dir, folder.string(), kRoomLights);
    check_one_line_error(r, folder.string());
    CHECK_THAT(r.err, Contains("folder"));
  }
  SECTION("a file without read permission") {
    if (::geteuid() == 0) {
      WARN("running as root: a chmod 000 file is still readable, unreadable-file case skipped");
      return;
    }
    fs::path file = dir / "locked.obj";
    test::write_text(file, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    fs::permissions(file, fs::perms::none);
    auto r = bad_render(dir, file.string(), kRoomLights);
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);
    check_one_line_error(r, file.string());
  }
}

TEST_CASE("info: every one of assimp's invalid test models is refused cleanly or read for real", "[cli][bad-input]") {
  std::error_code ec;
  if (!fs::is_directory(kInvalidModels, ec)) {
    WARN(kInvalidModels.string() + " does not exist (Debian package assimp-testmodels): skipped");
    return;
  }
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kInvalidModels)) files.push_back(entry.path());
  if (fs::exists(kInvalidOff)) files.push_back(kInvalidOff);
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 5);
  size_t refused = 0;
  for (const auto& file : files) {
    auto r = test::run_hilight({"info", file.string(), "--json"}, kAddressSpaceCap);
    CAPTURE(file, r.exit_code, r.out, r.err);
    // 1 is an internal error, >= 128 a signal: both are crashes here.
    REQUIRE((r.exit_code == 0 || r.exit_code == 2));
    if (r.exit_code == 2) {
      ++refused;
      CHECK(test::line_count(r.err) == 1);
      CHECK_THAT(r.err, Contains(file.string()));
      CHECK(r.out.empty());
    } else {
      // Accepted only if assimp really produced triangles (malformed2.obj is
      // a cube that merely names a missing material).
      auto j = nlohmann::json::parse(r.out);
      CHECK(j.at("triangles_input").get<size_t>() > 0);
      CHECK(j.at("triangles").get<size_t>() >= j.at("triangles_input").get<size_t>());
      CHECK(j.at("diagonal").get<double>() > 0.0);
    }
  }
  // Almost all of them are empty or broken beyond reading.
  CHECK(refused + 1 >= files.size());
}

TEST_CASE("render: meshes assimp rejects leave no output", "[cli][bad-input]") {
  std::error_code ec;
  if (!fs::is_directory(kInvalidModels, ec)) {
    WARN(kInvalidModels.string() + " does not exist (Debian package assimp-testmodels): skipped");
    return;
  }
  fs::path dir = test::output_dir("bad_input_assimp_rejects");
  for (const char* name : {"empty.obj", "malformed.obj", "empty.ply", "empty.off", "OutOfMemory.off"}) {
    fs::path file = kInvalidModels / name;
    if (!fs::exists(file)) continue;
    auto r = bad_render(dir, file.string(), kRoomLights, {}, kAddressSpaceCap);
    check_one_line_error(r, file.string());
  }
  if (fs::exists(kInvalidOff)) {
    auto r = bad_render(dir, kInvalidOff.string(), kRoomLights);
    check_one_line_error(r, kInvalidOff.string());
  }
}

TEST_CASE("render: a scene without triangles is refused", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_no_triangles");
  fs::path scene = dir / "scene.obj";
  SECTION("only vertices") { test::write_text(scene, "v 0 0 0\nv 1 0 0\nv 0 1 0\n"); }
  SECTION("only lines") { test::write_text(scene, "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n"); }
  SECTION("only points") { test::write_text(scene, "v 0 0 0\nv 1 0 0\nv 0 1 0\np 1\np 2\n"); }
  SECTION("only zero-area triangles") { test::write_text(scene, "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"); }
  auto r = bad_render(dir, scene.string(), kRoomLights);
  check_one_line_error(r, scene.string());
  auto info = test::run_hilight({"info", scene.string()});
  check_one_line_error(info, scene.string());
  CHECK(info.out.empty());
}

TEST_CASE("render: NaN or infinite vertex coordinates are refused", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_nan_vertices");
  fs::path scene = dir / "scene.obj";
  SECTION("nan") { test::write_text(scene, "v nan 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 2 4 3\nf 1 2 3\n"); }
  SECTION("inf") { test::write_text(scene, "v 0 0 0\nv 1 0 0\nv 0 -inf 0\nv 1 1 0\nf 2 4 3\nf 1 2 3\n"); }
  auto r = bad_render(dir, scene.string(), kRoomLights);
  check_one_line_error(r, scene.string());
  CHECK_THAT(r.err, Contains("NaN or infinite"));
}

TEST_CASE("render: a binary PLY that assimp would misread is refused rather than misread or crashed on", "[cli][bad-input]") {
  // assimp skips whitespace after end_header even in binary data: a first
  // float starting with byte 0x0a (-0.02) shifts every value after it, and
  // assimp then aborts on an assertion (measured) or reads a garbled mesh.
  fs::path dir = test::output_dir("bad_input_binary_ply_whitespace");
  fs::path scene = dir / "triangle.ply";
  const float xyz[9] = {-0.02f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f};
  const int32_t face[3] = {0, 1, 2};
  {
    std::ofstream out(scene, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    out.write(reinterpret_cast<const char*>(xyz), sizeof(xyz));
    out.put(char(3));
    out.write(reinterpret_cast<const char*>(face), sizeof(face));
  }
  REQUIRE(test::read_file(scene).find("end_header\n\n") != std::string::npos);  // the first data byte is 0x0a
  auto r = bad_render(dir, scene.string(), kRoomLights);
  check_one_line_error(r, scene.string());
  CHECK_THAT(r.err, Contains("whitespace byte"));
}

TEST_CASE("render: malformed lights JSON is named with its problem", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_lights");
  fs::path lights = dir / "lights.json";
  std::string problem;
  SECTION("truncated JSON") {
    test::write_text(lights, R"({"lights": [{"type": "point", "position": [1, 2)");
    problem = "malformed JSON";
  }
  SECTION("empty file") {
    test::write_text(lights, "");
    problem = "malformed JSON";
  }
  SECTION("lights is not an array") {
    test::write_text(lights, R"({"lights": 3})");
    problem = "\"lights\" array";
  }
  SECTION("a light without position") {
    test::write_text(lights, R"({"lights": [{"type": "point", "intensity": [1, 1, 1]}]})");
    problem = "position";
  }
  SECTION("negative intensity") {
    test::write_text(lights, R"({"lights": [{"type": "point", "position": [1, 1, 1], "intensity": [1, -1, 1]}]})");
    problem = "negative intensity";
  }
  SECTION("spot with a zero-length direction") {
    test::write_text(lights, R"({"lights": [{"type": "spot", "position": [1, 1, 1], "direction": [0, 0, 0],
                                              "cutoff_deg": 30, "intensity": [1, 1, 1]}]})");
    problem = "direction";
  }
  SECTION("spot without cutoff_deg") {
    test::write_text(lights, R"({"lights": [{"type": "spot", "position": [1, 1, 1], "direction": [0, -1, 0],
                                              "intensity": [1, 1, 1]}]})");
    problem = "cutoff_deg";
  }
  SECTION("unknown light type") {
    test::write_text(lights, R"({"lights": [{"type": "area", "position": [1, 1, 1], "intensity": [1, 1, 1]}]})");
    problem = "area";
  }
  SECTION("unknown field") {
    test::write_text(lights, R"({"lights": [{"type": "point", "position": [1, 1, 1], "intensity": [1, 1, 1],
                                              "colour": [1, 0, 0]}]})");
    problem = "colour";
  }
  SECTION("a light that is not an object") {
    test::write_text(lights, R"({"lights": [null]})");
    problem = "light 0";
  }
  SECTION("missing lights file") {
    lights = dir / "no-such-lights.json";
    problem = "no such file";
  }
  CAPTURE(test::read_file(lights));
  // A good scene and output requested: the lights fail, nothing is written.
  auto r = bad_render(dir, kRoom, lights.string());
  check_one_line_error(r, lights.string());
  CHECK_THAT(r.err, Contains(problem));
}

// Product bug: nlohmann's json::value("type", std::string) throws a type_error
// for a non-string "type"; it escapes as "internal error", exit 1.
TEST_CASE("render: a light whose type is not a string is an input error", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_lights_type_not_string");
  fs::path lights = dir / "lights.json";
  SECTION("number") {
    test::write_text(lights, R"({"lights": [{"type": 3, "position": [1, 1, 1], "intensity": [1, 1, 1]}]})");
  }
  SECTION("null") {
    test::write_text(lights, R"({"lights": [{"type": null, "position": [1, 1, 1], "intensity": [1, 1, 1]}]})");
  }
  auto r = bad_render(dir, kRoom, lights.string());
  check_one_line_error(r, lights.string());
}

TEST_CASE("render: an unknown renderer is named", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_unknown_renderer");
  auto r = bad_render(dir, kRoom, kRoomLights, {"--renderer", "nosuch"});
  check_one_line_error(r, "'nosuch'");
  CHECK_THAT(r.err, Contains("embree"));  // lists what is available
}

TEST_CASE("render: an unwritable output is named", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_unwritable_output");
  SECTION("folder does not exist") {
    auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", "/nonexistent-dir/out.ply", "--bounces", "0"});
    check_one_line_error(r, "/nonexistent-dir/out.ply");
    CHECK_FALSE(fs::exists("/nonexistent-dir"));
  }
  SECTION("output is an existing folder") {
    fs::path target = dir / "out.ply";
    fs::create_directories(target);
    auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", target.string(), "--bounces", "0"});
    check_one_line_error(r, target.string());
    CHECK(fs::is_directory(target));
    CHECK(fs::is_empty(target));
    CHECK(stray_temp_files(dir).empty());
  }
  SECTION("OUT.png of a bare OUT is a folder: OUT.ply is not written either") {
    fs::create_directories(dir / "out.png");
    auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", (dir / "out").string(), "--bounces", "0",
                                "--width", "64", "--height", "48"});
    check_one_line_error(r, (dir / "out.png").string());
    CHECK_FALSE(fs::exists(dir / "out.ply"));
    CHECK(stray_temp_files(dir).empty());
  }
  SECTION("second output unwritable: the first is not written") {
    auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", (dir / "first.ply").string(), "-o",
                                "/nonexistent-dir/second.png", "--bounces", "0", "--width", "64", "--height", "48"});
    check_one_line_error(r, "/nonexistent-dir/second.png");
    CHECK_FALSE(fs::exists(dir / "first.ply"));
    CHECK(stray_temp_files(dir).empty());
  }
}

TEST_CASE("render: an unknown output extension is named", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_output_extension");
  fs::path target = dir / "out.xyz";
  auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", target.string(), "--bounces", "0"});
  check_one_line_error(r, target.string());
  CHECK_THAT(r.err, Contains(".xyz"));
  CHECK_FALSE(fs::exists(target));
  CHECK(fs::is_empty(dir));
}

TEST_CASE("render: bad --camera text is refused", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_camera");
  std::string camera, mention = "--camera";
  SECTION("too few numbers") { camera = "1,2,3"; }
  SECTION("too many numbers") { camera = "1,2,3,4,5,6,50,8"; }
  SECTION("not a number") {
    camera = "1,2,3,4,5,6,wide";
    mention = "wide";
  }
  SECTION("empty items") { camera = ",,,,,,"; }
  SECTION("not finite") {
    camera = "1,2,3,4,5,6,nan";
    mention = "nan";
  }
  SECTION("eye equals target") { camera = "1,1,1,1,1,1,50"; }
  CAPTURE(camera);
  auto r = bad_render(dir, kRoom, kRoomLights, {"--camera", camera});
  check_one_line_error(r, mention);
}

TEST_CASE("render: an unknown --set renderer setting is named", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_unknown_setting");
  SECTION("unknown key") {
    auto r = bad_render(dir, kRoom, kRoomLights, {"--set", "foo=1"});
    check_one_line_error(r, "'foo'");
  }
  SECTION("not key=value") {
    auto r = bad_render(dir, kRoom, kRoomLights, {"--set", "foo"});
    check_one_line_error(r, "foo");
  }
  SECTION("bad value of a known key") {
    auto r = bad_render(dir, kRoom, kRoomLights, {"--set", "seed=abc"});
    check_one_line_error(r, "seed");
  }
}

TEST_CASE("render: bad command-line options are refused", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_options");
  std::vector<std::string> extra;
  std::string mention;
  SECTION("unknown option") {
    extra = {"--nosuch"};
    mention = "--nosuch";
  }
  SECTION("--bounces out of range") {
    extra = {"--bounces", "2"};
    mention = "--bounces";
  }
  SECTION("--width not a number") {
    extra = {"--width", "abc"};
    mention = "--width";
  }
  SECTION("--bounce-samples 1 (the renderer needs >= 2)") {
    extra = {"--bounce-samples", "1"};
    mention = "bounce_samples";
  }
  auto r = bad_render(dir, kRoom, kRoomLights, extra);
  check_one_line_error(r, mention);
}

TEST_CASE("launcher: an unknown command exits with 2", "[cli][bad-input]") {
  auto r = test::run_hilight({"nosuchcommand"});
  check_one_line_error(r, "'nosuchcommand'");
}

TEST_CASE("info and render without a scene exit with 2", "[cli][bad-input]") {
  SECTION("info") {
    auto r = test::run_hilight({"info"});
    check_one_line_error(r, "scene");
    CHECK(r.out.empty());
  }
  SECTION("render without --output") {
    auto r = test::run_hilight({"render", kRoom, "--lights", kRoomLights});
    check_one_line_error(r, "--output");
  }
}

TEST_CASE("render: a failure after output was requested leaves no file and keeps an old one", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_fail_after_output");
  fs::path lights = dir / "lights.json";
  test::write_text(lights, R"({"lights": [{"type": "point", "position": [1, 1, 1], "intensity": [1, 1, 1]},)");
  SECTION("no output existed") {
    auto r = bad_render(dir, kRoom, lights.string());
    check_one_line_error(r, lights.string());
  }
  SECTION("an earlier output is left untouched") {
    const std::string old = "an earlier result\n";
    test::write_text(dir / "old.ply", old);
    auto r = test::run_hilight({"render", kRoom, "--lights", lights.string(), "-o", (dir / "old.ply").string(), "--bounces", "0"});
    check_one_line_error(r, lights.string());
    CHECK(test::read_file(dir / "old.ply") == old);
    CHECK(stray_temp_files(dir).empty());
  }
  SECTION("the renderer refuses its settings after the scene was loaded") {
    auto r = bad_render(dir, kRoom, kRoomLights, {"--set", "no_such_setting=2"});
    check_one_line_error(r, "no_such_setting");
  }
  SECTION("a --max-edge that would make too many triangles") {
    auto r = bad_render(dir, kRoom, kRoomLights, {"--max-edge", "0.0001"});
    check_one_line_error(r, kRoom);
  }
}

// Product bugs: options that are not numbers slip through CLI11's
// NonNegativeNumber check (NaN compares false with everything).
TEST_CASE("NaN option values are refused", "[cli][bad-input]") {
  fs::path dir = test::output_dir("bad_input_nan_options");
  SECTION("render --exposure nan") {
    // Accepted today: the PNG comes out all black (lround of NaN).
    auto r = bad_render(dir, kRoom, kRoomLights, {"--exposure", "nan"});
    check_one_line_error(r, "--exposure");
  }
  SECTION("info --max-edge nan") {
    // Accepted today and silently replaced by the default edge length.
    auto r = test::run_hilight({"info", kRoom, "--max-edge", "nan"});
    check_one_line_error(r, "--max-edge");
  }
}

// Product bug: for a tiny --max-edge the estimate overflows size_t (UB, prints
// "about 0 triangles") and the edge is printed with %f ("0.000000").
TEST_CASE("a too-small --max-edge is reported with a meaningful estimate", "[cli][bad-input]") {
  auto r = test::run_hilight({"info", kRoom, "--max-edge", "1e-30"});
  check_one_line_error(r, kRoom);
  CHECK_THAT(r.err, !Contains("about 0 triangles"));
  CHECK_THAT(r.err, !Contains("--max-edge 0.000000"));
}

// Product robustness gap, hidden because it costs ~20 s and ~16 GB of RAM: with
// no cap, OutOfMemory.off (a 300-byte file declaring billions of elements) makes
// assimp allocate and zero-fill ~16 GB before failing. On a machine with less
// memory the kernel's OOM killer ends hilight with SIGKILL instead of the
// one-line exit 2. Run explicitly: hilight_tests "[oom]"
TEST_CASE("info: a model declaring billions of elements is refused within bounded memory", "[cli][bad-input][oom]") {
  fs::path file = kInvalidModels / "OutOfMemory.off";
  if (!fs::exists(file)) {
    WARN(file.string() + " does not exist: skipped");
    return;
  }
  auto run = test::run_hilight({"info", file.string()}, 0);
  CAPTURE(run.max_rss_kb);
  check_one_line_error(run, file.string());
  CHECK(run.max_rss_kb < 2L * 1024 * 1024);  // under 2 GB
}
