#pragma once
/// Rasterizes which scene triangle is nearest the eye in each texel (an ID
/// buffer): the six cube faces around each light (its shadow map, and where
/// its VPLs land) and camera views (the G-buffer of images). Graphics
/// pipeline with depth test; the IDs are copied into a buffer for the compute
/// stages, which intersect their exact rays with the triangles found there.
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

/// One view's triangles: `count` triangles from `first` in the index buffer
/// (three indices each) and in the triangle-id buffer (one scene triangle each).
struct RasterDraw {
  uint32_t first = 0, count = 0;
};

class TriangleRaster {
public:
  /// `vertices`: the scene's world positions (vec3 floats), shared by the
  /// triangles, so the vertex stage runs once per vertex and view.
  TriangleRaster(VulkanContext& context, const Buffer& vertices, std::span<const uint32_t> vertex_spirv,
                 std::span<const uint32_t> fragment_spirv);
  ~TriangleRaster();
  TriangleRaster(const TriangleRaster&) = delete;
  TriangleRaster& operator=(const TriangleRaster&) = delete;

  /// Records one render pass drawing each view k (draws[k] of
  /// `indices`/`triangle_ids`) into tile k of an atlas, and the copies of
  /// the tiles into `triangles` (scene triangle + 1; 0 = nothing), tile by
  /// tile, row by row. The atlas is (re)made when its
  /// shape changes; at most max_views() views.
  void record(VkCommandBuffer cmd, std::span<const RasterView> views, std::span<const RasterDraw> draws, const Buffer& indices,
              const Buffer& triangle_ids, uint32_t width, uint32_t height, const Buffer& triangles);

  /// How many width x height views fit in one atlas on this device.
  static uint32_t max_views(VulkanContext& context, uint32_t width, uint32_t height);

private:
  static constexpr uint32_t kColumns = 6;  ///< atlas tiles per row (a light's cube faces)
  void make_targets(uint32_t width, uint32_t height);
  void release_targets();
  void release();

  VulkanContext& m_context;
  const Buffer& m_vertices;
  VkRenderPass m_pass = VK_NULL_HANDLE;
  VkDescriptorSetLayout m_set_layout = VK_NULL_HANDLE;
  VkPipelineLayout m_layout = VK_NULL_HANDLE;
  VkPipeline m_pipeline = VK_NULL_HANDLE;
  VkShaderModule m_vertex = VK_NULL_HANDLE, m_fragment = VK_NULL_HANDLE;
  DeviceImage m_triangle, m_depth;
  VkFramebuffer m_framebuffer = VK_NULL_HANDLE;
};

} // namespace hilight::ism
