#pragma once
/// The rooms an IFC file names (issue 34 §5): its IfcSpace entities, each
/// with its long name ('Wohnen'), its number ('5'), its storey and its
/// extruded footprint, read with IfcPlusPlus; what `--place region:NAME`
/// takes and `hilight info` lists, in `hilight solve` and `hilight paint`
/// alike. A build without IfcPlusPlus, or a file that is not IFC, has none.
#include "hilight/light_space.hpp"
#include "hilight/named_room.hpp"
#include "hilight/scene.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hilight::cli {

struct IfcRooms {
  std::vector<NamedRoom> rooms;      ///< in the scene's frame (metres, moved home as the scene was)
  std::vector<std::string> storeys;  ///< every IfcBuildingStorey's name, lowest first
};

/// The IfcSpaces of `file` (the file `scene` was loaded from), for an .ifc
/// file in a build with IfcPlusPlus; empty otherwise. InputError when the
/// file cannot be read as IFC.
IfcRooms read_ifc_rooms(const std::filesystem::path& file, const Scene& scene);

/// The rooms `region:NAME` rules choose from: the IFC's IfcSpaces, else
/// free space split at doors, "room1"... (room_split.hpp). InputError when
/// the IFC cannot be read.
std::vector<NamedRoom> scene_rooms(const std::filesystem::path& file, const RayScene& rays);
/// The same, read only when `rules` name a room (else none: reading costs).
std::vector<NamedRoom> scene_rooms(const std::filesystem::path& file, const PlacementRules& rules, const RayScene& rays);

} // namespace hilight::cli
