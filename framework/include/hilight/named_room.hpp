#pragma once
/// A room with a name (issue 34 §5) that `--place region:NAME` names and
/// `hilight info` lists: an IfcSpace of an IFC file, its footprint extruded
/// over its height, or elsewhere a room of free space split at doors
/// ("room1", room_split.hpp). In the scene's frame (scene_origin.hpp), +Y up.
#include "hilight/math.hpp"

#include <memory>
#include <string>
#include <vector>

namespace hilight {

class RoomSplit;

struct NamedRoom {
  std::string name;    ///< what `region:NAME` matches (an IfcSpace's long name, else its name)
  std::string number;  ///< the IfcSpace's short name ("6"), listed only: region:6 is region 6
  std::string storey;  ///< the storey holding it ("" if none)
  std::vector<glm::vec2> footprint;  ///< (x, z) corners of its outline
  float y0 = 0.f, y1 = 0.f;          ///< floor and top of the space
  Bounds box;                        ///< the footprint over y0..y1 (a split room: its voxels' box)
  /// A room of free space split at doors: its number there (no footprint).
  std::shared_ptr<const RoomSplit> split;
  int split_number = 0;

  /// `p` stands over the footprint, between y0 and y1 (a split room: in its voxels).
  bool contains(const Vec3& p) const;
  /// The box from footprint, y0 and y1.
  void update_box();
};

/// The rooms of a split, named "room1", "room2", ... by their numbers.
std::vector<NamedRoom> named_rooms(const std::shared_ptr<const RoomSplit>& split);

/// The rooms `name` picks: those whose name is `name`, or every
/// room of the storey `name` (exact first, then ignoring ASCII case).
std::vector<const NamedRoom*> rooms_named(const std::vector<NamedRoom>& rooms, const std::string& name);

} // namespace hilight
