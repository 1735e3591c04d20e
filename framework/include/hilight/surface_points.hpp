#pragma once
/// The points at which illumination is evaluated: scene vertices, surface
/// samples, or target points bound to the surface. Structure of arrays.
#include "hilight/math.hpp"

#include <cstdint>
#include <vector>

namespace hilight {

struct Scene;

struct SurfacePoints {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  ///< unit shading normals
  std::vector<Rgb> albedo;

  size_t size() const { return positions.size(); }
  /// Content hash: renderers use it to reuse per-point-set work (bounce gathers).
  uint64_t content_key() const;

  /// Every vertex of the scene, in vertex order.
  static SurfacePoints from_vertices(const Scene& scene);
};

} // namespace hilight
