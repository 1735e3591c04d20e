#include "cube_culling.hpp"

#include <array>
#include <cmath>

namespace hilight::ism {

void cull_to_cube_faces(const Scene& scene, const Light& light, std::vector<uint32_t>& indices, std::vector<uint32_t>& ids,
                        std::vector<RasterDraw>& draws) {
  const Vec3& eye = light.position;
  const std::vector<RasterView> faces = cube_views(eye, 1.f, 2.f);
  // A face's directions lie within acos(1/√3) ≈ 54.74° of its centre: a spot
  // cone farther than that plus its cutoff from the centre cannot reach it.
  bool wanted[6] = {true, true, true, true, true, true};
  if (light.type == LightType::Spot && light.cutoff_deg < 90.f) {
    const float limit = std::cos(glm::radians(std::min(180.f, light.cutoff_deg + 54.8f)));
    for (int f = 0; f < 6; ++f) wanted[f] = glm::dot(light.direction, faces[f].forward) >= limit;
  }
  // Per vertex, 4 bits per face: outside each of the face pyramid's four
  // side planes (forward·d ≥ |right·d| and ≥ |up·d|).
  std::vector<uint32_t> outside(scene.positions.size());
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    const Vec3 d = scene.positions[v] - eye;
    uint32_t code = 0;
    for (uint32_t f = 0; f < 6; ++f) {
      const float a = glm::dot(d, faces[f].forward), r = glm::dot(d, faces[f].right), u = glm::dot(d, faces[f].up);
      code |= (uint32_t(a - r < 0.f) | uint32_t(a + r < 0.f) << 1 | uint32_t(a - u < 0.f) << 2 | uint32_t(a + u < 0.f) << 3) << (4 * f);
    }
    outside[v] = code;
  }
  // A triangle whose three vertices are outside one and the same plane cannot show.
  std::array<std::vector<uint32_t>, 6> per_face;
  for (uint32_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    const uint32_t common = outside[tri[0]] & outside[tri[1]] & outside[tri[2]];
    for (uint32_t f = 0; f < 6; ++f)
      if (wanted[f] && ((common >> (4 * f)) & 0xFu) == 0) per_face[f].push_back(t);
  }
  for (uint32_t f = 0; f < 6; ++f) {
    draws.push_back({uint32_t(ids.size()), uint32_t(per_face[f].size())});
    for (uint32_t t : per_face[f]) {
      ids.push_back(t);
      indices.insert(indices.end(), scene.triangles[t].begin(), scene.triangles[t].end());
    }
  }
}

} // namespace hilight::ism
