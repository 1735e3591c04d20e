// Scene loading and tessellation: formats, albedo, normals, determinism,
// crack-free refinement, and the bundled demo scene.
#include "hilight/error.hpp"
#include "hilight/io/image_io.hpp"
#include "hilight/io/tessellate.hpp"
#include "hilight/fixtures/scene_builders.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <map>

using namespace hilight;

namespace {

const std::string kRoom = std::string(HILIGHT_SOURCE_DIR) + "/scenes/room.obj";

float longest_edge(const Scene& s) {
  float longest = 0.f;
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) longest = std::max(longest, glm::length(s.positions[t[k]] - s.positions[t[(k + 1) % 3]]));
  return longest;
}

/// Every undirected edge of a closed, crack-free surface is used by exactly two triangles.
bool watertight(const Scene& s) {
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  for (const auto& [edge, count] : uses)
    if (count != 2) return false;
  return true;
}

/// A one-quad glTF 2.0 file (JSON + .bin) with a known baseColorFactor and,
/// optionally, a base-colour texture file.
void write_quad_gltf(const std::filesystem::path& dir, const char* color, const char* texture = nullptr) {
  const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1};
  const uint16_t idx[6] = {0, 2, 1, 0, 3, 2};
  std::ofstream bin(dir / "quad.bin", std::ios::binary);
  bin.write(reinterpret_cast<const char*>(pos), sizeof(pos));
  bin.write(reinterpret_cast<const char*>(idx), sizeof(idx));
  bin.close();
  test::write_text(dir / "quad.gltf", std::string(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],
"materials":[{"pbrMetallicRoughness":{"baseColorFactor":)") + color +
                                      (texture ? R"(,"baseColorTexture":{"index":0}}}],"textures":[{"source":0}],"images":[{"uri":")" +
                                                     std::string(texture) + R"("}],)"
                                               : std::string(R"(}}],)")) + R"(
"buffers":[{"byteLength":60,"uri":"quad.bin"}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":12}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,0,1]},
{"bufferView":1,"componentType":5123,"count":6,"type":"SCALAR"}]})");
}

} // namespace

TEST_CASE("the bundled room.obj is the furnished_room builder's scene", "[scene]") {
  Scene file = load_scene(kRoom, {0.5f});
  Scene built = finish_scene(builders::furnished_room(), {0.5f});
  CHECK(file.input_triangle_count == built.input_triangle_count);
  CHECK(file.triangles.size() == built.triangles.size());
  CHECK(file.bounds.lo == built.bounds.lo);
  CHECK(file.bounds.hi == built.bounds.hi);
  // Kd reaches the albedo: the first material listed is the walls.
  bool found_walls = false;
  for (const auto& m : file.materials)
    if (m.name.find("walls") != std::string::npos) {
      CHECK(m.albedo.r == Approx(0.75f));
      CHECK(m.albedo.b == Approx(0.70f));
      found_walls = true;
    }
  CHECK(found_walls);
}

TEST_CASE("tessellation keeps every edge within max-edge and the surface crack-free", "[scene][tessellate]") {
  for (float max_edge : {1.f, 0.37f, 0.1f}) {
    Scene s = finish_scene(builders::box_room({4.f, 3.f, 5.f}), {max_edge});
    INFO("max_edge " << max_edge);
    CHECK(longest_edge(s) <= max_edge * (1.f + 1e-5f));
    CHECK(s.triangles.size() > s.input_triangle_count);
    // A box's six faces have their own corner vertices (sharp edges), so check
    // crack-freedom per face: weld positions first.
    Scene welded = s;
    std::map<std::tuple<float, float, float>, uint32_t> ids;
    for (auto& t : welded.triangles)
      for (auto& v : t) {
        const Vec3& p = s.positions[v];
        v = ids.try_emplace({p.x, p.y, p.z}, uint32_t(ids.size())).first->second;
      }
    CHECK(watertight(welded));
  }
}

TEST_CASE("the same file and options give the same vertices in the same order", "[scene][tessellate]") {
  Scene a = load_scene(kRoom, {0.3f}), b = load_scene(kRoom, {0.3f});
  CHECK(a.positions == b.positions);
  CHECK(a.normals == b.normals);
  CHECK(a.triangles == b.triangles);
  CHECK(a.triangle_material == b.triangle_material);
  Scene c = load_scene(kRoom, {0.2f});
  CHECK(c.positions.size() > a.positions.size());
}

TEST_CASE("the default max-edge is a fortieth of the diagonal", "[scene][tessellate]") {
  Scene s = load_scene(kRoom);
  CHECK(s.max_edge == Approx(s.diagonal() / 40.f));
  CHECK(longest_edge(s) <= s.max_edge * 1.00001f);
}

TEST_CASE("normals are computed when the file has none, and albedo defaults to 0.8 grey", "[scene]") {
  auto dir = test::output_dir("scene_no_normals");
  test::write_text(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 0 -1\nf 1 2 3\n");
  Scene s = load_scene(dir / "tri.obj", {10.f});
  REQUIRE(s.triangles.size() == 1);
  for (const auto& n : s.normals) CHECK(glm::length(n - Vec3(0, 1, 0)) < 1e-5f);
  CHECK(s.triangle_albedo(0) == Rgb(0.8f));
}

TEST_CASE("glTF baseColorFactor becomes the albedo", "[scene][gltf]") {
  auto dir = test::output_dir("scene_gltf");
  write_quad_gltf(dir, "[0.2,0.4,0.6,1.0]");
  Scene s = load_scene(dir / "quad.gltf", {10.f});
  REQUIRE(s.input_triangle_count == 2);
  CHECK(s.triangle_albedo(0).r == Approx(0.2f));
  CHECK(s.triangle_albedo(0).g == Approx(0.4f));
  CHECK(s.triangle_albedo(0).b == Approx(0.6f));
}

TEST_CASE("a binary glTF (GLB) and a PLY from Debian's assimp-testmodels load", "[scene][gltf]") {
  const std::string glb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
  const std::string ply = "/usr/share/assimp/models/PLY/cube_binary.ply";
  if (!std::filesystem::exists(glb) || !std::filesystem::exists(ply)) {
    WARN("assimp-testmodels not installed: skipped");
    return;
  }
  CHECK(load_scene(glb).input_triangle_count == 12);
  CHECK(load_scene(ply).input_triangle_count == 12);
}

TEST_CASE("scenes with NaN coordinates, no triangles or no extent are refused with the file named", "[scene][bad-input]") {
  auto dir = test::output_dir("scene_bad");
  test::write_text(dir / "nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  test::write_text(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  CHECK_THROWS_WITH(load_scene(dir / "nan.obj"), Catch::Contains("nan.obj") && Catch::Contains("NaN"));
  CHECK_THROWS_WITH(load_scene(dir / "points.obj"), Catch::Contains("points.obj"));
  CHECK_THROWS_WITH(load_scene(dir / "missing.obj"), Catch::Contains("missing.obj: no such file"));
  CHECK_THROWS_AS(load_scene(dir), InputError);
  CHECK_THROWS_WITH(finish_scene(builders::plane(0.f), {}), Catch::Contains("no triangles of non-zero area") ||
                                                             Catch::Contains("zero extent"));
}

TEST_CASE("a max-edge that would explode the mesh is refused, not attempted", "[scene][bad-input]") {
  CHECK_THROWS_WITH(load_scene(kRoom, {1e-4f}), Catch::Contains("--max-edge") && Catch::Contains("limit"));
}

TEST_CASE("a base-colour texture is averaged into the albedo (linear light), times the factor", "[scene][texture]") {
  auto dir = test::output_dir("scene_texture");
  // An 8x8 texture of one known linear colour, written as sRGB PNG.
  Image texture(8, 8);
  for (size_t i = 0; i < texture.pixels.size(); ++i) {
    texture.pixels[i] = Rgb(0.2f, 0.4f, 0.6f);
    texture.covered[i] = 1;
  }
  write_image(dir / "tex.png", texture, 1.f);
  write_quad_gltf(dir, "[0.5,1.0,1.0,1.0]", "tex.png");
  Scene s = load_scene(dir / "quad.gltf", {10.f});
  CHECK(s.triangle_albedo(0).r == Approx(0.1f).epsilon(0.02));  // 0.5 × 0.2
  CHECK(s.triangle_albedo(0).g == Approx(0.4f).epsilon(0.02));
  CHECK(s.triangle_albedo(0).b == Approx(0.6f).epsilon(0.02));
  // A texture that cannot be read: the scene still loads, with the factor.
  write_quad_gltf(dir, "[0.5,1.0,1.0,1.0]", "missing.png");
  Scene t = load_scene(dir / "quad.gltf", {10.f});
  CHECK(t.triangle_albedo(0) == Rgb(0.5f, 1.f, 1.f));
}
