#include "hilight/real_model_scenes.hpp"

#include "hilight/error.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/scene_builders.hpp"

#include <array>
#include <cstdint>
#include <algorithm>
#include <cstdlib>
#include <functional>

namespace hilight::builders {

std::filesystem::path testmodels_dir() {
  if (const char* d = std::getenv("HILIGHT_TESTMODELS"); d && *d) return d;
  return "/usr/share/assimp/models";
}

Scene test_model(const std::string& relative_path) {
  const auto path = testmodels_dir() / relative_path;
  if (!std::filesystem::exists(path))
    throw InputError(path.string(), "test model missing (install Debian's assimp-testmodels: bash setup.sh deps)");
  // No tessellation here: the composed scene is tessellated once, as a whole.
  return load_scene(path, {1e30f});
}

void add_model(Scene& scene, const Scene& model, float x, float floor_y, float z, float size) {
  Bounds b;
  for (const auto& p : model.positions) b.extend(p);
  const Vec3 extent = b.hi - b.lo;
  const float scale = size / std::max({extent.x, extent.y, extent.z, 1e-30f});
  const Vec3 anchor((b.lo.x + b.hi.x) / 2, b.lo.y, (b.lo.z + b.hi.z) / 2);
  const uint32_t base = uint32_t(scene.positions.size()), material_base = uint32_t(scene.materials.size());
  for (size_t v = 0; v < model.positions.size(); ++v) {
    scene.positions.push_back((model.positions[v] - anchor) * scale + Vec3(x, floor_y, z));
    scene.normals.push_back(model.normals[v]);
  }
  for (size_t t = 0; t < model.triangles.size(); ++t) {
    const auto& tri = model.triangles[t];
    scene.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    scene.triangle_material.push_back(model.triangle_material[t] + material_base);
  }
  scene.materials.insert(scene.materials.end(), model.materials.begin(), model.materials.end());
}

Scene curved_models_on_floor() {
  Scene scene;
  scene.source = "builtin:curved_models_on_floor";
  add_quad(scene, {-2.f, 0.f, -2.f}, {-2.f, 0.f, 2.f}, {2.f, 0.f, 2.f}, {2.f, 0.f, -2.f}, Rgb(0.7f), "floor");
  add_quad(scene, {-2.f, 0.f, -2.f}, {2.f, 0.f, -2.f}, {2.f, 2.5f, -2.f}, {-2.f, 2.5f, -2.f}, Rgb(0.75f, 0.72f, 0.68f), "wall");
  add_model(scene, test_model("OBJ/WusonOBJ.obj"), -0.8f, 0.f, 0.f, 1.4f);
  add_model(scene, test_model("OBJ/spider.obj"), 0.9f, 0.f, 0.2f, 1.3f);
  return scene;
}

Scene real_furnished_room() {
  Scene scene;
  scene.source = "builtin:real_furnished_room";
  add_box(scene, {0.f, 0.f, 0.f}, {6.f, 3.f, 5.f}, Rgb(0.75f, 0.73f, 0.70f), true, "walls");
  add_table(scene);
  add_box(scene, {4.6f, 0.f, 0.3f}, {5.7f, 1.2f, 0.9f}, Rgb(0.3f, 0.45f, 0.6f), false, "cabinet");
  add_model(scene, test_model("OBJ/WusonOBJ.obj"), 2.f, 0.78f, 1.9f, 0.6f);
  add_model(scene, test_model("OBJ/spider.obj"), 4.2f, 0.f, 3.3f, 0.9f);
  add_model(scene, test_model("glTF/CesiumMilkTruck/CesiumMilkTruck.gltf"), 1.4f, 0.f, 4.f, 1.2f);
  add_model(scene, test_model("3DS/fels.3ds"), 5.15f, 1.2f, 0.6f, 0.5f);
  return scene;
}

BuiltScene engine_product() {
  BuiltScene b;
  b.name = "engine";
  b.scene = test_model("glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  Bounds box;
  for (const auto& p : b.scene.positions) box.extend(p);
  const Vec3 c = box.center(), half = 0.5f * box.extent();
  const float d = glm::length(box.extent());
  // A ring of zones a quarter diagonal beyond the sides, above the top: in
  // the open space the solve searches (half a diagonal beyond open sides).
  for (int k = 0; k < 6; ++k) {
    const float a = 2.f * float(kPi) * float(k) / 6.f;
    const Vec3 centre(c.x + std::cos(a) * (half.x + 0.25f * d), c.y + half.y + 0.1f * d, c.z + std::sin(a) * (half.z + 0.25f * d));
    b.zones.push_back({centre - Vec3(0.08f * d), centre + Vec3(0.08f * d)});
  }
  b.far_lights = true;
  return b;
}

namespace {

/// Appends the triangles of `model` that `keep` takes, clipped to y <= `cut`
/// (a triangle across the plane keeps its part below, as one or two
/// triangles; normals interpolated along the cut edges). Materials come along.
void add_below(Scene& out, const Scene& model, float cut, const std::function<bool(size_t)>& keep) {
  const uint32_t material_base = uint32_t(out.materials.size());
  out.materials.insert(out.materials.end(), model.materials.begin(), model.materials.end());
  std::vector<uint32_t> index(model.positions.size(), UINT32_MAX);
  auto shared = [&](uint32_t v) {
    if (index[v] == UINT32_MAX) {
      index[v] = uint32_t(out.positions.size());
      out.positions.push_back(model.positions[v]);
      out.normals.push_back(model.normals[v]);
    }
    return index[v];
  };
  for (size_t t = 0; t < model.triangles.size(); ++t) {
    if (!keep(t)) continue;
    const auto& tri = model.triangles[t];
    const uint32_t material = model.triangle_material[t] + material_base;
    int below = 0;
    for (uint32_t v : tri) below += model.positions[v].y <= cut;
    if (below == 0) continue;
    if (below == 3) {
      out.triangles.push_back({shared(tri[0]), shared(tri[1]), shared(tri[2])});
      out.triangle_material.push_back(material);
      continue;
    }
    // Sutherland–Hodgman against the one plane: 3 or 4 corners, fanned.
    std::vector<std::pair<Vec3, Vec3>> corners;
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = model.positions[tri[k]], &b = model.positions[tri[(k + 1) % 3]];
      const Vec3 &na = model.normals[tri[k]], &nb = model.normals[tri[(k + 1) % 3]];
      if (a.y <= cut) corners.emplace_back(a, na);
      if ((a.y <= cut) != (b.y <= cut)) {
        const float s = (cut - a.y) / (b.y - a.y);
        corners.emplace_back(Vec3(a.x + s * (b.x - a.x), cut, a.z + s * (b.z - a.z)), glm::normalize(na + s * (nb - na)));
      }
    }
    const uint32_t base = uint32_t(out.positions.size());
    for (const auto& [p, n] : corners) out.positions.push_back(p), out.normals.push_back(n);
    for (uint32_t k = 1; k + 1 < corners.size(); ++k) {
      out.triangles.push_back({base, base + k, base + k + 1});
      out.triangle_material.push_back(material);
    }
  }
}

/// A table: a top [lo, hi] in x and z at `height` (4 cm thick), four legs.
void add_table_at(Scene& s, float x0, float z0, float x1, float z1, float height, const Rgb& wood) {
  add_box(s, Vec3(x0, height - 0.04f, z0), Vec3(x1, height, z1), wood, false, "table top");
  for (float x : {x0 + 0.05f, x1 - 0.1f})
    for (float z : {z0 + 0.05f, z1 - 0.1f}) add_box(s, Vec3(x, 0.f, z), Vec3(x + 0.05f, height - 0.04f, z + 0.05f), wood, false, "table leg");
}

/// A chair: a seat 0.45 high, a back on the side `back` (+1: +z, -1: -z).
void add_chair(Scene& s, float x, float z, float back, const Rgb& wood) {
  add_box(s, Vec3(x - 0.22f, 0.f, z - 0.22f), Vec3(x + 0.22f, 0.45f, z + 0.22f), wood, false, "chair");
  const float zb = z + back * 0.2f;
  add_box(s, Vec3(x - 0.22f, 0.45f, std::min(zb, zb + back * 0.04f)), Vec3(x + 0.22f, 0.9f, std::max(zb, zb + back * 0.04f)), wood, false,
          "chair back");
}

/// A real model placed as add_model places it, its albedos kept at most 0.8
/// (a white default material would be a mirror-bright statue).
void add_real(Scene& s, const std::string& file, float x, float floor_y, float z, float size) {
  const size_t first = s.materials.size();
  add_model(s, test_model(file), x, floor_y, z, size);
  for (size_t m = first; m < s.materials.size(); ++m) s.materials[m].albedo = glm::min(s.materials[m].albedo, Rgb(0.8f));
}

} // namespace

BuiltScene furnished_home() {
  BuiltScene b;
  b.name = "home";
  Scene& s = b.scene;
  s.source = "builtin:furnished_home";
  // The house's ground floor, up to the top of the upper floor's slab.
  constexpr float kCut = 2.7f, kCeiling = 2.5f;
  const Scene house = test_model("IFC/AC14-FZK-Haus.ifc");
  // The leaves of the three inner doors (the doorways stay, with their frames).
  const Bounds leaves[] = {{Vec3(1.6f, -0.01f, -5.86f), Vec3(6.1f, 1.97f, -5.80f)}, {Vec3(7.40f, -0.01f, -5.41f), Vec3(7.47f, 1.97f, -4.59f)}};
  add_below(s, house, kCut, [&](size_t t) {
    const std::string& name = house.materials[house.triangle_material[t]].name;
    if (name == "Erde") return false;  // the terrain around the house
    if (name.rfind("Kiefer,gl", 0) != 0) return true;
    for (const Bounds& leaf : leaves) {
      bool inside = true;
      for (uint32_t v : house.triangles[t]) inside &= leaf.contains(house.positions[v]);
      if (inside) return false;
    }
    return true;
  });
  // A flat roof slab over the storey (it closes the stair's opening).
  add_box(s, Vec3(0.f, kCut, -10.f), Vec3(12.f, kCut + 0.2f, 0.f), Rgb(0.6f), false, "roof slab");

  const Rgb wood(0.55f, 0.4f, 0.28f), dark(0.35f, 0.25f, 0.18f), fabric(0.45f, 0.5f, 0.6f), white(0.78f, 0.77f, 0.74f);
  // Living room (x 0.3–11.7, z -4.0 to -0.3; the stair at x 6.6–8.3).
  add_box(s, Vec3(0.8f, 0.f, -1.2f), Vec3(3.0f, 0.42f, -0.35f), fabric, false, "sofa");
  add_box(s, Vec3(0.8f, 0.42f, -0.6f), Vec3(3.0f, 0.85f, -0.35f), fabric, false, "sofa back");
  for (float x : {0.8f, 2.8f}) add_box(s, Vec3(x, 0.42f, -1.2f), Vec3(x + 0.2f, 0.62f, -0.6f), fabric, false, "sofa arm");
  add_table_at(s, 1.3f, -2.3f, 2.5f, -1.7f, 0.45f, dark);
  add_real(s, "OBJ/WusonOBJ.obj", 1.9f, 0.45f, -2.0f, 0.4f);
  add_box(s, Vec3(0.3f, 0.f, -3.6f), Vec3(0.75f, 0.6f, -2.0f), white, false, "sideboard");
  add_real(s, "3DS/fels.3ds", 0.52f, 0.6f, -2.8f, 0.35f);
  add_table_at(s, 9.2f, -3.3f, 10.8f, -2.3f, 0.76f, wood);
  for (float x : {9.6f, 10.4f}) add_chair(s, x, -3.65f, -1.f, wood), add_chair(s, x, -1.95f, 1.f, wood);
  add_real(s, "MS3D/jeep1.ms3d", 10.0f, 0.76f, -2.8f, 0.35f);
  add_box(s, Vec3(11.25f, 0.f, -3.4f), Vec3(11.7f, 0.75f, -1.6f), white, false, "sideboard");
  add_real(s, "PLY/Wuson.ply", 11.47f, 0.75f, -2.5f, 0.4f);
  add_real(s, "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", 4.6f, 0.f, -2.4f, 0.7f);
  // Hall (z -5.75 to -4.25): a bench for shoes.
  add_box(s, Vec3(1.2f, 0.f, -5.75f), Vec3(2.4f, 0.45f, -5.4f), wood, false, "hall bench");
  // North-west room (the house's table at x 0.3–1.6): a bookshelf, the spider.
  add_box(s, Vec3(2.6f, 0.f, -9.7f), Vec3(3.75f, 2.0f, -9.35f), dark, false, "bookshelf");
  add_chair(s, 1.0f, -7.9f, 1.f, wood);
  add_real(s, "OBJ/spider.obj", 2.4f, 0.f, -7.4f, 0.8f);
  // Middle room: a desk, a chair, a wardrobe.
  add_table_at(s, 4.3f, -9.7f, 5.7f, -9.0f, 0.76f, wood);
  add_chair(s, 5.0f, -8.6f, 1.f, wood);
  add_box(s, Vec3(6.75f, 0.f, -9.7f), Vec3(7.41f, 2.1f, -8.1f), white, false, "wardrobe");
  add_real(s, "OBJ/WusonOBJ.obj", 4.7f, 0.76f, -9.35f, 0.3f);
  // North-east room (the house's bed at x 7.7–9.7): a wardrobe, a nightstand.
  add_box(s, Vec3(10.95f, 0.f, -9.7f), Vec3(11.7f, 2.1f, -7.9f), white, false, "wardrobe");
  add_box(s, Vec3(7.7f, 0.f, -9.2f), Vec3(8.2f, 0.5f, -8.7f), dark, false, "nightstand");

  // Ceiling lamps hang 0.15–0.4 m under the ceiling, away from the walls
  // (the living room in two, either side of the stair's opening).
  const float lamp_lo = kCeiling - 0.4f, lamp_hi = kCeiling - 0.15f;
  for (const auto& [x0, z0, x1, z1] : {std::array<float, 4>{0.8f, -3.5f, 6.0f, -0.8f}, std::array<float, 4>{8.8f, -3.5f, 11.2f, -0.8f},
                                       std::array<float, 4>{0.8f, -5.3f, 3.3f, -4.7f}, std::array<float, 4>{0.8f, -9.2f, 3.3f, -6.5f},
                                       std::array<float, 4>{4.5f, -9.2f, 6.9f, -6.5f}, std::array<float, 4>{8.1f, -9.2f, 11.2f, -4.8f}})
    b.zones.push_back({Vec3(x0, lamp_lo, z0), Vec3(x1, lamp_hi, z1)});
  return b;
}

} // namespace hilight::builders
