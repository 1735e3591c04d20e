#pragma once
/// The scene on the device, made once per scene: vertices and indices for the
/// raster, per-triangle corners, planes' neighbours and albedo for the
/// compute stages, and the ISMs' pool of surface samples.
#include "vulkan_resources.hpp"
#include "hilight/scene.hpp"

#include <memory>

namespace hilight::ism {

struct SceneBuffers {
  Buffer vertices;         ///< vec3 positions (vertex input)
  Buffer indices;          ///< three per triangle (index input)
  Buffer identity_ids;     ///< triangle t -> t (a draw of every triangle)
  Buffer corners;          ///< nine floats per triangle: its corners
  Buffer neighbours;       ///< three per triangle: across each edge (~0u: none)
  Buffer triangle_albedo;  ///< vec4 per triangle
  Buffer pool;             ///< vec4 area-uniform surface samples, in random order

  /// InputError for scenes with no triangles, no area, or too many triangles.
  SceneBuffers(VulkanContext& context, const Scene& scene, uint32_t pool_size, uint64_t seed);
};

/// For each triangle, the triangle across each of its edges (~0u: none).
std::vector<uint32_t> edge_neighbours(const Scene& scene);

} // namespace hilight::ism
