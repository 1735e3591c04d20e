#pragma once
/// Free space split at doors into rooms (issue 34 §5), for scenes that do
/// not name their rooms (anything but an IFC file with IfcSpaces). Regions
/// (regions.hpp) join rooms through every opening; here the opening of a
/// door is what separates them: free space farther than kCoreClearance from
/// every surface (the air of a room, above its furniture) falls apart at
/// doors, whose half width is less; each such core grows back over the free
/// space around it, the nearer core first, so a doorway is shared by the
/// rooms on its two sides. Space connected to the sides of the light bounds
/// (the outside of a building, a product's surroundings) is no room. Rooms
/// are numbered from 1 by their floor (lowest storey first, within 0.5 m),
/// then along x, then along z: a sofa moved does not renumber them.
#include "hilight/ray_scene.hpp"

#include <vector>

namespace hilight {

class RoomSplit {
public:
  /// Metres: half of the widest door that still separates two rooms
  /// (1.1 m); a corridor narrower than twice this joins what it leads to.
  static constexpr float kCoreClearance = 0.55f;

  struct Room {
    int number = 0;      ///< from 1
    Bounds box;          ///< its voxels' bounding box
    double volume = 0;   ///< scene units cubed
  };

  /// `voxel`: the grid's step in metres (at least the longest axis / 160).
  explicit RoomSplit(const RayScene& rays, float voxel = 0.1f);

  const std::vector<Room>& list() const { return m_rooms; }
  /// The number of the room `p` stands in; 0 outside every room.
  int at(const Vec3& p) const;

private:
  size_t index(int x, int y, int z) const { return (size_t(z) * m_dims.y + size_t(y)) * m_dims.x + size_t(x); }
  Bounds m_box;
  glm::ivec3 m_dims{0};
  float m_voxel = 0.f;
  std::vector<int> m_label;  ///< per voxel: room number, 0 none
  std::vector<Room> m_rooms;
};

} // namespace hilight
