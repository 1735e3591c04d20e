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

Bounds Scene::light_bounds() const {
  // Only flat axes grow: a room keeps its walls (a light outside them would
  // "light" their outer sides), a floor with low objects gets height — on
  // the side its surfaces face, when most of their area faces one way (a
  // light under an open floor would only light its underside).
  Bounds b = bounds;
  const float flat = 0.25f * diagonal(), grown = 0.5f * diagonal();
  Vec3 facing(0.f), area(0.f);
  for (size_t t = 0; t < triangles.size(); ++t) {
    const Vec3 &p0 = positions[triangles[t][0]], &p1 = positions[triangles[t][1]], &p2 = positions[triangles[t][2]];
    const Vec3 n = glm::cross(p1 - p0, p2 - p0);  // length: twice the area
    facing += n;
    area += glm::abs(n);
  }
  for (int k = 0; k < 3; ++k) {
    float extent = b.hi[k] - b.lo[k];
    if (extent >= flat) continue;
    const float lean = area[k] > 0.f ? facing[k] / area[k] : 0.f;  // +1: all face +k
    if (lean > 0.5f) b.hi[k] += grown - extent;
    else if (lean < -0.5f) b.lo[k] -= grown - extent;
    else {
      b.lo[k] -= 0.5f * (grown - extent);
      b.hi[k] += 0.5f * (grown - extent);
    }
  }
  return b;
}

void Scene::update_bounds() {
  bounds = Bounds{};
  for (const auto& p : positions) bounds.extend(p);
}

} // namespace hilight
