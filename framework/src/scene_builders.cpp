#include "hilight/scene_builders.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace hilight::builders {

namespace {
uint32_t add_material(Scene& scene, const Rgb& albedo, const std::string& name) {
  scene.materials.push_back({name, albedo});
  return uint32_t(scene.materials.size() - 1);
}

// Adds a quad whose vertices are its own (flat normal), so corners stay sharp.
void push_quad(Scene& scene, const Vec3 (&c)[4], uint32_t material) {
  Vec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
  uint32_t base = uint32_t(scene.positions.size());
  for (const auto& p : c) {
    scene.positions.push_back(p);
    scene.normals.push_back(n);
  }
  scene.triangles.push_back({base, base + 1, base + 2});
  scene.triangles.push_back({base, base + 2, base + 3});
  scene.triangle_material.push_back(material);
  scene.triangle_material.push_back(material);
}
} // namespace

void add_quad(Scene& scene, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Rgb& albedo,
              const std::string& name) {
  push_quad(scene, {a, b, c, d}, add_material(scene, albedo, name));
}

void add_box(Scene& scene, const Vec3& lo, const Vec3& hi, const Rgb& albedo, bool inward, const std::string& name) {
  uint32_t m = add_material(scene, albedo, name);
  auto corner = [&](int i) { return Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
  // Each face listed counter-clockwise seen from outside (outward normal).
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    Vec3 q[4] = {corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3])};
    if (inward) std::swap(q[1], q[3]);
    push_quad(scene, q, m);
  }
}

Scene plane(float half_size, const Rgb& albedo) {
  Scene scene;
  scene.source = "builtin:plane";
  float h = half_size;
  add_quad(scene, {-h, 0.f, -h}, {-h, 0.f, h}, {h, 0.f, h}, {h, 0.f, -h}, albedo, "floor");
  return scene;
}

Scene box_room(const Vec3& size, const Rgb& albedo) {
  Scene scene;
  scene.source = "builtin:box_room";
  add_box(scene, Vec3(0.f), size, albedo, true, "walls");
  return scene;
}

Scene sphere(float radius, int subdivisions, bool inward, const Rgb& albedo) {
  Scene scene;
  scene.source = "builtin:sphere";
  scene.materials.push_back({"sphere", albedo});
  const float t = (1.f + std::sqrt(5.f)) / 2.f;
  std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                                            {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for (auto& p : v) p = glm::normalize(p);
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      auto key = std::minmax(a, b);
      auto [it, inserted] = mid.try_emplace(key, uint32_t(v.size()));
      if (inserted) v.push_back(glm::normalize(v[a] + v[b]));
      return it->second;
    };
    std::vector<std::array<uint32_t, 3>> next;
    for (const auto& tri : f) {
      uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]), ca = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = std::move(next);
  }
  for (const auto& p : v) {
    scene.positions.push_back(p * radius);
    scene.normals.push_back(inward ? -p : p);
  }
  for (auto tri : f) {
    if (inward) std::swap(tri[1], tri[2]);
    scene.triangles.push_back(tri);
    scene.triangle_material.push_back(0);
  }
  return scene;
}

void add_table(Scene& scene) {
  add_box(scene, {1.2f, 0.72f, 1.4f}, {2.8f, 0.78f, 2.4f}, Rgb(0.55f, 0.35f, 0.2f), false, "table_top");
  for (float x : {1.3f, 2.6f})
    for (float z : {1.5f, 2.2f}) add_box(scene, {x, 0.f, z}, {x + 0.1f, 0.72f, z + 0.1f}, Rgb(0.45f, 0.3f, 0.18f), false, "table_leg");
}

Scene furnished_room() {
  Scene scene;
  scene.source = "builtin:furnished_room";
  add_box(scene, {0.f, 0.f, 0.f}, {6.f, 3.f, 5.f}, Rgb(0.75f, 0.73f, 0.70f), true, "walls");
  add_table(scene);
  add_box(scene, {4.6f, 0.f, 0.3f}, {5.7f, 1.9f, 0.9f}, Rgb(0.3f, 0.45f, 0.6f), false, "cabinet");
  add_box(scene, {3.4f, 0.f, 3.6f}, {5.2f, 0.45f, 4.3f}, Rgb(0.6f, 0.2f, 0.2f), false, "bench");
  add_box(scene, {0.8f, 0.f, 3.8f}, {1.2f, 3.f, 4.2f}, Rgb(0.8f, 0.8f, 0.78f), false, "pillar");
  return scene;
}

Scene open_plan_office(float width, float depth) {
  Scene scene;
  scene.source = "builtin:open_plan_office";
  add_box(scene, {0.f, 0.f, 0.f}, {width, 3.f, depth}, Rgb(0.7f, 0.7f, 0.68f), true, "walls");
  int desk = 0;
  for (float z = 1.5f; z + 0.8f <= depth - 1.f; z += 2.f)
    for (float x = 1.5f; x + 1.6f <= width - 1.f; x += 2.4f)
      add_box(scene, {x, 0.f, z}, {x + 1.6f, 0.75f, z + 0.8f}, Rgb(0.55f, 0.45f, 0.35f), false, "desk " + std::to_string(desk++));
  for (float x = 1.f; x + 1.2f <= width - 1.f; x += 4.f)
    add_box(scene, {x, 0.f, 0.f}, {x + 1.2f, 1.2f, 0.45f}, Rgb(0.4f, 0.4f, 0.45f), false, "cabinet");
  return scene;
}

} // namespace hilight::builders
