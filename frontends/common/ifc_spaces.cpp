// The rooms an IFC file names (ifc_spaces.hpp).
#include "ifc_spaces.hpp"

#include "hilight/room_split.hpp"
#include "hilight/scene_origin.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <tuple>

#ifdef HILIGHT_HAVE_IFCPP
#include "ifc_model.hpp"

#include <ifcpp/IFC4/include/IfcBuildingStorey.h>
#include <ifcpp/IFC4/include/IfcLabel.h>
#include <ifcpp/IFC4/include/IfcRelAggregates.h>
#include <ifcpp/model/UnitConverter.h>
#endif

namespace hilight::cli {

namespace {

bool has_ifc_extension(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".ifc";  // .ifczip and the rest: no rooms by name
}

} // namespace

std::vector<NamedRoom> scene_rooms(const std::filesystem::path& file, const PlacementRules& rules, const RayScene& rays) {
  if (rules.region_names.empty() && rules.not_region_names.empty()) return {};
  return scene_rooms(file, rays);
}

std::vector<NamedRoom> scene_rooms(const std::filesystem::path& file, const RayScene& rays) {
  if (auto ifc = read_ifc_rooms(file, rays.scene()); !ifc.rooms.empty()) return std::move(ifc.rooms);
  return named_rooms(std::make_shared<const RoomSplit>(rays));
}

#ifndef HILIGHT_HAVE_IFCPP

IfcRooms read_ifc_rooms(const std::filesystem::path&, const Scene&) { return {}; }

#else

namespace {

std::string label(const shared_ptr<IfcLabel>& l) { return l ? ifc::narrow(l->m_value) : std::string(); }

/// The storey a space belongs to: the one that aggregates it.
shared_ptr<IfcBuildingStorey> storey_of(const shared_ptr<IfcSpace>& space) {
  for (const auto& weak : space->m_Decomposes_inverse)
    if (const auto rel = weak.lock())
      if (const auto storey = dynamic_pointer_cast<IfcBuildingStorey>(rel->m_RelatingObject)) return storey;
  return nullptr;
}

} // namespace

IfcRooms read_ifc_rooms(const std::filesystem::path& file, const Scene& scene) {
  IfcRooms out;
  if (!has_ifc_extension(file)) return out;
  shared_ptr<BuildingModel> model = ifc::load(file);
  model->resolveInverseAttributes();
  const double metres = model->getUnitConverter()->getLengthInMeterFactor();
  const double to_metres = metres > 0 ? metres : 1.0;
  std::vector<std::pair<double, std::string>> storeys;
  std::vector<NamedRoom> found;
  for (const auto& [id, e] : model->getMapIfcEntities()) {
    if (const auto s = dynamic_pointer_cast<IfcBuildingStorey>(e))
      storeys.push_back({glm::dvec3(ifc::placement_matrix(s->m_ObjectPlacement)[3]).z, label(s->m_Name)});
    const auto space = dynamic_pointer_cast<IfcSpace>(e);
    if (!space) continue;
    const auto f = ifc::footprint(space, true);
    if (!f) continue;  // a body hilight cannot outline: not offered
    NamedRoom room;
    room.number = label(space->m_Name);
    room.name = space->m_LongName ? label(space->m_LongName) : room.number;
    if (room.name.empty()) continue;
    if (const auto storey = storey_of(space)) room.storey = label(storey->m_Name);
    // The outline at the floor and at the top, in hilight's axes, metres, then the scene's frame.
    room.y0 = std::numeric_limits<float>::max();
    room.y1 = -std::numeric_limits<float>::max();
    for (const auto& c : f->polygon)
      for (double z : {f->z0, f->z1}) {
        const glm::dvec3 world = ifc::from_ifc(glm::dvec3(f->world * glm::dvec4(c, z, 1.0)) * to_metres);
        const Vec3 local = to_local(world, scene.frame);
        if (z == f->z0) room.footprint.push_back({local.x, local.z});
        room.y0 = std::min(room.y0, local.y);
        room.y1 = std::max(room.y1, local.y);
      }
    room.update_box();
    found.push_back(std::move(room));
  }
  // Lowest storey first, then by number and name: the order does not depend on the reader's maps.
  std::sort(storeys.begin(), storeys.end());
  for (const auto& s : storeys) out.storeys.push_back(s.second);
  const auto floor_dm = [](const NamedRoom& r) { return std::lround(10.0 * r.y0); };  // one storey: one key
  std::stable_sort(found.begin(), found.end(), [&](const NamedRoom& x, const NamedRoom& y) {
    return std::tuple(floor_dm(x), x.number, x.name) < std::tuple(floor_dm(y), y.number, y.name);
  });
  out.rooms = std::move(found);
  return out;
}

#endif

} // namespace hilight::cli
