#pragma once
/// What the frontends' IFC code shares (the CLI's ifc_luminaires.cpp, ifc_spaces.cpp):
/// reading a file with IfcPlusPlus, placements as matrices, an IfcSpace's
/// extruded footprint, and IFC's axes against hilight's. Only with
/// IfcPlusPlus (HILIGHT_HAVE_IFCPP).
#ifdef HILIGHT_HAVE_IFCPP
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <ifcpp/IFC4/include/IfcAxis2Placement3D.h>
#include <ifcpp/IFC4/include/IfcCartesianPoint.h>
#include <ifcpp/IFC4/include/IfcDirection.h>
#include <ifcpp/IFC4/include/IfcObjectPlacement.h>
#include <ifcpp/IFC4/include/IfcSpace.h>
#include <ifcpp/model/BuildingModel.h>

namespace hilight::cli::ifc {

using Mat = glm::dmat4;

std::wstring wide(const std::string& utf8);
std::string narrow(const std::wstring& w);
/// hilight's axes (+Y up, assimp's reading of IFC) and IFC's (+Z up): IFC (x, y, z) = hilight (x, −z, y).
inline glm::dvec3 to_ifc(const glm::dvec3& h) { return {h.x, -h.z, h.y}; }
inline glm::dvec3 from_ifc(const glm::dvec3& i) { return {i.x, i.z, -i.y}; }
std::vector<double> coordinates(const shared_ptr<IfcCartesianPoint>& p);
glm::dvec3 direction(const shared_ptr<IfcDirection>& d, const glm::dvec3& fallback);
Mat axis_matrix(const shared_ptr<IfcAxis2Placement3D>& a);
Mat placement_matrix(const shared_ptr<IfcObjectPlacement>& p, int depth = 0);

/// A space's footprint: a polygon in its local x, y and the heights it spans.
struct Footprint {
  std::vector<glm::dvec2> polygon;
  double z0 = 0, z1 = 0;
  Mat world{1.0}, to_local{1.0};
  bool contains(const glm::dvec3& p_world) const;
};
/// The footprint of a space whose body is an extruded polyline or rectangle
/// (the usual case); `through_clipping`: also of one cut from such an
/// extrusion (IfcBooleanClippingResult: a room under a roof), uncut.
std::optional<Footprint> footprint(const shared_ptr<IfcSpace>& space, bool through_clipping = false);

/// The file read by IfcPlusPlus; InputError naming it when it cannot be.
shared_ptr<BuildingModel> load(const std::filesystem::path& file);

} // namespace hilight::cli::ifc
#endif
