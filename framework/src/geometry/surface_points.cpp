#include "hilight/surface_points.hpp"

#include "hilight/hash.hpp"
#include "hilight/scene.hpp"

#include <cstring>

namespace hilight {


uint64_t SurfacePoints::content_key() const {
  uint64_t h = kFnvOffset;
  h = hash_words(h, positions.data(), positions.size() * sizeof(Vec3));
  h = hash_words(h, normals.data(), normals.size() * sizeof(Vec3));
  h = hash_words(h, albedo.data(), albedo.size() * sizeof(Rgb));
  return h;
}

SurfacePoints SurfacePoints::from_vertices(const Scene& scene) {
  SurfacePoints points;
  points.positions = scene.positions;
  points.normals = scene.normals;
  points.albedo = scene.vertex_albedo();
  return points;
}

} // namespace hilight
