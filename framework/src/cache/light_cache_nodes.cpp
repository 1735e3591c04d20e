#include "hilight/light_cache_nodes.hpp"
#include "hilight/light_space.hpp"
#include "hilight/progress.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/packing.hpp>
#include <glm/gtx/component_wise.hpp>
#include <istream>
#include <ostream>
#include <tbb/parallel_for.h>

namespace hilight {

namespace {

using Block = NodeResponses::Block;

constexpr uint16_t kHalfOne = 0x3C00;  ///< 1.0 as a half float
/// A block's scale is a unit light's bounce at a vertex. Nodes stand 1e-3 of
/// the scene's diagonal from every surface, so it stays below about
/// 1/(π (1e-3 d)²): 3e11 even for a 1 mm scene. A larger one is forged or damaged.
constexpr float kMaxScale = 1e12f;

/// A block from `count` vertices' halves (3 each) over `scale`: only its lit runs kept.
Block pack_block(float scale, const uint16_t* h, size_t count) {
  Block block;
  block.scale = scale;
  auto lit = [&](size_t v) { return (h[3 * v] | h[3 * v + 1] | h[3 * v + 2]) != 0; };
  for (size_t v = 0; v < count;) {
    while (v < count && !lit(v)) ++v;
    if (v == count) break;
    block.run_start.push_back(uint32_t(v));
    block.run_offset.push_back(uint32_t(block.halves.size() / 3));
    const size_t start = v;
    while (v < count && lit(v)) ++v;
    block.halves.insert(block.halves.end(), h + 3 * start, h + 3 * v);
  }
  block.run_offset.push_back(uint32_t(block.halves.size() / 3));
  // Grown a run at a time, the vectors hold up to twice what they keep: a
  // cache of every bounce is lit nearly everywhere (the bench building's
  // nodes took 176 MB in memory for 120 MB of data).
  block.run_start.shrink_to_fit();
  block.run_offset.shrink_to_fit();
  block.halves.shrink_to_fit();
  return block;
}

size_t run_length(const Block& b, size_t r) { return b.run_offset[r + 1] - b.run_offset[r]; }

/// On disk a block's runs alternate: dark vertices, then lit ones, ...
std::vector<uint32_t> alternating_runs(const Block& b) {
  std::vector<uint32_t> runs;
  uint32_t at = 0;
  for (size_t r = 0; r < b.run_start.size(); ++r) {
    runs.push_back(b.run_start[r] - at);
    runs.push_back(uint32_t(run_length(b, r)));
    at = b.run_start[r] + runs.back();
  }
  return runs;
}

/// The block that alternating `runs` and `halves` describe over `count`
/// vertices; false when they do not cover exactly that (damage).
bool block_from_runs(const std::vector<uint32_t>& runs, std::vector<uint16_t> halves, size_t count, Block& block) {
  if (runs.size() % 2 != 0) return false;
  size_t v = 0, lit = 0;
  block.run_start.clear();
  block.run_offset.clear();
  block.run_start.reserve(runs.size() / 2);  // exactly, as pack_block keeps them
  block.run_offset.reserve(runs.size() / 2 + 1);
  for (size_t r = 0; r < runs.size(); r += 2) {
    if (runs[r] > count - v) return false;
    v += runs[r];
    if (runs[r + 1] > count - v || 3 * (lit + runs[r + 1]) > halves.size()) return false;
    if (runs[r + 1] == 0) continue;
    block.run_start.push_back(uint32_t(v));
    block.run_offset.push_back(uint32_t(lit));
    v += runs[r + 1];
    lit += runs[r + 1];
  }
  if (v > count || 3 * lit != halves.size()) return false;
  block.run_offset.push_back(uint32_t(lit));
  block.halves = std::move(halves);
  return true;
}

template <class T>
void put(std::ostream& out, const T* data, size_t count) {
  out.write(reinterpret_cast<const char*>(data), std::streamsize(count * sizeof(T)));
}

template <class T>
bool get(std::istream& in, T* data, size_t count) {
  return bool(in.read(reinterpret_cast<char*>(data), std::streamsize(count * sizeof(T))));
}

} // namespace

float NodeResponses::half_to_float(uint16_t h) { return glm::unpackHalf1x16(h); }

Rgb NodeResponses::value(size_t slot, size_t vertex) const {
  const Block& b = m_nodes[slot][vertex / kBlock];
  const uint32_t local = uint32_t(vertex % kBlock);
  const auto after = std::upper_bound(b.run_start.begin(), b.run_start.end(), local);
  if (after == b.run_start.begin()) return Rgb(0.f);
  const size_t r = size_t(after - b.run_start.begin()) - 1;
  const size_t along = local - b.run_start[r];
  if (along >= run_length(b, r)) return Rgb(0.f);
  const uint16_t* h = &b.halves[3 * (b.run_offset[r] + along)];
  return b.scale * Rgb(half_to_float(h[0]), half_to_float(h[1]), half_to_float(h[2]));
}

void NodeResponses::block_values(size_t slot, size_t block, Rgb* out) const {
  const Block& b = m_nodes[slot][block];
  std::fill_n(out, std::min(kBlock, m_vertex_count - block * kBlock), Rgb(0.f));
  for (size_t r = 0; r < b.run_start.size(); ++r)
    for (size_t k = 0; k < run_length(b, r); ++k) {
      const uint16_t* h = &b.halves[3 * (b.run_offset[r] + k)];
      out[b.run_start[r] + k] = b.scale * Rgb(half_to_float(h[0]), half_to_float(h[1]), half_to_float(h[2]));
    }
}

size_t NodeResponses::memory_bytes() const {
  size_t bytes = 0;
  for (const auto& node : m_nodes)
    for (const Block& b : node) bytes += sizeof(Block) + 4 * (b.run_start.size() + b.run_offset.size()) + 2 * b.halves.size();
  return bytes;
}

void NodeResponses::trace(const Scene& scene, Renderer& renderer, const std::vector<Vec3>& positions) {
  if (positions.empty()) return;
  m_vertex_count = scene.positions.size();
  const size_t first = count();
  m_nodes.resize(first + positions.size(), std::vector<Block>(blocks()));
  const SurfacePoints all = SurfacePoints::from_vertices(scene);
  // A few nodes a call, at every vertex at once, cut into blocks after: a
  // renderer with further bounces transports each light over the whole
  // scene whatever points it is asked about, so a call per block of vertices
  // transported every node's light once per block (8 times in a furnished
  // flat of 258k vertices; issue 33). The batch keeps the float responses
  // under about 64 MB.
  const size_t batch = std::clamp<size_t>(size_t(64e6 / (sizeof(Rgb) * double(m_vertex_count))), 1, 16);
  const size_t batches = (positions.size() + batch - 1) / batch;
  ProgressStage progress("building the light cache", double(batches));
  for (size_t begin = 0; begin < positions.size(); begin += batch) {
    Lighting lights;
    for (size_t k = begin; k < std::min(positions.size(), begin + batch); ++k) lights.push_back(Light::point(positions[k], Rgb(1.f)));
    const std::vector<Rgb> traced = renderer.unit_responses(all, lights, Transport::IndirectOnly);
    tbb::parallel_for(size_t(0), lights.size() * blocks(), [&](size_t task) {
      const size_t k = task / blocks(), block = task % blocks();
      const size_t lo = block * kBlock, n = std::min(kBlock, m_vertex_count - lo);
      const Rgb* node = traced.data() + k * m_vertex_count + lo;
      float scale = 0.f;
      for (size_t v = 0; v < n; ++v) scale = std::max({scale, node[v].r, node[v].g, node[v].b});
      const float inverse = scale > 0.f ? 1.f / scale : 0.f;
      std::vector<uint16_t> h(3 * n);
      for (size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) h[3 * v + c] = uint16_t(glm::packHalf1x16(std::max(0.f, node[v][c]) * inverse));
      m_nodes[first + begin + k][block] = pack_block(scale, h.data(), n);
    });
    progress.advance();
  }
}

void NodeResponses::append(const NodeResponses& other, size_t slot) {
  m_vertex_count = other.m_vertex_count;
  m_nodes.push_back(other.m_nodes[slot]);
}

void NodeResponses::write(std::ostream& out) const {
  for (const auto& node : m_nodes)
    for (const Block& b : node) {
      const std::vector<uint32_t> runs = alternating_runs(b);
      const uint64_t sizes[2] = {runs.size(), b.halves.size()};
      put(out, &b.scale, 1);
      put(out, sizes, 2);
      put(out, runs.data(), runs.size());
      put(out, b.halves.data(), b.halves.size());
    }
}

uint64_t stream_bytes_left(std::istream& in) {
  const auto at = in.tellg();
  if (at < 0 || !in.seekg(0, std::ios::end)) return UINT64_MAX;
  const auto end = in.tellg();
  in.seekg(at);
  return end >= at ? uint64_t(end - at) : UINT64_MAX;
}

bool NodeResponses::read(std::istream& in, size_t vertex_count, size_t count) {
  if (vertex_count == 0 || vertex_count >= (uint64_t(1) << 32) || count > (size_t(1) << 24)) return false;
  // Each block takes at least its scale and two sizes on disk: a count the
  // file is too short for is refused before the nodes are allocated.
  const uint64_t min_block = sizeof(float) + 2 * sizeof(uint64_t);
  if (uint64_t(count) * ((vertex_count + kBlock - 1) / kBlock) > stream_bytes_left(in) / min_block) return false;
  m_vertex_count = vertex_count;
  m_nodes.assign(count, std::vector<Block>(blocks()));
  for (auto& node : m_nodes)
    for (size_t block = 0; block < node.size(); ++block) {
      const size_t n = std::min(kBlock, vertex_count - block * kBlock);
      float scale = 0.f;
      uint64_t sizes[2];
      if (!get(in, &scale, 1) || !get(in, sizes, 2)) return false;
      // At most two runs and three halves a vertex: anything more is damage.
      if (sizes[0] > 2 * n + 2 || sizes[1] > 3 * n || !(scale >= 0.f && scale <= kMaxScale)) return false;
      std::vector<uint32_t> runs(sizes[0]);
      std::vector<uint16_t> halves(sizes[1]);
      if (!get(in, runs.data(), sizes[0]) || !get(in, halves.data(), sizes[1])) return false;
      // Written over the block's largest value: each in [0, 1] (as bits: no
      // sign, at most 1.0), which also rules out NaN and infinity.
      if (std::any_of(halves.begin(), halves.end(), [](uint16_t h) { return h > kHalfOne; })) return false;
      if (!block_from_runs(runs, std::move(halves), n, node[block])) return false;
      node[block].scale = scale;
    }
  return true;
}

NodeSampleTable::NodeSampleTable(const NodeResponses& nodes, const Scene& scene, const SampleSet& samples)
    : m_samples(samples.size()) {
  const size_t m = m_samples;
  m_data.resize(nodes.count() * m);
  tbb::parallel_for(size_t(0), nodes.count(), [&](size_t s) {
    for (size_t i = 0; i < m; ++i) {
      const SurfaceBinding& b = samples.binding[i];
      const auto& tri = scene.triangles[b.triangle];
      m_data[s * m + i] = (1.f - b.u - b.v) * nodes.value(s, tri[0]) + b.u * nodes.value(s, tri[1]) + b.v * nodes.value(s, tri[2]);
    }
  });
}

void NodeSampleTable::add_blend(const uint32_t* slots, const float* weights, int count, Rgb* out) const {
  for (int k = 0; k < count; ++k) {
    const Rgb* column = &m_data[size_t(slots[k]) * m_samples];
    const float w = weights[k];
    for (size_t i = 0; i < m_samples; ++i) out[i] += w * column[i];
  }
}

bool node_is_free(const RayScene& rays, const Vec3& position, float clearance) { return LightSpace::free_at(rays, position, clearance); }

bool node_seen(const RayScene& rays, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const float distance = glm::length(d);
  // Embree takes no ray from beyond ±1.8e18 (a light asked about at 1e30, a
  // corrupt cache's cell): nothing to trace there, so seen.
  constexpr float kEmbreeLargest = 1e18f;
  const float farthest = std::max(glm::compMax(glm::abs(a)), glm::compMax(glm::abs(b)));
  if (!(distance > 0.f) || !std::isfinite(distance) || !(farthest < kEmbreeLargest)) return true;
  return !rays.occluded(a, d / distance, distance);
}

void corners_on_light_side(const RayScene& rays, const Vec3& light, const CellCorners& c, bool keep[8]) {
  // Sides: corners joined by any unblocked segment between them.
  int side[8];
  for (int k = 0; k < 8; ++k) side[k] = k;
  const auto root = [&](int k) {
    while (side[k] != k) k = side[k];
    return k;
  };
  int sides = 0;
  for (int k = 0; k < 8; ++k) sides += c.present[k];
  for (int k = 0; k < 8 && sides > 1; ++k)
    for (int other = k + 1; other < 8 && sides > 1; ++other)
      if (c.present[k] && c.present[other] && root(k) != root(other) && node_seen(rays, c.position[k], c.position[other])) {
        side[root(other)] = root(k);
        --sides;
      }
  for (int k = 0; k < 8; ++k) keep[k] = c.present[k];
  if (sides <= 1) return;
  // Every side the light sees (two seen sides meet through the light's own
  // free space); none seen: every corner.
  bool seen[8]{}, any = false;
  for (int k = 0; k < 8; ++k)
    if (c.present[k] && !seen[root(k)] && node_seen(rays, light, c.position[k])) seen[root(k)] = any = true;
  if (!any) return;
  for (int k = 0; k < 8; ++k) keep[k] = c.present[k] && seen[root(k)];
}

} // namespace hilight
