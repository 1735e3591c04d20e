#pragma once
/// The POV-Ray reference renderer: exports the scene (io/pov_export) and runs
/// the real `povray`. Per-point illumination is baked with `mesh_camera`:
/// one tiny camera triangle per point, just off the surface along its normal,
/// its single ray aimed back at the point (docs/povray.md).
#include "hilight/io/pov_export.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/renderer.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace hilight::povray {

struct PovraySettings {
  PovSettings pov;
  double timeout_seconds = 600;
  std::string executable;
};

class PovrayRenderer final : public Renderer {
public:
  explicit PovrayRenderer(PovraySettings settings) : m_settings(std::move(settings)) {}

  void set_scene(std::shared_ptr<const Scene> scene) override;
  std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) override;
  std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                  Transport transport = Transport::All) override;
  Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) override;
  std::string settings_key() const override;

private:
  /// Radiance at the points under `lights`, from one POV-Ray run.
  std::vector<Rgb> bake(const SurfacePoints& points, std::span<const Light> lights, int bounces);
  /// Direct light at every point through two receivers (docs/povray.md):
  /// one POV-Ray run, and one more per light that some point's own wedge
  /// blocks (rendering model), with that point's receiver dark.
  std::vector<Rgb> bake_direct(const SurfacePoints& points, std::span<const Light> lights);
  /// One run, the points shaded `at`; `dark` (2 per point, empty: none) are receivers left black.
  std::vector<Rgb> bake_direct_run(const SurfacePoints& points, const std::vector<Vec3>& at, std::span<const Light> lights,
                                   const std::vector<uint8_t>& dark);
  /// Every point baked on the mesh itself (the side its normal points to), one run.
  std::vector<Rgb> bake_on_mesh(const SurfacePoints& points, std::span<const Light> lights, int bounces);
  /// Runs bake.pov in `folder` into a one-row image of `pixels`.
  Image run_bake(const std::filesystem::path& folder, size_t pixels) const;
  /// Scale for light colours so that baked values sit where half floats are precise.
  float exposure_scale(std::span<const Light> lights) const;

  PovraySettings m_settings;
  /// The scene as POV-Ray sees it: scaled by m_pov_scale, a power of two
  /// (exact in floats) that puts its size in [8, 16). POV-Ray's tolerances
  /// are absolute (it ignores shadow hits closer than 1e-3); there they lie
  /// below hilight's step off creases (RayScene::shading_step: 2.4e-3 to
  /// 4.8e-3) whatever the scene's own scale. Larger, POV-Ray's shading of
  /// curved meshes drifts from the oracle (measured: 2.1% at [8, 16), 2.9%
  /// at [16, 32), 4.0% at [64, 128)).
  std::shared_ptr<const Scene> m_scene;
  float m_pov_scale = 1.f;
  std::shared_ptr<const RayScene> m_rays;
  /// Points and lights into POV-Ray's scale: positions × s, intensities × s²
  /// (so the irradiance I/d² at every point stays the same).
  SurfacePoints to_pov(const SurfacePoints& points) const;
  Lighting to_pov(std::span<const Light> lights) const;
};

} // namespace hilight::povray
