#pragma once
/// The light cache of paper §3.4, for the part that interpolates well: the
/// first bounce. Unit point lights sit at the nodes of a grid over the scene;
/// the bounce each one sends to every scene vertex is computed once per scene
/// (and kept on disk), and the bounce of a light anywhere is the trilinear
/// blend of its cell's nodes. Nodes inside solid objects are left out of the
/// blend. Direct light, which has sharp shadows, is always traced exactly.
#include "hilight/pipeline/samples.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/renderer.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hilight {

struct LightCacheSettings {
  int cells_along_longest_axis = 8;
  bool open_space = false;  ///< grid over open_light_bounds() (lights outside the scene), not light_bounds()
};

class LightCache {
public:
  /// Builds: one batch of renderer->unit_responses(IndirectOnly) over all
  /// scene vertices for the grid's free nodes.
  static LightCache build(const Scene& scene, const RayScene& rays, Renderer& renderer, const LightCacheSettings& settings);
  /// Key of the cache for this scene and renderer settings (file name part).
  static uint64_t key(const Scene& scene, const std::string& renderer_key, const LightCacheSettings& settings);

  /// Loads if a matching file exists and is intact; nullopt otherwise.
  static std::optional<LightCache> load(const std::filesystem::path& file, uint64_t key, size_t vertex_count);
  void save(const std::filesystem::path& file) const;

  size_t node_count() const { return m_node_valid.size(); }
  size_t valid_node_count() const;

private:
  friend class LightCacheView;
  uint64_t m_key = 0;
  Vec3 m_origin{0.f};  ///< position of node (0,0,0)
  Vec3 m_spacing{1.f};
  glm::ivec3 m_dims{0};
  size_t m_vertex_count = 0;
  std::vector<uint8_t> m_node_valid;
  std::vector<Rgb> m_data;  ///< node-major: [node * vertex_count + vertex], only valid nodes hold data
  std::vector<uint32_t> m_node_slot;  ///< node -> index into m_data blocks

  Vec3 node_position(int x, int y, int z) const { return m_origin + Vec3(float(x), float(y), float(z)) * m_spacing; }
};

/// The cache restricted to one sample set: per node, the bounce at each
/// sample (barycentric from the sample's triangle's vertices).
class LightCacheView {
public:
  LightCacheView(const LightCache& cache, const Scene& scene, const SampleSet& samples);
  /// Adds the interpolated bounce of a unit light at `position` to out[0..m).
  void add_indirect(const Vec3& position, Rgb* out) const;

private:
  const LightCache& m_cache;
  size_t m_samples;
  std::vector<Rgb> m_data;  ///< [slot * m + i]
};

/// The default folder for cache files: $HILIGHT_CACHE_DIR, else
/// $XDG_CACHE_HOME/hilight, else ~/.cache/hilight.
std::filesystem::path default_cache_dir();

} // namespace hilight
