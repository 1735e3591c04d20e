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

template <class T>
void put(std::ostream& out, const T* data, size_t count) {
  out.write(reinterpret_cast<const char*>(data), std::streamsize(count * sizeof(T)));
}

template <class T>
bool get(std::istream& in, T* data, size_t count) {
  return bool(in.read(reinterpret_cast<char*>(data), std::streamsize(count * sizeof(T))));
}

} // namespace

void NodeResponses::trace(const Scene& scene, Renderer& renderer, const std::vector<Vec3>& positions) {
  if (positions.empty()) return;
  m_vertex_count = scene.positions.size();
  Lighting lights;
  for (const auto& p : positions) lights.push_back(Light::point(p, Rgb(1.f)));
  std::vector<Rgb> traced = renderer.unit_responses(SurfacePoints::from_vertices(scene), lights, Transport::IndirectOnly);
  const size_t vc = m_vertex_count;
  tbb::parallel_for(size_t(0), lights.size(), [&](size_t slot) {
    Rgb* node = traced.data() + slot * vc;
    unpack(pack(node, vc), node, vc);
  });
  m_data.insert(m_data.end(), traced.begin(), traced.end());
}

void NodeResponses::append(const NodeResponses& other, size_t slot) {
  m_vertex_count = other.m_vertex_count;
  m_data.insert(m_data.end(), other.node(slot), other.node(slot) + other.m_vertex_count);
}

void NodeResponses::write(std::ostream& out) const {
  for (size_t slot = 0; slot < count(); ++slot) {
    const PackedNode node = pack(this->node(slot), m_vertex_count);
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
  m_data.assign(vertex_count * count, Rgb(0.f));
  for (size_t slot = 0; slot < count; ++slot) {
    PackedNode node;
    uint64_t sizes[2];
    if (!get(in, &node.scale, 1) || !get(in, sizes, 2)) return false;
    // At most two runs and three halves a vertex: anything more is damage.
    if (sizes[0] > 2 * vertex_count + 2 || sizes[1] > 3 * vertex_count || !std::isfinite(node.scale)) return false;
    node.runs.resize(sizes[0]);
    node.halves.resize(sizes[1]);
    if (!get(in, node.runs.data(), sizes[0]) || !get(in, node.halves.data(), sizes[1])) return false;
    if (!unpack(node, m_data.data() + slot * vertex_count, vertex_count)) return false;
  }
  return true;
}

NodeSampleTable::NodeSampleTable(const NodeResponses& nodes, const Scene& scene, const SampleSet& samples)
    : m_samples(samples.size()) {
  const size_t m = m_samples;
  m_data.resize(nodes.count() * m);
  tbb::parallel_for(size_t(0), nodes.count(), [&](size_t s) {
    const Rgb* node = nodes.node(s);
    for (size_t i = 0; i < m; ++i) {
      const SurfaceBinding& b = samples.binding[i];
      const auto& tri = scene.triangles[b.triangle];
      m_data[s * m + i] = (1.f - b.u - b.v) * node[tri[0]] + b.u * node[tri[1]] + b.v * node[tri[2]];
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
