#include "core/region.hpp"

#include <algorithm>

namespace hilight::painter {

std::optional<SurfacePick> pick_near(const RayScene& rays, const Vec3& p) { return pick_near(rays, p, nullptr); }

std::optional<SurfacePick> pick_near(const RayScene& rays, const Vec3& p, const Visibility* visible) {
  Hit hit = rays.closest_point(p, 0.01f * rays.scene().diagonal());
  if (!hit.valid()) return std::nullopt;
  const Vec3 position = rays.hit_position(hit);
  if (visible && !visible->point(hit.triangle, position)) return std::nullopt;
  return SurfacePick{position, rays.hit_normal(hit)};
}

std::vector<VertexDistance> vertices_in_dab(const Scene& scene, const SurfacePick& centre, float radius) {
  std::vector<VertexDistance> result;
  const float r2 = radius * radius;
  for (uint32_t v = 0; v < scene.positions.size(); ++v) {
    Vec3 d = scene.positions[v] - centre.position;
    float d2 = glm::dot(d, d);
    if (d2 > r2 || glm::dot(scene.normals[v], centre.normal) <= 0.f) continue;
    result.push_back({v, std::sqrt(d2)});
  }
  return result;
}

std::vector<uint32_t> region_vertices(const RayScene& rays, const std::vector<Vec3>& points, float radius) {
  std::vector<uint32_t> result;
  for (const Vec3& p : points) {
    auto pick = pick_near(rays, p);
    if (!pick) continue;
    for (const auto& vd : vertices_in_dab(rays.scene(), *pick, radius)) result.push_back(vd.vertex);
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

Vec3 centroid(const std::vector<Vec3>& points) {
  DVec3 sum(0.0);
  for (const Vec3& p : points) sum += DVec3(p);
  return points.empty() ? Vec3(0.f) : Vec3(sum / double(points.size()));
}

} // namespace hilight::painter
