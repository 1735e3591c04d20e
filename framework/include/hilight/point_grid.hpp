#pragma once
/// Points on a uniform hash grid: each cell's point indices in the order
/// they were added; what lies near a place is what the 27 cells around its
/// own hold.
#include "hilight/math.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace hilight {

class PointGrid {
public:
  explicit PointGrid(float cell) : m_cell(cell) {}

  void add(const Vec3& p, uint32_t index) { m_cells[key(cell_of(p))].push_back(index); }
  glm::ivec3 cell_of(const Vec3& p) const { return glm::ivec3(glm::floor(p / m_cell)); }
  /// A cell's coordinates packed in 21 bits each (wrapping far out: a shared
  /// key only adds candidates, which callers test by distance).
  static uint64_t key(const glm::ivec3& c) {
    return (uint64_t(uint32_t(c.x) & 0x1FFFFF) << 42) | (uint64_t(uint32_t(c.y) & 0x1FFFFF) << 21) | uint64_t(uint32_t(c.z) & 0x1FFFFF);
  }
  /// f(index) for each point in the cells around p's (x, then y, then z
  /// from −1 to 1), each cell's in the order added.
  template <class F> void for_each_near(const Vec3& p, F&& f) const {
    const glm::ivec3 c = cell_of(p);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = m_cells.find(key(c + glm::ivec3(dx, dy, dz)));
          if (it == m_cells.end()) continue;
          for (uint32_t i : it->second) f(i);
        }
  }

  /// f(indices) for each cell that holds points (in no particular order).
  template <class F> void for_each_cell(F&& f) const {
    for (const auto& [key, members] : m_cells) f(members);
  }
  size_t cell_count() const { return m_cells.size(); }

private:
  float m_cell;
  std::unordered_map<uint64_t, std::vector<uint32_t>> m_cells;
};

} // namespace hilight
