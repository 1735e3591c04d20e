// The `grid` light cache (paper §3.4): unit lights at the centres of a
// regular grid of cells over the light space, the bounce of a light anywhere
// the trilinear blend of its cell's eight nodes. Nodes inside solid objects
// or on surfaces, and nodes on the far side of a wall through the cell
// (corners_on_light_side), are left out of the blend (the others are
// renormalized).
#include "hilight/error.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/light_cache_nodes.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>
#include <tbb/parallel_for.h>

namespace hilight {
namespace {

constexpr uint32_t kFormat = 2;  // 2: nodes in blocks of vertices, each with its scale

class GridCache final : public LightCache {
public:
  Vec3 origin{0.f};  ///< position of node (0,0,0)
  Vec3 spacing{1.f};
  glm::ivec3 dims{0};
  std::vector<uint32_t> slot;  ///< node -> index into responses, UINT32_MAX where no light can stand
  NodeResponses responses;

  std::unique_ptr<LightCacheView> view(const RayScene& rays, const SampleSet& samples) const override;
  size_t node_count() const override { return responses.count(); }

  void write(std::ostream& out) const override {
    const uint64_t counts[2] = {slot.size(), responses.count()};
    out.write(reinterpret_cast<const char*>(counts), sizeof(counts));
    out.write(reinterpret_cast<const char*>(&origin), sizeof(origin));
    out.write(reinterpret_cast<const char*>(&spacing), sizeof(spacing));
    out.write(reinterpret_cast<const char*>(&dims), sizeof(dims));
    out.write(reinterpret_cast<const char*>(slot.data()), std::streamsize(slot.size() * sizeof(uint32_t)));
    responses.write(out);
  }

  bool read(std::istream& in, size_t vertex_count) {
    uint64_t counts[2];
    if (!in.read(reinterpret_cast<char*>(counts), sizeof(counts)) || counts[0] > (1u << 24) || counts[1] > counts[0]) return false;
    in.read(reinterpret_cast<char*>(&origin), sizeof(origin));
    in.read(reinterpret_cast<char*>(&spacing), sizeof(spacing));
    in.read(reinterpret_cast<char*>(&dims), sizeof(dims));
    // Untrusted numbers: each size within the count before multiplying (no
    // wrap to a small product), a finite origin and a positive spacing (a NaN
    // would make a negative index).
    const auto within = [&](int d) { return d >= 1 && uint64_t(d) <= counts[0]; };
    if (!in || !within(dims.x) || !within(dims.y) || !within(dims.z) || uint64_t(dims.x) * dims.y * dims.z != counts[0]) return false;
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(origin[k]) || !(spacing[k] > 0.f) || !std::isfinite(spacing[k])) return false;
    if (counts[0] > stream_bytes_left(in) / sizeof(uint32_t)) return false;
    slot.resize(counts[0]);
    if (!in.read(reinterpret_cast<char*>(slot.data()), std::streamsize(slot.size() * sizeof(uint32_t)))) return false;
    for (uint32_t s : slot)
      if (s != UINT32_MAX && s >= counts[1]) return false;
    return responses.read(in, vertex_count, counts[1]);
  }
};

class GridView final : public LightCacheView {
public:
  GridView(const GridCache& cache, const RayScene& rays, const SampleSet& samples)
      : m_cache(cache), m_rays(rays), m_table(cache.responses, rays.scene(), samples) {}

  void add_indirect(const Vec3& position, Rgb* out) const override {
    const GridCache& c = m_cache;
    const Vec3 g = (position - c.origin) / c.spacing;
    glm::ivec3 base;
    Vec3 f;
    for (int k = 0; k < 3; ++k) {
      const float clamped = std::clamp(g[k], 0.f, float(c.dims[k] - 1));
      base[k] = std::min(int(std::floor(clamped)), std::max(0, c.dims[k] - 2));
      f[k] = c.dims[k] > 1 ? clamped - float(base[k]) : 0.f;
    }
    CellCorners corners;
    uint32_t corner_slot[8]{};
    for (int corner = 0; corner < 8; ++corner) {
      const glm::ivec3 q = base + glm::ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      if (q.x >= c.dims.x || q.y >= c.dims.y || q.z >= c.dims.z) continue;
      corner_slot[corner] = c.slot[size_t(q.x) + size_t(c.dims.x) * (size_t(q.y) + size_t(c.dims.y) * size_t(q.z))];
      corners.present[corner] = corner_slot[corner] != UINT32_MAX;
      corners.position[corner] = c.origin + Vec3(q) * c.spacing;
      corners.weight[corner] = (corner & 1 ? f.x : 1.f - f.x) * (corner & 2 ? f.y : 1.f - f.y) * (corner & 4 ? f.z : 1.f - f.z);
    }
    bool keep[8];
    corners_on_light_side(m_rays, position, corners, keep);
    uint32_t slots[8];
    float weights[8];
    int kept = 0;
    float total = 0.f;
    for (int corner = 0; corner < 8; ++corner)
      if (keep[corner] && corners.weight[corner] > 0.f) {
        slots[kept] = corner_slot[corner];
        weights[kept] = corners.weight[corner];
        total += weights[kept++];
      }
    if (kept == 0 || total <= 0.f) return;  // surrounded by solid: no cached bounce
    for (int k = 0; k < kept; ++k) weights[k] /= total;
    m_table.add_blend(slots, weights, kept, out);
  }

private:
  const GridCache& m_cache;
  const RayScene& m_rays;
  NodeSampleTable m_table;
};

std::unique_ptr<LightCacheView> GridCache::view(const RayScene& rays, const SampleSet& samples) const {
  return std::make_unique<GridView>(*this, rays, samples);
}

class GridBuilder final : public LightCacheBuilder {
public:
  explicit GridBuilder(int cells) : m_cells(cells) {}

  std::string settings_key() const override { return "grid/" + std::to_string(kFormat) + "/cells=" + std::to_string(m_cells); }

  std::unique_ptr<LightCache> build(const LightCacheScene& in) const override {
    auto cache = std::make_unique<GridCache>();
    const Vec3 extent = in.bounds.extent();
    const float longest = std::max({extent.x, extent.y, extent.z});
    const float cell = longest / float(m_cells);
    // Nodes at cell centres: never on the bounding walls.
    for (int k = 0; k < 3; ++k) {
      cache->dims[k] = std::max(1, int(std::ceil(extent[k] / cell - 1e-4f)));
      cache->spacing[k] = extent[k] / float(cache->dims[k]);
      cache->origin[k] = in.bounds.lo[k] + 0.5f * cache->spacing[k];
    }
    const size_t nodes = size_t(cache->dims.x) * cache->dims.y * cache->dims.z;
    const float clearance = 1e-3f * in.scene.diagonal();
    std::vector<Vec3> positions(nodes);
    std::vector<uint8_t> free(nodes);
    tbb::parallel_for(size_t(0), nodes, [&](size_t n) {
      const size_t x = n % cache->dims.x, y = (n / cache->dims.x) % cache->dims.y, z = n / (size_t(cache->dims.x) * cache->dims.y);
      positions[n] = cache->origin + Vec3(float(x), float(y), float(z)) * cache->spacing;
      free[n] = node_is_free(in.rays, positions[n], clearance);
    });
    std::vector<Vec3> lights;
    cache->slot.assign(nodes, UINT32_MAX);
    for (size_t n = 0; n < nodes; ++n)
      if (free[n]) {
        cache->slot[n] = uint32_t(lights.size());
        lights.push_back(positions[n]);
      }
    cache->responses = NodeResponses(in.scene.positions.size());
    cache->responses.trace(in.scene, in.renderer, lights);
    return cache;
  }

  std::unique_ptr<LightCache> read(std::istream& in, size_t vertex_count) const override {
    auto cache = std::make_unique<GridCache>();
    if (!cache->read(in, vertex_count)) return nullptr;
    return cache;
  }

private:
  int m_cells;
};

void register_grid(PluginRegistrar& registrar) {
  registrar.cache([](const Properties& p) {
    const long long cells = p.get_int("cells", 8);
    if (cells < 1 || cells > 24) throw InputError("cache grid: cells must be within 1-24 (got " + std::to_string(cells) + ")");
    return std::make_unique<GridBuilder>(int(cells));
  });
}

} // namespace
} // namespace hilight

HILIGHT_PLUGIN("cache", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION, "light cache on a regular grid of cells (cells=8 along the longest axis)",
               hilight::register_grid)
