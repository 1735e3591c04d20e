#pragma once
/// The connected parts of free space (issue 10 §1): rooms and storeys joined
/// by doors, stairs and openings. Found by flood-filling a voxelisation of
/// the scene's light bounds: voxels a surface passes through are walls, the
/// rest fill 6-connected; parts inside solids (a closed cabinet) and
/// pockets under 32 voxels are not regions. Regions are numbered by size, largest first, so the numbers
/// `hilight info` prints are the ones `--place region:K` and `not-region:K`
/// take.
#include "hilight/ray_scene.hpp"

#include <vector>

namespace hilight {

struct Region {
  int id = 0;
  Bounds box;          ///< the region's voxels' bounding box
  double volume = 0;   ///< scene units cubed
  /// Its voxels reach a side of the light bounds: the outside of a closed
  /// building (a room's walls keep it off every side), or any part of an
  /// open scene. A building's frontends do not offer it as a room.
  bool at_border = false;
};

class Regions {
public:
  /// `cells`: voxels along the longest axis of the scene's light bounds.
  explicit Regions(const RayScene& rays, int cells = 64);

  const std::vector<Region>& list() const { return m_regions; }
  /// The region `p` stands in; -1 outside the light bounds or with no region
  /// in the voxels around it (inside a solid). A point in a wall's voxel
  /// takes the region of the nearest free voxel at most two away.
  int at(const Vec3& p) const;
  float voxel_size() const { return m_voxel; }

private:
  size_t index(int x, int y, int z) const { return (size_t(z) * m_dims.y + size_t(y)) * m_dims.x + size_t(x); }
  Bounds m_box;
  glm::ivec3 m_dims{0};
  float m_voxel = 0.f;
  std::vector<int> m_label;  ///< per voxel: region id, -1 wall or no region
  std::vector<Region> m_regions;
};

} // namespace hilight
