// Files an input names must lie in its folder or below (issue 35, item 6):
// a glTF buffer uri "../x.bin", an OBJ's "mtllib ../../etc/passwd". Both
// glTF readers (hilight's, for targets and lights; assimp's, for scenes) and
// the OBJ path refuse them in one line naming the input, without reading
// them: nothing of the other file (a line, its size) reaches stderr.
#include "hilight/error.hpp"
#include "hilight/io/gltf.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoomLights = HILIGHT_SOURCE_DIR "/scenes/room-lights.json";

/// One coloured triangle: POSITION then COLOR_0, 36 bytes each, in `bin`.
std::string triangle_bin() {
  const float data[18] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
  std::string bytes(sizeof(data), '\0');
  std::memcpy(bytes.data(), data, sizeof(data));
  return bytes;
}

/// A glTF whose only buffer is `uri` (72 bytes: one coloured triangle).
std::string triangle_gltf(const std::string& uri) {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "COLOR_0": 1}}]}],
  "buffers": [{"uri": ")" + uri + R"(", "byteLength": 72}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"}]})";
}

/// Refused in one line naming `input` (`why`: the reason, when one is
/// expected), and nothing of the other file (`secret`) told.
void check_refused(const test::RunResult& r, const fs::path& input, const std::string& secret, const std::string& why = "outside its folder") {
  CAPTURE(r.exit_code, r.out, r.err);
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Contains(input.string()));
  CHECK_THAT(r.err, Contains(why));
  CHECK_THAT(r.err + r.out, !Contains(secret));
}

} // namespace

TEST_CASE("a glTF buffer uri leading out of the file's folder is refused by both glTF readers", "[gltf][bad-input][security]") {
  const fs::path dir = test::output_dir("gltf_outside_uri");
  fs::create_directories(dir / "in");
  test::write_text(dir / "secret.bin", triangle_bin());  // a readable buffer: only the folder rule refuses it
  test::write_text(dir / "in" / "inside.bin", triangle_bin());
  const fs::path outside = dir / "in" / "outside.gltf", inside = dir / "in" / "inside.gltf";
  test::write_text(outside, triangle_gltf("../secret.bin"));
  test::write_text(inside, triangle_gltf("inside.bin"));

  SECTION("hilight's reader (targets)") {
    CHECK(hilight::read_gltf_colours(inside).positions.size() == 3);
    try {
      hilight::read_gltf_colours(outside);
      FAIL("a buffer outside the folder was read");
    } catch (const hilight::InputError& e) {
      CHECK_THAT(std::string(e.what()), Contains(outside.string()) && Contains("../secret.bin") && Contains("outside its folder"));
    }
  }
  SECTION("assimp's reader (scenes)") {
    CHECK(test::run_hilight({"info", inside.string()}).exit_code == 0);
    check_refused(test::run_hilight({"info", outside.string()}), outside, "requestedBytes");
  }
  SECTION("an absolute uri, and another file's size is not told") {
    test::write_text(dir / "other.bin", std::string(1234, 'x'));
    const fs::path absolute = dir / "in" / "absolute.gltf";
    test::write_text(absolute, triangle_gltf(fs::absolute(dir / "other.bin").string()));
    // assimp looks for it inside the folder ("could not open"): not read either.
    check_refused(test::run_hilight({"info", absolute.string()}), absolute, "1234", "");
    try {
      hilight::read_gltf_colours(absolute);
      FAIL("a buffer outside the folder was read");
    } catch (const hilight::InputError& e) {
      CHECK_THAT(std::string(e.what()), Contains("outside its folder") && !Contains("1234"));
    }
  }
}

TEST_CASE("an OBJ whose mtllib leads out of its folder is refused, and nothing of that file is echoed", "[scene][bad-input][security]") {
  const fs::path dir = test::output_dir("obj_outside_mtllib");
  fs::create_directories(dir / "in");
  // Not a material file: assimp quoted its first line in its error.
  test::write_text(dir / "secret.txt", "root:x:0:0:SECRET-LINE:/root:/bin/bash\n");
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n";
  for (const std::string& mtllib : {"../secret.txt", "../../../../../../../../../../etc/passwd"}) {
    CAPTURE(mtllib);
    const fs::path obj = dir / "in" / "quad.obj";
    test::write_text(obj, "mtllib " + mtllib + "\nusemtl a\n" + quad);
    check_refused(test::run_hilight({"info", obj.string()}), obj, "root:");
    check_refused(test::run_hilight({"render", obj.string(), "--lights", kRoomLights, "-o", (dir / "out.ply").string()}), obj, "root:");
    CHECK_FALSE(fs::exists(dir / "out.ply"));
  }
  // A material file beside it is read as always.
  test::write_text(dir / "in" / "a.mtl", "newmtl a\nKd 0.2 0.4 0.6\n");
  test::write_text(dir / "in" / "near.obj", "mtllib a.mtl\nusemtl a\n" + quad);
  const auto near = test::run_hilight({"info", (dir / "in" / "near.obj").string()});
  CHECK(near.exit_code == 0);
  CHECK(near.err.empty());
}

TEST_CASE("a texture outside the scene's folder is not read: its colour factor stands, and it is said", "[scene][security]") {
  const fs::path dir = test::output_dir("texture_outside");
  fs::create_directories(dir / "in");
  test::write_text(dir / "in" / "a.mtl", "newmtl a\nKd 0.2 0.4 0.6\nmap_Kd ../../../../../../../../../../etc/passwd\n");
  test::write_text(dir / "in" / "quad.obj", "mtllib a.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n");
  const auto r = test::run_hilight({"info", (dir / "in" / "quad.obj").string()});
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Contains("quad.obj") && Contains("outside the scene's folder"));
}
