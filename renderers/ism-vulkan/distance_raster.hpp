#pragma once
/// Rasterizes the scene into layers of (distance to the eye, triangle + 1):
/// the six cube faces around each light (its shadow map, and where its VPLs
/// land) and camera views (the G-buffer of images). Graphics pipeline with
/// depth test; the results are copied into buffers for the compute stages.
#include "vulkan_resources.hpp"
#include "hilight/math.hpp"

#include <span>
#include <vector>

namespace hilight::ism {

/// A pinhole view: a direction d from the eye lands at normalized device
/// coordinates (d·right, d·up) / (d·forward); right and up carry the scale.
struct RasterView {
  Vec3 eye, forward, right, up;
  float near_plane, far_plane;
};

/// The six 90° cube-face views around `eye` (faces as in shaders/common.glsl).
std::vector<RasterView> cube_views(const Vec3& eye, float near_plane, float far_plane);

class DistanceRaster {
public:
  /// `vertices`: world positions (vec3 floats); `indices`: three per triangle,
  /// in triangle order (shared vertices let the vertex stage run once per vertex).
  DistanceRaster(VulkanContext& context, const Buffer& vertices, const Buffer& indices, uint32_t triangle_count,
                 std::span<const uint32_t> vertex_spirv, std::span<const uint32_t> fragment_spirv);
  ~DistanceRaster();
  DistanceRaster(const DistanceRaster&) = delete;
  DistanceRaster& operator=(const DistanceRaster&) = delete;

  /// Records one render pass per view (view k into layer k) and the copies
  /// of all layers into `distances` (float) and `triangles` (uint), layer by
  /// layer, row by row. Render targets are (re)made when the shape changes.
  void record(VkCommandBuffer cmd, std::span<const RasterView> views, uint32_t width, uint32_t height,
              const Buffer& distances, const Buffer& triangles);

private:
  void make_targets(uint32_t width, uint32_t height, uint32_t layers);
  void release_targets();
  void release();

  VulkanContext& m_context;
  const Buffer& m_vertices;
  const Buffer& m_indices;
  uint32_t m_triangles;
  VkRenderPass m_pass = VK_NULL_HANDLE;
  VkPipelineLayout m_layout = VK_NULL_HANDLE;
  VkPipeline m_pipeline = VK_NULL_HANDLE;
  VkShaderModule m_vertex = VK_NULL_HANDLE, m_fragment = VK_NULL_HANDLE;
  DeviceImage m_distance, m_triangle, m_depth;
  std::vector<VkFramebuffer> m_framebuffers;
};

} // namespace hilight::ism
