#pragma once
/// The renderer interface: illumination of surface points under a lighting,
/// the batch of unit-light responses φ the solver lives on, and images.
/// Module boundaries are at batch granularity: one call per set of lights,
/// never per ray or per point.
#include "hilight/camera.hpp"
#include "hilight/image.hpp"
#include "hilight/lighting.hpp"
#include "hilight/surface_points.hpp"

#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace hilight {

struct Scene;

/// Which light paths a call computes (the light cache wants them apart).
enum class Transport { All, DirectOnly, IndirectOnly };

class Renderer {
public:
  virtual ~Renderer() = default;

  /// Binds the scene (builds acceleration structures). Must precede the rest.
  virtual void set_scene(std::shared_ptr<const Scene> scene) = 0;

  /// Outgoing radiance (RGB) at every point under all `lights` together.
  virtual std::vector<Rgb> illuminate(const SurfacePoints& points, std::span<const Light> lights) = 0;

  /// φ: the response of each light with unit white intensity (its own
  /// intensity is ignored; type, position, direction and cone are used).
  /// Result is light-major: element [j * points.size() + i].
  virtual std::vector<Rgb> unit_responses(const SurfacePoints& points, std::span<const Light> lights,
                                          Transport transport = Transport::All) = 0;

  /// A string that changes whenever the renderer's settings change its
  /// results (used to key caches of its output on disk).
  virtual std::string settings_key() const = 0;

  /// An image of the scene from `camera`, shaded by the same model.
  virtual Image render_image(const Camera& camera, std::span<const Light> lights, int width, int height) = 0;

  /// Rays cast by the last call (shadow + bounce), for throughput figures; 0 if unknown.
  virtual uint64_t rays_cast() const { return 0; }

  /// Drops what the renderer keeps between calls only to make repeated ones
  /// faster (Embree: the bounce gathers of its last point sets). Results do
  /// not change; the next call on those points does that work again. Called
  /// after one-off work over many points, such as a light cache's build.
  virtual void release_scratch() {}

  /// Benchmark baselines the renderer can measure on the same work as
  /// unit_responses (e.g. raw ray-query throughput), as name -> value.
  virtual std::vector<std::pair<std::string, double>> baseline_figures(const SurfacePoints& /*points*/,
                                                                       std::span<const Light> /*lights*/) {
    return {};
  }
};

} // namespace hilight
