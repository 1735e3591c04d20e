#include "octree_cells.hpp"

#include "hilight/light_cache_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>

namespace hilight::adaptive {

const Cell& CellTree::leaf(const Vec3& p, Vec3& fraction) const {
  const float fine = float(1 << depth);
  Vec3 q;  // p in finest-lattice units
  glm::ivec3 base;
  for (int k = 0; k < 3; ++k) {
    const float u = std::clamp((p[k] - origin[k]) / base_size[k], 0.f, float(base_cells[k]));
    base[k] = std::min(int(u), base_cells[k] - 1);
    q[k] = u * fine;
  }
  const Cell* cell = &cells[size_t(base.x) + size_t(base_cells.x) * (size_t(base.y) + size_t(base_cells.y) * size_t(base.z))];
  while (cell->first_child >= 0) {
    const float half = 0.5f * float(cell_span(cell->level));
    int child = 0;
    for (int k = 0; k < 3; ++k)
      if (q[k] >= float(cell->lo[k]) + half) child |= 1 << k;
    cell = &cells[size_t(cell->first_child) + size_t(child)];
  }
  const float span = float(cell_span(cell->level));
  for (int k = 0; k < 3; ++k) fraction[k] = std::clamp((q[k] - float(cell->lo[k])) / span, 0.f, 1.f);
  return *cell;
}

namespace {

/// Trilinear weights at fraction `f` of the usable corners, renormalized.
int corner_weights(const Cell& cell, const Vec3& f, uint32_t slots[8], float weights[8]) {
  int used = 0;
  float total = 0.f;
  for (int corner = 0; corner < 8; ++corner) {
    const float w = (corner & 1 ? f.x : 1.f - f.x) * (corner & 2 ? f.y : 1.f - f.y) * (corner & 4 ? f.z : 1.f - f.z);
    if (cell.corner[corner] == kNoNode || w <= 0.f) continue;
    slots[used] = cell.corner[corner];
    weights[used++] = w;
    total += w;
  }
  if (total <= 0.f) return 0;  // surrounded by solid: no cached bounce
  for (int k = 0; k < used; ++k) weights[k] /= total;
  return used;
}

} // namespace

int CellTree::blend(const Vec3& p, uint32_t slots[9], float weights[9], const KeepSide& keep_side) const {
  Vec3 f;
  const Cell& cell = leaf(p, f);
  CellCorners corners;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 bits(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    corners.present[corner] = cell.corner[corner] != kNoNode;
    corners.position[corner] = position(cell.lo + bits * cell_span(cell.level));
    corners.weight[corner] = (bits.x ? f.x : 1.f - f.x) * (bits.y ? f.y : 1.f - f.y) * (bits.z ? f.z : 1.f - f.z);
  }
  bool keep[8];
  keep_side(corners, keep);
  // A wall through the cell: the light's side alone, without the tent (the
  // centre node may stand on either side).
  Cell own_side = cell;
  bool split = false;
  for (int corner = 0; corner < 8; ++corner)
    if (corners.present[corner] && !keep[corner]) {
      own_side.corner[corner] = kNoNode;
      split = true;
    }
  if (split) return corner_weights(own_side, f, slots, weights);
  int used = corner_weights(cell, f, slots, weights);
  if (cell.centre == kNoNode) return used;
  // blend = corners(p) + tent(p) · (centre − corners(centre)): exact at the
  // centre, the corners' blend on the faces.
  const float tent = (1.f - std::abs(2.f * f.x - 1.f)) * (1.f - std::abs(2.f * f.y - 1.f)) * (1.f - std::abs(2.f * f.z - 1.f));
  if (tent <= 0.f) return used;
  uint32_t centre_slots[8];
  float centre_weights[8];
  const int at_centre = corner_weights(cell, Vec3(0.5f), centre_slots, centre_weights);
  for (int c = 0; c < at_centre; ++c)
    for (int k = 0; k < used; ++k)
      if (slots[k] == centre_slots[c]) weights[k] -= tent * centre_weights[c];
  slots[used] = cell.centre;
  weights[used++] = tent;
  return used;
}

void CellTree::write(std::ostream& out) const {
  const uint64_t count = cells.size();
  out.write(reinterpret_cast<const char*>(&origin), sizeof(origin));
  out.write(reinterpret_cast<const char*>(&base_size), sizeof(base_size));
  out.write(reinterpret_cast<const char*>(&base_cells), sizeof(base_cells));
  out.write(reinterpret_cast<const char*>(&depth), sizeof(depth));
  out.write(reinterpret_cast<const char*>(&count), sizeof(count));
  out.write(reinterpret_cast<const char*>(cells.data()), std::streamsize(cells.size() * sizeof(Cell)));
}

bool CellTree::read(std::istream& in, size_t nodes) {
  uint64_t count = 0;
  in.read(reinterpret_cast<char*>(&origin), sizeof(origin));
  in.read(reinterpret_cast<char*>(&base_size), sizeof(base_size));
  in.read(reinterpret_cast<char*>(&base_cells), sizeof(base_cells));
  in.read(reinterpret_cast<char*>(&depth), sizeof(depth));
  in.read(reinterpret_cast<char*>(&count), sizeof(count));
  // Untrusted numbers: each base size within the count before multiplying
  // (no wrap), a finite origin and positive cell sizes (a NaN would make a
  // negative index).
  const auto within = [&](int n) { return n >= 1 && uint64_t(n) <= count; };
  if (!in || depth < 0 || depth > 8 || count > (1u << 24) || !within(base_cells.x) || !within(base_cells.y) || !within(base_cells.z))
    return false;
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(origin[k]) || !std::isfinite(base_size[k]) || !(base_size[k] > 0.f)) return false;
  const uint64_t base = uint64_t(base_cells.x) * base_cells.y * base_cells.z;
  if (base > count) return false;
  if (count > stream_bytes_left(in) / sizeof(Cell)) return false;
  cells.resize(count);
  if (!in.read(reinterpret_cast<char*>(cells.data()), std::streamsize(count * sizeof(Cell)))) return false;
  // Every child index points forward and inside, every corner at a node: a
  // damaged tree must not send a lookup out of bounds or round in a loop.
  for (size_t i = 0; i < cells.size(); ++i) {
    const Cell& c = cells[i];
    if (c.level < 0 || c.level > depth || (c.first_child >= 0 && (size_t(c.first_child) <= i || uint64_t(c.first_child) + 8 > count)))
      return false;
    if (c.first_child >= 0 && c.level == depth) return false;
    for (uint32_t s : c.corner)
      if (s != kNoNode && s >= nodes) return false;
    if (c.centre != kNoNode && (c.centre >= nodes || c.first_child >= 0)) return false;
  }
  return true;
}

} // namespace hilight::adaptive
