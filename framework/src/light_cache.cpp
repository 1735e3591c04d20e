#include "hilight/light_cache.hpp"

#include "hilight/hash.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/light_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/packing.hpp>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <tbb/parallel_for.h>

namespace hilight {

namespace fs = std::filesystem;

namespace {

constexpr uint32_t kFormatVersion = 8;  // 4: grid over light_bounds(); 5: flat axes grow on the side surfaces face; 6: smooth points shaded at the point (rendering model); 7: half floats, zero runs; 8: crease points nudged the same on any tessellation
constexpr uint64_t kMaxVertices = uint64_t(1) << 32;

/// One node's bounce over every vertex as it is kept on disk: values over the
/// node's largest channel in half floats (a bounce is ~1e-7 in millimetre
/// scenes: below half's range without the scale), and the runs of vertices
/// with no bounce at all (other rooms, behind walls) as lengths only.
struct PackedNode {
  float scale = 0.f;
  std::vector<uint32_t> runs;     ///< alternating: zero vertices, then non-zero vertices, ...
  std::vector<uint16_t> halves;   ///< 3 per non-zero vertex
};

PackedNode pack(const Rgb* values, size_t count) {
  PackedNode node;
  for (size_t v = 0; v < count; ++v) node.scale = std::max({node.scale, values[v].r, values[v].g, values[v].b});
  const float inverse = node.scale > 0.f ? 1.f / node.scale : 0.f;
  std::vector<uint16_t> h(3 * count);
  for (size_t v = 0; v < count; ++v)
    for (int c = 0; c < 3; ++c) h[3 * v + c] = uint16_t(glm::packHalf1x16(std::max(0.f, values[v][c]) * inverse));
  auto nonzero = [&](size_t v) { return (h[3 * v] | h[3 * v + 1] | h[3 * v + 2]) != 0; };
  for (size_t v = 0; v < count;) {
    const size_t zeros_start = v;
    while (v < count && !nonzero(v)) ++v;
    const size_t values_start = v;
    while (v < count && nonzero(v)) ++v;
    node.runs.push_back(uint32_t(values_start - zeros_start));
    node.runs.push_back(uint32_t(v - values_start));
    node.halves.insert(node.halves.end(), h.begin() + std::ptrdiff_t(3 * values_start), h.begin() + std::ptrdiff_t(3 * v));
  }
  return node;
}

/// The values `pack` kept; false when the runs do not cover `count` vertices.
bool unpack(const PackedNode& node, Rgb* out, size_t count) {
  size_t v = 0, h = 0;
  for (size_t r = 0; r + 1 < node.runs.size(); r += 2) {
    if (node.runs[r] > count - v) return false;
    for (uint32_t k = 0; k < node.runs[r]; ++k) out[v++] = Rgb(0.f);
    if (node.runs[r + 1] > count - v || 3 * size_t(node.runs[r + 1]) > node.halves.size() - h) return false;
    for (uint32_t k = 0; k < node.runs[r + 1]; ++k, h += 3)
      out[v++] = node.scale * Rgb(glm::unpackHalf1x16(node.halves[h]), glm::unpackHalf1x16(node.halves[h + 1]),
                                  glm::unpackHalf1x16(node.halves[h + 2]));
  }
  return v == count && h == node.halves.size() && node.runs.size() % 2 == 0;
}
constexpr char kMagic[8] = {'H', 'L', 'C', 'A', 'C', 'H', 'E', '1'};

} // namespace

uint64_t LightCache::key(const Scene& scene, const std::string& renderer_key, const LightCacheSettings& settings) {
  uint64_t h = kFnvOffset;
  h = fnv1a(h, &kFormatVersion, sizeof(kFormatVersion));
  h = fnv1a(h, scene.positions.data(), scene.positions.size() * sizeof(Vec3));
  h = fnv1a(h, scene.normals.data(), scene.normals.size() * sizeof(Vec3));
  h = fnv1a(h, scene.triangles.data(), scene.triangles.size() * sizeof(scene.triangles[0]));
  h = fnv1a(h, scene.triangle_material.data(), scene.triangle_material.size() * sizeof(uint32_t));
  for (const auto& m : scene.materials) h = fnv1a(h, &m.albedo, sizeof(m.albedo));
  h = fnv1a(h, renderer_key.data(), renderer_key.size());
  h = fnv1a(h, &settings.cells_along_longest_axis, sizeof(int));
  if (settings.open_space) h = fnv1a(h, "open", 4);
  return h;
}

LightCache LightCache::build(const Scene& scene, const RayScene& rays, Renderer& renderer, const LightCacheSettings& settings) {
  LightCache cache;
  const Bounds b = settings.open_space ? open_light_bounds(scene) : scene.light_bounds();
  Vec3 extent = b.extent();
  float longest = std::max(extent.x, std::max(extent.y, extent.z));
  float cell = longest / float(std::max(1, settings.cells_along_longest_axis));
  // Nodes at cell centres: never on the bounding walls.
  for (int k = 0; k < 3; ++k) {
    cache.m_dims[k] = std::max(1, int(std::ceil(extent[k] / cell - 1e-4f)));
    cache.m_spacing[k] = extent[k] / float(cache.m_dims[k]);
    cache.m_origin[k] = b.lo[k] + 0.5f * cache.m_spacing[k];
  }
  const size_t nodes = size_t(cache.m_dims.x) * cache.m_dims.y * cache.m_dims.z;
  cache.m_node_valid.assign(nodes, 0);
  cache.m_node_slot.assign(nodes, UINT32_MAX);
  const float clearance = 1e-3f * scene.diagonal();
  std::vector<Vec3> positions(nodes);
  tbb::parallel_for(size_t(0), nodes, [&](size_t n) {
    const size_t x = n % cache.m_dims.x, y = (n / cache.m_dims.x) % cache.m_dims.y, z = n / (size_t(cache.m_dims.x) * cache.m_dims.y);
    positions[n] = cache.node_position(int(x), int(y), int(z));
    cache.m_node_valid[n] = !rays.inside_solid(positions[n]) && !rays.closest_point(positions[n], clearance).valid();
  });
  Lighting lights;
  for (size_t n = 0; n < nodes; ++n)
    if (cache.m_node_valid[n]) {
      cache.m_node_slot[n] = uint32_t(lights.size());
      lights.push_back(Light::point(positions[n], Rgb(1.f)));
    }
  cache.m_vertex_count = scene.positions.size();
  cache.m_key = key(scene, renderer.settings_key(), settings);
  if (!lights.empty()) cache.m_data = renderer.unit_responses(SurfacePoints::from_vertices(scene), lights, Transport::IndirectOnly);
  // Kept as the disk keeps it, so a solve that built the cache and one that
  // loaded it see the same numbers.
  const size_t vc = cache.m_vertex_count;
  tbb::parallel_for(size_t(0), lights.size(), [&](size_t slot) {
    Rgb* node = cache.m_data.data() + slot * vc;
    unpack(pack(node, vc), node, vc);
  });
  return cache;
}

size_t LightCache::valid_node_count() const {
  size_t n = 0;
  for (auto v : m_node_valid) n += v;
  return n;
}

void LightCache::save(const fs::path& file) const {
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  write_atomically(file, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    uint64_t counts[3] = {m_vertex_count, m_node_valid.size(), m_data.size()};
    out.write(kMagic, sizeof(kMagic));
    out.write(reinterpret_cast<const char*>(&m_key), sizeof(m_key));
    out.write(reinterpret_cast<const char*>(counts), sizeof(counts));
    out.write(reinterpret_cast<const char*>(&m_origin), sizeof(m_origin));
    out.write(reinterpret_cast<const char*>(&m_spacing), sizeof(m_spacing));
    out.write(reinterpret_cast<const char*>(&m_dims), sizeof(m_dims));
    out.write(reinterpret_cast<const char*>(m_node_valid.data()), std::streamsize(m_node_valid.size()));
    out.write(reinterpret_cast<const char*>(m_node_slot.data()), std::streamsize(m_node_slot.size() * sizeof(uint32_t)));
    const size_t slots = m_vertex_count ? m_data.size() / m_vertex_count : 0;
    for (size_t slot = 0; slot < slots; ++slot) {
      const PackedNode node = pack(m_data.data() + slot * m_vertex_count, m_vertex_count);
      const uint64_t sizes[2] = {node.runs.size(), node.halves.size()};
      out.write(reinterpret_cast<const char*>(&node.scale), sizeof(node.scale));
      out.write(reinterpret_cast<const char*>(sizes), sizeof(sizes));
      out.write(reinterpret_cast<const char*>(node.runs.data()), std::streamsize(node.runs.size() * sizeof(uint32_t)));
      out.write(reinterpret_cast<const char*>(node.halves.data()), std::streamsize(node.halves.size() * sizeof(uint16_t)));
    }
    if (!out) throw std::runtime_error("light cache: write failed");
  });
}

std::optional<LightCache> LightCache::load(const fs::path& file, uint64_t key, size_t vertex_count) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  char magic[8];
  LightCache c;
  uint64_t counts[3];
  in.read(magic, sizeof(magic));
  in.read(reinterpret_cast<char*>(&c.m_key), sizeof(c.m_key));
  in.read(reinterpret_cast<char*>(counts), sizeof(counts));
  if (!in || std::memcmp(magic, kMagic, sizeof(kMagic)) != 0 || c.m_key != key || counts[0] != vertex_count) return std::nullopt;
  if (counts[1] > (1u << 24)) return std::nullopt;
  c.m_vertex_count = counts[0];
  in.read(reinterpret_cast<char*>(&c.m_origin), sizeof(c.m_origin));
  in.read(reinterpret_cast<char*>(&c.m_spacing), sizeof(c.m_spacing));
  in.read(reinterpret_cast<char*>(&c.m_dims), sizeof(c.m_dims));
  if (!in || size_t(c.m_dims.x) * c.m_dims.y * c.m_dims.z != counts[1]) return std::nullopt;
  c.m_node_valid.resize(counts[1]);
  c.m_node_slot.resize(counts[1]);
  in.read(reinterpret_cast<char*>(c.m_node_valid.data()), std::streamsize(counts[1]));
  in.read(reinterpret_cast<char*>(c.m_node_slot.data()), std::streamsize(counts[1] * sizeof(uint32_t)));
  if (counts[0] >= kMaxVertices || counts[2] != c.valid_node_count() * counts[0]) return std::nullopt;
  c.m_data.resize(counts[2]);
  const size_t slots = counts[0] ? counts[2] / counts[0] : 0;
  for (size_t slot = 0; slot < slots; ++slot) {
    PackedNode node;
    uint64_t sizes[2];
    in.read(reinterpret_cast<char*>(&node.scale), sizeof(node.scale));
    in.read(reinterpret_cast<char*>(sizes), sizeof(sizes));
    // At most two runs and three halves a vertex: anything more is damage.
    if (!in || sizes[0] > 2 * counts[0] + 2 || sizes[1] > 3 * counts[0] || !std::isfinite(node.scale)) return std::nullopt;
    node.runs.resize(sizes[0]);
    node.halves.resize(sizes[1]);
    in.read(reinterpret_cast<char*>(node.runs.data()), std::streamsize(sizes[0] * sizeof(uint32_t)));
    in.read(reinterpret_cast<char*>(node.halves.data()), std::streamsize(sizes[1] * sizeof(uint16_t)));
    if (!in || !unpack(node, c.m_data.data() + slot * counts[0], counts[0])) return std::nullopt;
  }
  return c;
}

LightCacheView::LightCacheView(const LightCache& cache, const Scene& scene, const SampleSet& samples)
    : m_cache(cache), m_samples(samples.size()) {
  const size_t slots = cache.valid_node_count(), m = samples.size(), vc = cache.m_vertex_count;
  m_data.resize(slots * m);
  tbb::parallel_for(size_t(0), slots, [&](size_t s) {
    const Rgb* node = &cache.m_data[s * vc];
    for (size_t i = 0; i < m; ++i) {
      const SurfaceBinding& b = samples.binding[i];
      const auto& tri = scene.triangles[b.triangle];
      m_data[s * m + i] = (1.f - b.u - b.v) * node[tri[0]] + b.u * node[tri[1]] + b.v * node[tri[2]];
    }
  });
}

void LightCacheView::add_indirect(const Vec3& position, Rgb* out) const {
  const LightCache& c = m_cache;
  Vec3 g = (position - c.m_origin) / c.m_spacing;
  glm::ivec3 base;
  Vec3 f;
  for (int k = 0; k < 3; ++k) {
    float clamped = std::clamp(g[k], 0.f, float(c.m_dims[k] - 1));
    base[k] = std::min(int(std::floor(clamped)), std::max(0, c.m_dims[k] - 2));
    f[k] = c.m_dims[k] > 1 ? clamped - float(base[k]) : 0.f;
  }
  uint32_t slots[8];
  float weights[8];
  int used = 0;
  float total = 0.f;
  for (int corner = 0; corner < 8; ++corner) {
    glm::ivec3 q = base + glm::ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    if (q.x >= c.m_dims.x || q.y >= c.m_dims.y || q.z >= c.m_dims.z) continue;
    size_t node = size_t(q.x) + size_t(c.m_dims.x) * (size_t(q.y) + size_t(c.m_dims.y) * size_t(q.z));
    if (!c.m_node_valid[node]) continue;
    float w = (corner & 1 ? f.x : 1.f - f.x) * (corner & 2 ? f.y : 1.f - f.y) * (corner & 4 ? f.z : 1.f - f.z);
    if (w <= 0.f) continue;
    slots[used] = c.m_node_slot[node];
    weights[used++] = w;
    total += w;
  }
  if (used == 0 || total <= 0.f) return;  // surrounded by solid: no cached bounce
  for (int k = 0; k < used; ++k) {
    const Rgb* col = &m_data[size_t(slots[k]) * m_samples];
    float w = weights[k] / total;
    for (size_t i = 0; i < m_samples; ++i) out[i] += w * col[i];
  }
}

fs::path default_cache_dir() {
  if (const char* d = std::getenv("HILIGHT_CACHE_DIR"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "hilight";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "hilight";
  return fs::temp_directory_path() / "hilight-cache";
}

} // namespace hilight
