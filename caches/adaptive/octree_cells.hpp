#pragma once
// The adaptive cache's cells: a grid of base cells over the light space, each
// split into eight children where the trilinear blend of its corner nodes was
// measured to be wrong. Corners are nodes (unit lights); cells store the
// slots of their eight corners, so finding a light's blend is a descent.
#include "hilight/light_cache_nodes.hpp"
#include "hilight/math.hpp"

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <vector>

namespace hilight::adaptive {

constexpr uint32_t kNoNode = UINT32_MAX;  ///< a corner where no light can stand (solid, surface)

struct Cell {
  glm::ivec3 lo{0};      ///< lowest corner in finest-lattice units
  int level = 0;         ///< 0: a base cell
  int32_t first_child = -1;  ///< index of 8 consecutive children, -1: a leaf
  uint32_t corner[8]{};  ///< node slots, corner bit 0: +x, 1: +y, 2: +z
  /// A leaf's centre node (traced to decide the split, kept when the cell was
  /// not split): the blend adds a tent that corrects it there, zero on the
  /// cell's faces so neighbours still meet. kNoNode: none.
  uint32_t centre = kNoNode;
};

struct CellTree {
  Vec3 origin{0.f};      ///< the box's low corner (finest-lattice point (0,0,0))
  Vec3 base_size{1.f};   ///< a base cell's size
  glm::ivec3 base_cells{1};
  int depth = 0;         ///< levels a base cell may be split
  std::vector<Cell> cells;  ///< base cells first, in x-fastest order

  int cell_span(int level) const { return 1 << (depth - level); }
  /// Finest-lattice point → world.
  Vec3 position(const glm::ivec3& lattice) const {
    return origin + Vec3(lattice) * base_size / float(1 << depth);
  }
  /// The leaf holding `p` (clamped into the box) and p's place in it, in [0,1]³.
  const Cell& leaf(const Vec3& p, Vec3& fraction) const;
  /// Marks the corners of a cell a light at the blended point takes (corners_on_light_side).
  using KeepSide = std::function<void(const CellCorners& corners, bool keep[8])>;
  /// Weights of the nodes that blend to the bounce at `p`: trilinear over the
  /// leaf's usable corners (renormalized over them) plus the centre's tent;
  /// where `keep_side` drops corners beyond a wall, trilinear over the kept
  /// corners only. Returns how many were written (at most 9).
  int blend(const Vec3& p, uint32_t slots[9], float weights[9], const KeepSide& keep_side) const;

  void write(std::ostream& out) const;
  /// False when the stream does not hold a consistent tree over `nodes` nodes.
  bool read(std::istream& in, size_t nodes);
};

} // namespace hilight::adaptive
