#pragma once
/// The lookup that regions (regions.hpp) and rooms (room_split.hpp) share:
/// both label a box cut into cubic voxels, and a point on a wall's voxel
/// belongs to the space beside it.
#include "hilight/math.hpp"

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace hilight {

/// The label of the voxel holding `p` in the grid `labels` (x fastest, `dims`
/// voxels of edge `voxel` from `box.lo`); where that voxel's label is `none`
/// (a wall's), the label of the nearest labelled voxel two or fewer away;
/// `none` outside the box or with nothing near.
/// One part of a grid's 6-connected voxels: how many voxels, and its first (lowest index).
struct VoxelPart {
  size_t voxels = 0;
  size_t first = 0;
};

/// Labels the 6-connected parts of the voxels `in` accepts and `labels`
/// still holds `unlabelled` at, scanning in index order: the k-th part found
/// gets `first_label + k`. Returns the parts in that order.
std::vector<VoxelPart> label_parts(const glm::ivec3& dims, const std::function<bool(size_t)>& in, std::vector<int>& labels,
                                   int unlabelled, int first_label);

int label_near(const std::vector<int>& labels, const glm::ivec3& dims, const Bounds& box, float voxel, const Vec3& p, int none);

} // namespace hilight
