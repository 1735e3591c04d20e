// The `adaptive` light cache: nodes where the bounce needs them. It starts
// from the grid cache's lattice of nodes and splits a cell between them into
// eight wherever the blend of its corners is measured to be wrong: a unit
// light at the cell's centre is traced exactly and compared, over every
// scene vertex, with the blend the cell would give there. Cells are split
// worst first while the budget of traced lights lasts, so the extra lights
// goes where the bounce changes fast (near walls, doors, between rooms).
#include "hilight/error.hpp"
#include "hilight/light_cache.hpp"
#include "hilight/light_cache_nodes.hpp"
#include "hilight/plugin.hpp"
#include "hilight/version.hpp"
#include "hilight/registry.hpp"
#include "cell_refiner.hpp"

#include <algorithm>
#include <cmath>
#include <istream>
#include <map>
#include <numeric>
#include <ostream>
#include <tbb/parallel_for.h>

namespace hilight {
namespace {

using adaptive::Cell;
using adaptive::CellTree;
using adaptive::kNoNode;

constexpr uint32_t kFormat = 2;  // 2: nodes in blocks of vertices, each with its scale

class AdaptiveCache final : public LightCache {
public:
  CellTree tree;
  NodeResponses responses;

  std::unique_ptr<LightCacheView> view(const RayScene& rays, const SampleSet& samples) const override;
  size_t node_count() const override { return responses.count(); }
  void write(std::ostream& out) const override {
    const uint64_t nodes = responses.count();
    out.write(reinterpret_cast<const char*>(&nodes), sizeof(nodes));
    tree.write(out);
    responses.write(out);
  }
  bool read(std::istream& in, size_t vertex_count) {
    uint64_t nodes = 0;
    if (!in.read(reinterpret_cast<char*>(&nodes), sizeof(nodes)) || nodes > (1u << 24)) return false;
    return tree.read(in, nodes) && responses.read(in, vertex_count, nodes);
  }
};

class AdaptiveView final : public LightCacheView {
public:
  AdaptiveView(const AdaptiveCache& cache, const RayScene& rays, const SampleSet& samples)
      : m_tree(cache.tree), m_rays(rays), m_table(cache.responses, rays.scene(), samples) {}
  void add_indirect(const Vec3& position, Rgb* out) const override {
    uint32_t slots[9];
    float weights[9];
    const auto keep_side = [&](const CellCorners& corners, bool keep[8]) { corners_on_light_side(m_rays, position, corners, keep); };
    if (const int used = m_tree.blend(position, slots, weights, keep_side)) m_table.add_blend(slots, weights, used, out);
  }

private:
  const CellTree& m_tree;
  const RayScene& m_rays;
  NodeSampleTable m_table;
};

std::unique_ptr<LightCacheView> AdaptiveCache::view(const RayScene& rays, const SampleSet& samples) const {
  return std::make_unique<AdaptiveView>(*this, rays, samples);
}

class AdaptiveBuilder final : public LightCacheBuilder {
public:
  explicit AdaptiveBuilder(adaptive::RefineSettings settings) : m_settings(settings) {}

  std::string settings_key() const override {
    return "adaptive/" + std::to_string(kFormat) + "/cells=" + std::to_string(m_settings.cells) + "/depth=" +
           std::to_string(m_settings.depth) + "/tolerance=" + std::to_string(m_settings.tolerance) +
           "/growth=" + std::to_string(m_settings.growth);
  }

  std::unique_ptr<LightCache> build(const LightCacheScene& in) const override {
    auto cache = std::make_unique<AdaptiveCache>();
    adaptive::refine_cells(in, m_settings, cache->tree, cache->responses);
    return cache;
  }

  std::unique_ptr<LightCache> read(std::istream& in, size_t vertex_count) const override {
    auto cache = std::make_unique<AdaptiveCache>();
    if (!cache->read(in, vertex_count)) return nullptr;
    return cache;
  }

private:
  adaptive::RefineSettings m_settings;
};

void register_adaptive(PluginRegistrar& registrar) {
  registrar.cache([](const Properties& p) {
    adaptive::RefineSettings s;
    s.cells = int(p.get_int("cells", s.cells));
    s.depth = int(p.get_int("depth", s.depth));
    s.tolerance = p.get_double("tolerance", s.tolerance);
    s.growth = p.get_double("growth", s.growth);
    if (s.cells < 1 || s.cells > 16) throw InputError("cache adaptive: cells must be within 1-16");
    if (s.depth < 0 || s.depth > 4) throw InputError("cache adaptive: depth must be within 0-4");
    if (!(s.tolerance >= 0 && s.tolerance <= 10)) throw InputError("cache adaptive: tolerance must be within 0-10");
    if (!(s.growth >= 1 && s.growth <= 100)) throw InputError("cache adaptive: growth must be within 1-100");
    return std::make_unique<AdaptiveBuilder>(s);
  });
}

} // namespace
} // namespace hilight

HILIGHT_PLUGIN("cache", HILIGHT_PLUGIN_NAME, HILIGHT_VERSION,
               "light cache whose cells are split where the blend is measured wrong (cells=8 depth=1 tolerance=0.05 growth=1.5)",
               hilight::register_adaptive)
