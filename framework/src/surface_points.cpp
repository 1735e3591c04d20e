#include "hilight/surface_points.hpp"

#include "hilight/scene.hpp"

#include <cstring>

namespace hilight {

namespace {
// FNV-1a over the raw floats: cheap, and any change of any point changes it.
uint64_t fnv1a(uint64_t hash, const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ull;
  }
  return hash;
}
} // namespace

uint64_t SurfacePoints::content_key() const {
  uint64_t h = 1469598103934665603ull;
  h = fnv1a(h, positions.data(), positions.size() * sizeof(Vec3));
  h = fnv1a(h, normals.data(), normals.size() * sizeof(Vec3));
  h = fnv1a(h, albedo.data(), albedo.size() * sizeof(Rgb));
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
