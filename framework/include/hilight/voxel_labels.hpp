#pragma once
/// The lookup that regions (regions.hpp) and rooms (room_split.hpp) share:
/// both label a box cut into cubic voxels, and a point on a wall's voxel
/// belongs to the space beside it.
#include "hilight/math.hpp"

#include <vector>

namespace hilight {

/// The label of the voxel holding `p` in the grid `labels` (x fastest, `dims`
/// voxels of edge `voxel` from `box.lo`); where that voxel's label is `none`
/// (a wall's), the label of the nearest labelled voxel two or fewer away;
/// `none` outside the box or with nothing near.
int label_near(const std::vector<int>& labels, const glm::ivec3& dims, const Bounds& box, float voxel, const Vec3& p, int none);

} // namespace hilight
