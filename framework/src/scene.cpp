#include "hilight/scene.hpp"

namespace hilight {

std::vector<Rgb> Scene::vertex_albedo() const {
  std::vector<Rgb> albedo(positions.size(), Rgb(0.8f));
  std::vector<char> set(positions.size(), 0);
  for (size_t t = 0; t < triangles.size(); ++t)
    for (uint32_t v : triangles[t])
      if (!set[v]) {
        albedo[v] = triangle_albedo(t);
        set[v] = 1;
      }
  return albedo;
}

Vec3 Scene::face_normal(size_t t) const {
  const auto& tri = triangles[t];
  Vec3 n = glm::cross(positions[tri[1]] - positions[tri[0]], positions[tri[2]] - positions[tri[0]]);
  float len = glm::length(n);
  return len > 0.f ? n / len : Vec3(0.f, 0.f, 1.f);
}


void Scene::update_bounds() {
  bounds = Bounds{};
  for (const auto& p : positions) bounds.extend(p);
}

} // namespace hilight
