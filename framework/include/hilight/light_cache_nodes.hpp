#pragma once
/// What every cache plugin keeps: the bounce of unit point lights at nodes,
/// over every scene vertex, stored compactly on disk (half floats over each
/// node's largest value, runs of dark vertices as lengths), and the same
/// restricted to one sample set for the solve's blends.
#include "hilight/pipeline/samples.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/renderer.hpp"

#include <cstdint>
#include <iosfwd>
#include <vector>

namespace hilight {

class NodeResponses {
public:
  NodeResponses() = default;
  explicit NodeResponses(size_t vertex_count) : m_vertex_count(vertex_count) {}

  /// Appends the bounce of a unit light at each of `positions` over every
  /// vertex (one renderer batch), rounded as the disk keeps it so that a
  /// solve that built a cache and one that loaded it see the same numbers.
  void trace(const Scene& scene, Renderer& renderer, const std::vector<Vec3>& positions);

  /// Appends node `slot` of `other` (same vertices).
  void append(const NodeResponses& other, size_t slot);

  size_t count() const { return m_scales.size(); }
  size_t vertex_count() const { return m_vertex_count; }
  /// Node `slot`'s bounce at `vertex`.
  Rgb value(size_t slot, size_t vertex) const {
    const uint16_t* h = &m_halves[3 * (slot * m_vertex_count + vertex)];
    return m_scales[slot] * Rgb(half_to_float(h[0]), half_to_float(h[1]), half_to_float(h[2]));
  }

  void write(std::ostream& out) const;
  /// False when the stream does not hold `count` nodes over `vertex_count` vertices.
  bool read(std::istream& in, size_t vertex_count, size_t count);

private:
  static float half_to_float(uint16_t h);
  size_t m_vertex_count = 0;
  // Kept in memory as on disk, in half floats over each node's largest value
  // (6 bytes a vertex, not 12: a 400k-triangle building's cache is several
  // hundred MB even so); value() gives exactly what the disk's reader gives.
  std::vector<uint16_t> m_halves;  ///< node-major: 3 × [slot * vertex_count + vertex]
  std::vector<float> m_scales;     ///< per node
};

/// The nodes' bounce at one sample set's points (barycentric from each
/// sample's triangle), and blends of them.
class NodeSampleTable {
public:
  NodeSampleTable(const NodeResponses& nodes, const Scene& scene, const SampleSet& samples);
  /// out[i] += Σ_k weights[k] · bounce of node slots[k] at sample i.
  void add_blend(const uint32_t* slots, const float* weights, int count, Rgb* out) const;
  size_t samples() const { return m_samples; }

private:
  size_t m_samples = 0;
  std::vector<Rgb> m_data;  ///< [slot * samples + i]
};

/// A node can hold a light when it is in free space: not inside a solid and
/// not within `clearance` of a surface (there the bounce is singular).
bool node_is_free(const RayScene& rays, const Vec3& position, float clearance);

} // namespace hilight
