#pragma once
/// The light cache of paper §3.4, as an interface: a cache plugin keeps the
/// first bounce of unit point lights at nodes placed through the light space
/// (computed once per scene and kept on disk), and gives the bounce of a
/// light anywhere by blending its nearby nodes. Direct light, which has sharp
/// shadows, is always traced exactly. Plugins: caches/grid (a regular grid)
/// and caches/adaptive (nodes refined where the blend is measured to be
/// wrong); `--cache none` solves without one.
#include "hilight/light_bounds.hpp"
#include "hilight/solve/samples.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/renderer.hpp"

#include <iosfwd>
#include <memory>
#include <string>

namespace hilight {

/// What a cache is built over: the scene, its rays, the renderer whose
/// bounce it keeps, and the box lights may stand in (the light space's).
struct LightCacheScene {
  const Scene& scene;
  const RayScene& rays;
  Renderer& renderer;
  Bounds bounds;
};

/// A cache restricted to one sample set (the solve's thousands of φ
/// evaluations read only these points).
class LightCacheView {
public:
  virtual ~LightCacheView() = default;
  /// Adds the cached bounce of a unit light at `position` to out[0..samples).
  /// Only nodes on the light's side of a wall through its cell are blended
  /// (corners_on_light_side): a node behind a wall keeps the other room's
  /// bounce, not this one's.
  virtual void add_indirect(const Vec3& position, Rgb* out) const = 0;
};

class LightCache {
public:
  virtual ~LightCache() = default;
  /// The view over `samples` of the scene `rays` holds (its rays decide
  /// which nodes a light sees).
  virtual std::unique_ptr<LightCacheView> view(const RayScene& rays, const SampleSet& samples) const = 0;
  /// Unit lights whose bounce it keeps (its build cost in renderer batches' lights).
  virtual size_t node_count() const = 0;
  /// Its contents; the framework adds the file header and checksum (light_cache_file.hpp).
  virtual void write(std::ostream& out) const = 0;
};

/// A cache plugin: builds caches, and reads back what LightCache::write wrote.
class LightCacheBuilder {
public:
  virtual ~LightCacheBuilder() = default;
  /// Changes whenever build() would make a different cache of the same scene
  /// (its settings, its format version): part of the cache file's key.
  virtual std::string settings_key() const = 0;
  virtual std::unique_ptr<LightCache> build(const LightCacheScene& in) const = 0;
  /// nullptr when the contents do not make a cache over `vertex_count` vertices.
  virtual std::unique_ptr<LightCache> read(std::istream& in, size_t vertex_count) const = 0;
};

} // namespace hilight
