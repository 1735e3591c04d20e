#include "hilight/real_model_scenes.hpp"

#include "hilight/error.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/scene_builders.hpp"

#include <algorithm>
#include <cstdlib>

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

} // namespace hilight::builders
