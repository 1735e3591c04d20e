#include "hilight/light_cache_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/packing.hpp>
#include <istream>
#include <ostream>
#include <tbb/parallel_for.h>

namespace hilight {

namespace {

/// One node's bounce over every vertex as it is kept on disk: values over the
/// node's largest channel in half floats (a bounce is ~1e-7 in millimetre
/// scenes: below half's range without the scale), and the runs of vertices
/// with no bounce at all (other rooms, behind walls) as lengths only.
struct PackedNode {
  float scale = 0.f;
  std::vector<uint32_t> runs;     ///< alternating: zero vertices, then non-zero vertices, ...
  std::vector<uint16_t> halves;   ///< 3 per non-zero vertex
};

/// A node kept as halves over `scale` (3 per vertex), with its dark runs found.
PackedNode pack_halves(float scale, const uint16_t* h, size_t count) {
  PackedNode node;
  node.scale = scale;
  auto nonzero = [&](size_t v) { return (h[3 * v] | h[3 * v + 1] | h[3 * v + 2]) != 0; };
  for (size_t v = 0; v < count;) {
    const size_t zeros_start = v;
    while (v < count && !nonzero(v)) ++v;
    const size_t values_start = v;
    while (v < count && nonzero(v)) ++v;
    node.runs.push_back(uint32_t(values_start - zeros_start));
    node.runs.push_back(uint32_t(v - values_start));
    node.halves.insert(node.halves.end(), h + 3 * values_start, h + 3 * v);
  }
  return node;
}

/// The halves `pack_halves` kept, dark runs as zeros (`out`: 3 per vertex, zeroed);
/// false when the runs do not cover `count` vertices.
bool unpack(const PackedNode& node, uint16_t* out, size_t count) {
  size_t v = 0, h = 0;
  for (size_t r = 0; r + 1 < node.runs.size(); r += 2) {
    if (node.runs[r] > count - v) return false;
    v += node.runs[r];
    if (node.runs[r + 1] > count - v || 3 * size_t(node.runs[r + 1]) > node.halves.size() - h) return false;
    std::copy_n(node.halves.begin() + std::ptrdiff_t(h), 3 * size_t(node.runs[r + 1]), out + 3 * v);
    v += node.runs[r + 1];
    h += 3 * size_t(node.runs[r + 1]);
  }
  return v == count && h == node.halves.size() && node.runs.size() % 2 == 0;
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

void NodeResponses::trace(const Scene& scene, Renderer& renderer, const std::vector<Vec3>& positions) {
  if (positions.empty()) return;
  m_vertex_count = scene.positions.size();
  const size_t vc = m_vertex_count;
  // A few nodes a renderer call: the float responses of all of them at once
  // would be twice the halves kept (1.3 GB for a 400k-triangle building).
  constexpr size_t kBatch = 16;
  for (size_t begin = 0; begin < positions.size(); begin += kBatch) {
    Lighting lights;
    for (size_t n = begin; n < std::min(positions.size(), begin + kBatch); ++n) lights.push_back(Light::point(positions[n], Rgb(1.f)));
    const std::vector<Rgb> traced = renderer.unit_responses(SurfacePoints::from_vertices(scene), lights, Transport::IndirectOnly);
    const size_t first = count();
    m_scales.resize(first + lights.size());
    m_halves.resize(3 * vc * m_scales.size());
    tbb::parallel_for(size_t(0), lights.size(), [&](size_t k) {
      const Rgb* node = traced.data() + k * vc;
      float scale = 0.f;
      for (size_t v = 0; v < vc; ++v) scale = std::max({scale, node[v].r, node[v].g, node[v].b});
      const float inverse = scale > 0.f ? 1.f / scale : 0.f;
      uint16_t* h = &m_halves[3 * (first + k) * vc];
      for (size_t v = 0; v < vc; ++v)
        for (int c = 0; c < 3; ++c) h[3 * v + c] = uint16_t(glm::packHalf1x16(std::max(0.f, node[v][c]) * inverse));
      m_scales[first + k] = scale;
    });
  }
}

void NodeResponses::append(const NodeResponses& other, size_t slot) {
  m_vertex_count = other.m_vertex_count;
  const auto from = other.m_halves.begin() + std::ptrdiff_t(3 * slot * other.m_vertex_count);
  m_halves.insert(m_halves.end(), from, from + std::ptrdiff_t(3 * other.m_vertex_count));
  m_scales.push_back(other.m_scales[slot]);
}

void NodeResponses::write(std::ostream& out) const {
  for (size_t slot = 0; slot < count(); ++slot) {
    const PackedNode node = pack_halves(m_scales[slot], &m_halves[3 * slot * m_vertex_count], m_vertex_count);
    const uint64_t sizes[2] = {node.runs.size(), node.halves.size()};
    put(out, &node.scale, 1);
    put(out, sizes, 2);
    put(out, node.runs.data(), node.runs.size());
    put(out, node.halves.data(), node.halves.size());
  }
}

bool NodeResponses::read(std::istream& in, size_t vertex_count, size_t count) {
  if (vertex_count == 0 || vertex_count >= (uint64_t(1) << 32) || count > (size_t(1) << 24)) return false;
  m_vertex_count = vertex_count;
  m_halves.assign(3 * vertex_count * count, uint16_t(0));
  m_scales.assign(count, 0.f);
  for (size_t slot = 0; slot < count; ++slot) {
    PackedNode node;
    uint64_t sizes[2];
    if (!get(in, &node.scale, 1) || !get(in, sizes, 2)) return false;
    // At most two runs and three halves a vertex: anything more is damage.
    if (sizes[0] > 2 * vertex_count + 2 || sizes[1] > 3 * vertex_count || !std::isfinite(node.scale)) return false;
    node.runs.resize(sizes[0]);
    node.halves.resize(sizes[1]);
    if (!get(in, node.runs.data(), sizes[0]) || !get(in, node.halves.data(), sizes[1])) return false;
    if (!unpack(node, &m_halves[3 * slot * vertex_count], vertex_count)) return false;
    m_scales[slot] = node.scale;
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

bool node_is_free(const RayScene& rays, const Vec3& position, float clearance) {
  return !rays.inside_solid(position) && !rays.closest_point(position, clearance).valid();
}

} // namespace hilight
