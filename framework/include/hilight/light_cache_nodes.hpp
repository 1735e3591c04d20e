#pragma once
/// What every cache plugin keeps: the bounce of unit point lights at nodes,
/// over every scene vertex, stored compactly on disk (half floats over each
/// node's largest value, runs of dark vertices as lengths), and the same
/// restricted to one sample set for the solve's blends.
#include "hilight/solve/samples.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/renderer.hpp"

#include <cstdint>
#include <iosfwd>
#include <vector>

namespace hilight {

class NodeResponses {
public:
  /// Vertices kept under one scale: a dim corner of the scene keeps its
  /// precision beside a bright one.
  static constexpr size_t kBlock = 32768;

  NodeResponses() = default;
  explicit NodeResponses(size_t vertex_count) : m_vertex_count(vertex_count) {}

  /// Appends the bounce of a unit light at each of `positions` over every
  /// vertex (a few lights a renderer call, each over every vertex: a
  /// renderer with further bounces transports a light over the whole scene),
  /// rounded as the disk keeps it so that a solve that built a cache and one
  /// that loaded it see the same numbers.
  void trace(const Scene& scene, Renderer& renderer, const std::vector<Vec3>& positions);

  /// Appends node `slot` of `other` (same vertices).
  void append(const NodeResponses& other, size_t slot);

  size_t count() const { return m_nodes.size(); }
  size_t vertex_count() const { return m_vertex_count; }
  size_t blocks() const { return (m_vertex_count + kBlock - 1) / kBlock; }
  /// Node `slot`'s bounce at `vertex`.
  Rgb value(size_t slot, size_t vertex) const;
  /// Node `slot`'s bounce at every vertex of `block` (out: up to kBlock values).
  void block_values(size_t slot, size_t block, Rgb* out) const;
  /// Bytes the nodes take in memory.
  size_t memory_bytes() const;

  void write(std::ostream& out) const;
  /// False when the stream does not hold `count` nodes over `vertex_count` vertices.
  bool read(std::istream& in, size_t vertex_count, size_t count);

  /// One node over one block, kept in memory as on disk: half floats over
  /// the block's largest channel (a bounce is ~1e-7 in millimetre scenes:
  /// below half's range without the scale), and only the runs of lit
  /// vertices — in a building most of a node's vertices are other rooms,
  /// behind walls, with no bounce at all.
  struct Block {
    float scale = 0.f;
    std::vector<uint32_t> run_start;   ///< first vertex (in the block) of each lit run, ascending
    std::vector<uint32_t> run_offset;  ///< its first vertex's index in `halves`/3; one more entry: the end
    std::vector<uint16_t> halves;      ///< 3 per lit vertex
  };

private:
  static float half_to_float(uint16_t h);
  size_t m_vertex_count = 0;
  std::vector<std::vector<Block>> m_nodes;  ///< [slot][block]
};

/// Bytes left to read in `in` (UINT64_MAX when it cannot tell): a count read
/// from a cache file is checked against it before anything is allocated.
uint64_t stream_bytes_left(std::istream& in);

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
/// not within `clearance` of a surface (there the bounce is singular):
/// LightSpace::free_at, the one test of free space.
bool node_is_free(const RayScene& rays, const Vec3& position, float clearance);

/// Whether nothing stands on the segment between `a` and `b`.
bool node_seen(const RayScene& rays, const Vec3& a, const Vec3& b);

/// One cell's eight corner nodes (corner bit 0: +x, 1: +y, 2: +z), as a
/// cache blends them for a light inside the cell.
struct CellCorners {
  Vec3 position[8];
  float weight[8]{};      ///< trilinear weight at the light
  bool present[8]{};      ///< false: no node there (solid, surface)
};

/// Which corners' bounce a light at `light` takes. A wall through the cell
/// splits its corners into sides: corners joined by any unblocked segment
/// are one side. A node on a side the light does not see keeps the next
/// room's bounce, so the light takes only the sides it sees. Sides, not
/// single nodes: a table between the light and one node of its own room
/// does not drop that node, so the blend stays continuous as the light
/// moves within a room. Where the light sees no side, all are kept.
void corners_on_light_side(const RayScene& rays, const Vec3& light, const CellCorners& corners, bool keep[8]);

} // namespace hilight
