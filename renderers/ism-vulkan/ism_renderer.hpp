#pragma once
/// The ism-vulkan renderer: direct light from cube shadow maps, the first
/// bounce from virtual point lights with imperfect shadow maps (Ritschel et
/// al. 2008), all on one Vulkan device (lavapipe when there is no GPU).
/// How a batch of lights flows through the stages: docs/ism-vulkan.md.
#include "bounce_transport.hpp"
#include "compute_kernel.hpp"
#include "triangle_raster.hpp"
#include "ism_settings.hpp"
#include "scene_buffers.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/renderer.hpp"

#include <map>
#include <memory>
#include <mutex>

namespace hilight::ism {

class IsmRenderer final : public Renderer {
public:
  explicit IsmRenderer(const IsmSettings& settings);
  ~IsmRenderer() override;

  void set_scene(std::shared_ptr<const Scene> scene) override;
  std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) override;
  std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                  Transport transport = Transport::All) override;
  std::string settings_key() const override { return m_settings.key(); }
  Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) override;
  /// Seconds per stage of one profiled unit_responses call (each stage
  /// submitted and waited for on its own).
  std::vector<std::pair<std::string, double>> baseline_figures(const SurfacePoints& points,
                                                               std::span<const Light> lights) override;
  std::string device_description() const { return m_context->description(); }

private:
  struct PointBuffers;
  struct Bounces;
  struct Workspace;
  struct Kernels;
  class StageClock;

  /// Which bounces a call carries: as the settings say, up to the first
  /// (the images' pixels), or only the later ones (the images' vertices).
  enum class Later { Included, Excluded, Only };
  /// unit_responses, with `later` (area and line sources as their parts).
  std::vector<Rgb> responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport, Later later);
  /// unit_responses for point-like lights (point, spot, luminaire).
  std::vector<Rgb> point_responses(const SurfacePoints& points, std::span<const Light> lights, Transport transport, Later later);

  /// The points on the device (shading points, normals, albedo), kept while the same set comes back.
  const PointBuffers& upload_points(const SurfacePoints& points);
  std::unique_ptr<PointBuffers> make_point_buffers(const SurfacePoints& points);
  /// More than one bounce asked for (bounces ≥ 2 or all).
  bool every_bounce_path() const { return m_settings.bounces != 0 && m_settings.bounces != 1; }
  /// The bounce points and their transport, made on the first call that needs them.
  const Bounces& bounces();
  /// The gather rows of receivers [first, first + count) of `pb`, both sides
  /// each, from their hemisphere maps of the bounce points (bounce_splat.comp).
  GatherRows bounce_rows(const PointBuffers& pb, size_t first, size_t count);
  /// d₁ + … + d_{B−1} at the bounce points for one chunk of lights, from
  /// their direct light in the workspace (BounceSeries::bounced).
  std::vector<Rgb> later_bounce_field(std::span<const Light> lights, const Workspace& ws);
  /// Adds bounces 2..B of `lights` lights (their fields, light-major) to
  /// `out` (light-major, as unit_responses): the points' maps are made once
  /// per call, or kept with a small point set.
  void gather_later_bounces(const SurfacePoints& points, const PointBuffers& pb, const std::vector<Rgb>& field, size_t lights,
                            Rgb* out);
  Workspace& workspace(uint32_t lights_per_chunk, size_t point_count);
  /// The shadow maps' culled triangle lists for `lights`, written into the
  /// workspace (grown as needed); returns one draw per cube face.
  std::vector<RasterDraw> upload_face_triangles(std::span<const Light> lights, Workspace& ws);
  uint32_t lights_per_chunk(size_t light_count, size_t point_count) const;
  /// Records the whole pipeline for one chunk of lights into `cmd`.
  void record_chunk(VkCommandBuffer cmd, const PointBuffers& points, std::span<const Light> lights, Transport transport, Later later,
                    Workspace& ws, StageClock& clock);
  void begin_commands(VkCommandBuffer cmd);
  void submit_and_wait(VkCommandBuffer cmd);

  IsmSettings m_settings;
  std::unique_ptr<VulkanContext> m_context;
  std::shared_ptr<const Scene> m_scene;
  std::shared_ptr<const RayScene> m_rays;
  std::unique_ptr<SceneBuffers> m_buffers;
  std::unique_ptr<TriangleRaster> m_raster;
  std::unique_ptr<Kernels> m_kernels;
  std::unique_ptr<PointBuffers> m_points;
  std::unique_ptr<Bounces> m_bounces;
  std::unique_ptr<SurfacePoints> m_vertices;  ///< the scene's vertices, albedo 1 (images' later bounces)
  std::unique_ptr<PointBuffers> m_vertex_buffers;
  std::unique_ptr<Workspace> m_workspace;
  std::unique_ptr<StageClock> m_clock;
  VkCommandBuffer m_cmd = VK_NULL_HANDLE;
  VkFence m_fence = VK_NULL_HANDLE;
  std::mutex m_mutex;  ///< one queue: calls (possibly from several solver threads) take turns
};

} // namespace hilight::ism
