#include "core/vertex_points.hpp"

namespace hilight::painter {

SurfacePoints points_of_vertices(const Scene& scene, const std::vector<uint32_t>& vertices) {
  const std::vector<Rgb> albedo = scene.vertex_albedo();
  SurfacePoints points;
  for (uint32_t v : vertices) {
    points.positions.push_back(scene.positions[v]);
    points.normals.push_back(scene.normals[v]);
    points.albedo.push_back(albedo[v]);
  }
  return points;
}

} // namespace hilight::painter
