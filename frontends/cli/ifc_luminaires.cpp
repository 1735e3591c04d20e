// The luminaires of a solve in a copy of its input IFC (ifc_luminaires.hpp).
#include "ifc_luminaires.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#ifdef HILIGHT_HAVE_IFCPP
#include "ifc_model.hpp"

#include <glm/glm.hpp>
#include <ifcpp/IFC4/include/IfcAxis2Placement2D.h>
#include <ifcpp/IFC4/include/IfcAxis2Placement3D.h>
#include <ifcpp/IFC4/include/IfcArbitraryClosedProfileDef.h>
#include <ifcpp/IFC4/include/IfcBuildingStorey.h>
#include <ifcpp/IFC4/include/IfcCartesianPoint.h>
#include <ifcpp/IFC4/include/IfcDirection.h>
#include <ifcpp/IFC4/include/IfcExtrudedAreaSolid.h>
#include <ifcpp/IFC4/include/IfcGeometricRepresentationContext.h>
#include <ifcpp/IFC4/include/IfcGloballyUniqueId.h>
#include <ifcpp/IFC4/include/IfcIdentifier.h>
#include <ifcpp/IFC4/include/IfcLabel.h>
#include <ifcpp/IFC4/include/IfcLengthMeasure.h>
#include <ifcpp/IFC4/include/IfcLightFixture.h>
#include <ifcpp/IFC4/include/IfcLightFixtureTypeEnum.h>
#include <ifcpp/IFC4/include/IfcLocalPlacement.h>
#include <ifcpp/IFC4/include/IfcLuminousFluxMeasure.h>
#include <ifcpp/IFC4/include/IfcOwnerHistory.h>
#include <ifcpp/IFC4/include/IfcPolyline.h>
#include <ifcpp/IFC4/include/IfcPositiveLengthMeasure.h>
#include <ifcpp/IFC4/include/IfcPowerMeasure.h>
#include <ifcpp/IFC4/include/IfcProductDefinitionShape.h>
#include <ifcpp/IFC4/include/IfcProfileTypeEnum.h>
#include <ifcpp/IFC4/include/IfcPropertySet.h>
#include <ifcpp/IFC4/include/IfcPropertySingleValue.h>
#include <ifcpp/IFC4/include/IfcReal.h>
#include <ifcpp/IFC4/include/IfcRectangleProfileDef.h>
#include <ifcpp/IFC4/include/IfcRelContainedInSpatialStructure.h>
#include <ifcpp/IFC4/include/IfcRelReferencedInSpatialStructure.h>
#include <ifcpp/IFC4/include/IfcRelDefinesByProperties.h>
#include <ifcpp/IFC4/include/IfcShapeRepresentation.h>
#include <ifcpp/IFC4/include/IfcSpace.h>
#include <ifcpp/IFC4/include/IfcText.h>
#include <ifcpp/model/BuildingModel.h>
#include <ifcpp/model/UnitConverter.h>
#include <ifcpp/reader/ReaderSTEP.h>
#include <ifcpp/writer/WriterSTEP.h>
#endif

namespace hilight::cli {

#ifndef HILIGHT_HAVE_IFCPP

bool ifc_output_available() { return false; }

IfcWritten write_ifc_luminaires(const std::filesystem::path&, const std::filesystem::path& out, const std::vector<IfcLuminaire>&) {
  throw InputError(out.string(), "IFC output needs IfcPlusPlus, which this build lacks (apt install libifcplusplus-dev libboost-dev, then cmake again)");
}

std::vector<IfcFixture> read_ifc_fixtures(const std::filesystem::path& file) {
  throw InputError(file.string(), "reading IFC fixtures needs IfcPlusPlus, which this build lacks");
}

#else

using namespace ifc;

namespace {

/// An IFC GlobalId (22 characters of IFC's base 64) from a 128-bit hash of `key`: the same luminaire, the same id.
std::wstring global_id(const std::string& key) {
  static const char* chars = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_$";
  uint64_t h1 = 1469598103934665603ull, h2 = 1099511628211ull * 31;
  for (unsigned char c : key) {
    h1 = (h1 ^ c) * 1099511628211ull;
    h2 = (h2 ^ c) * 6364136223846793005ull + 1442695040888963407ull;
  }
  std::wstring out;
  out += wchar_t(chars[(h1 >> 62) & 3]);  // the first character carries 2 bits
  for (int k = 0; k < 21; ++k) {
    const uint64_t word = k < 10 ? h1 >> (6 * k) : h2 >> (6 * (k - 10));
    out += wchar_t(chars[word & 63]);
  }
  return out;
}

shared_ptr<IfcCartesianPoint> point(std::initializer_list<double> c) {
  auto p = make_shared<IfcCartesianPoint>();
  for (double v : c) p->m_Coordinates.push_back(make_shared<IfcLengthMeasure>(v));
  return p;
}

shared_ptr<IfcDirection> dir(std::initializer_list<double> c) {
  auto d = make_shared<IfcDirection>();
  for (double v : c) d->m_DirectionRatios.push_back(make_shared<IfcReal>(v));
  return d;
}

shared_ptr<IfcAxis2Placement3D> axes(const glm::dvec3& at, const glm::dvec3& z, const glm::dvec3& x) {
  auto a = make_shared<IfcAxis2Placement3D>();
  a->m_Location = point({at.x, at.y, at.z});
  a->m_Axis = dir({z.x, z.y, z.z});
  a->m_RefDirection = dir({x.x, x.y, x.z});
  return a;
}

shared_ptr<IfcPropertySingleValue> property(const std::string& name, const shared_ptr<IfcValue>& value) {
  auto p = make_shared<IfcPropertySingleValue>();
  p->m_Name = make_shared<IfcIdentifier>(wide(name));
  p->m_NominalValue = value;
  return p;
}

} // namespace

bool ifc_output_available() { return true; }

IfcWritten write_ifc_luminaires(const std::filesystem::path& source, const std::filesystem::path& out,
                                const std::vector<IfcLuminaire>& luminaires) {
  shared_ptr<BuildingModel> model = load(source);
  const double metres = model->getUnitConverter()->getLengthInMeterFactor();
  const double per_metre = metres > 0 ? 1.0 / metres : 1.0;
  // What the file has: its owner history, its 3D context, its spaces and storeys.
  shared_ptr<IfcOwnerHistory> owner;
  std::vector<shared_ptr<IfcSpace>> spaces;
  std::vector<std::pair<double, shared_ptr<IfcBuildingStorey>>> storeys;
  for (const auto& [id, e] : model->getMapIfcEntities()) {
    if (!owner) owner = dynamic_pointer_cast<IfcOwnerHistory>(e);
    if (const auto s = dynamic_pointer_cast<IfcSpace>(e)) spaces.push_back(s);
    if (const auto s = dynamic_pointer_cast<IfcBuildingStorey>(e))
      storeys.push_back({glm::dvec3(placement_matrix(s->m_ObjectPlacement)[3]).z, s});
  }
  std::sort(storeys.begin(), storeys.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<shared_ptr<IfcSpace>, Footprint>> footprints;
  for (const auto& s : spaces)
    if (auto f = footprint(s, true)) footprints.push_back({s, *f});  // a room under a roof too, as hilight reads rooms (ifc_spaces.cpp)
  shared_ptr<IfcGeometricRepresentationContext> context = model->getIfcGeometricRepresentationContext3D();
  if (!context)
    for (const auto& [id, e] : model->getMapIfcEntities())
      if (const auto c = dynamic_pointer_cast<IfcGeometricRepresentationContext>(e); c && !context) context = c;

  IfcWritten written;
  std::map<BuildingEntity*, std::pair<shared_ptr<IfcSpatialElement>, std::vector<shared_ptr<IfcProduct>>>> contained;
  std::vector<shared_ptr<BuildingEntity>> added;
  const std::string key = std::filesystem::absolute(out).lexically_normal().string();
  for (size_t j = 0; j < luminaires.size(); ++j) {
    const IfcLuminaire& l = luminaires[j];
    const glm::dvec3 at = to_ifc(l.position) * per_metre;
    // Where it stands: the space whose footprint holds it (a hair under the ceiling), else the storey
    // below. Uncut, a room under a roof reaches into the storey above: of the spaces that hold it, the
    // one whose floor is highest.
    shared_ptr<IfcSpatialElement> where;
    std::string where_name;
    double highest_floor = -std::numeric_limits<double>::max();
    for (const auto& [space, f] : footprints) {
      if (!f.contains(at) && !f.contains(at - glm::dvec3(0, 0, 0.05 * per_metre))) continue;
      const double z = (f.world * glm::dvec4(0.0, 0.0, f.z0, 1.0)).z;
      if (where && !(z > highest_floor)) continue;
      where = space, highest_floor = z;
      const auto& label = space->m_LongName ? space->m_LongName : space->m_Name;
      where_name = label ? narrow(label->m_value) : "IfcSpace";
    }
    if (where) ++written.in_spaces;
    if (!where && !storeys.empty()) {
      auto below = storeys.front();
      for (const auto& s : storeys)
        if (s.first <= at.z + 1e-6) below = s;
      where = below.second;
      where_name = below.second->m_Name ? narrow(below.second->m_Name->m_value) : "IfcBuildingStorey";
      ++written.in_storeys;
    }
    written.spaces.push_back(where_name);
    // Placed relative to what holds it, turned as the luminaire (its C0 along local x), aimed along local −z.
    const Mat parent = where ? placement_matrix(where->m_ObjectPlacement) : Mat(1.0);
    const Mat to_parent = glm::inverse(parent);
    const double spin = l.spin_deg * 3.14159265358979323846 / 180.0;
    const glm::dvec3 c0_world = to_ifc({std::cos(spin), 0.0, -std::sin(spin)});  // hilight's C0 turned from +X towards −Z
    const glm::dvec3 down = glm::normalize(to_ifc(l.aim));
    auto placement = make_shared<IfcLocalPlacement>();
    if (where) placement->m_PlacementRelTo = where->m_ObjectPlacement;
    placement->m_RelativePlacement = axes(glm::dvec3(to_parent * glm::dvec4(at, 1.0)), glm::dvec3(to_parent * glm::dvec4(-down, 0.0)),
                                          glm::dvec3(to_parent * glm::dvec4(c0_world, 0.0)));
    auto fixture = make_shared<IfcLightFixture>();
    fixture->m_GlobalId = make_shared<IfcGloballyUniqueId>(global_id(key + "#" + std::to_string(j)));
    fixture->m_OwnerHistory = owner;
    fixture->m_Name = make_shared<IfcLabel>(wide("Luminaire " + std::to_string(j + 1)));
    fixture->m_Description = make_shared<IfcText>(wide(l.product));
    fixture->m_ObjectType = make_shared<IfcLabel>(wide(l.product));
    fixture->m_ObjectPlacement = placement;
    fixture->m_Tag = make_shared<IfcIdentifier>(wide(std::to_string(j + 1)));
    fixture->m_PredefinedType = make_shared<IfcLightFixtureTypeEnum>(IfcLightFixtureTypeEnum::ENUM_DIRECTIONSOURCE);
    // Its body: the outline (at least 5 cm) as a 5 cm box above the luminous opening.
    if (context) {
      const double length = std::max(l.size.x, 0.05) * per_metre, width = std::max(l.size.y, 0.05) * per_metre;
      auto profile = make_shared<IfcRectangleProfileDef>();
      profile->m_ProfileType = make_shared<IfcProfileTypeEnum>(IfcProfileTypeEnum::ENUM_AREA);
      profile->m_Position = make_shared<IfcAxis2Placement2D>();  // optional in IFC4, not to IFC2X3 readers (assimp)
      profile->m_Position->m_Location = point({0, 0});
      profile->m_Position->m_RefDirection = dir({1, 0});
      profile->m_XDim = make_shared<IfcPositiveLengthMeasure>(length);
      profile->m_YDim = make_shared<IfcPositiveLengthMeasure>(width);
      auto solid = make_shared<IfcExtrudedAreaSolid>();
      solid->m_SweptArea = profile;
      solid->m_Position = axes({0, 0, 0}, {0, 0, 1}, {1, 0, 0});
      solid->m_ExtrudedDirection = dir({0, 0, 1});
      solid->m_Depth = make_shared<IfcPositiveLengthMeasure>(0.05 * per_metre);
      auto body = make_shared<IfcShapeRepresentation>();
      body->m_ContextOfItems = context;
      body->m_RepresentationIdentifier = make_shared<IfcLabel>(L"Body");
      body->m_RepresentationType = make_shared<IfcLabel>(L"SweptSolid");
      body->m_Items.push_back(solid);
      auto shape = make_shared<IfcProductDefinitionShape>();
      shape->m_Representations.push_back(body);
      fixture->m_Representation = shape;
      for (const shared_ptr<BuildingEntity>& e : std::initializer_list<shared_ptr<BuildingEntity>>{profile, solid, body, shape}) added.push_back(e);
    }
    // What hilight knows of it.
    auto pset = make_shared<IfcPropertySet>();
    pset->m_GlobalId = make_shared<IfcGloballyUniqueId>(global_id(key + "#pset" + std::to_string(j)));
    pset->m_OwnerHistory = owner;
    pset->m_Name = make_shared<IfcLabel>(L"hilight_Luminaire");
    pset->m_HasProperties.push_back(property("Product", make_shared<IfcLabel>(wide(l.product))));
    pset->m_HasProperties.push_back(property("PhotometryFile", make_shared<IfcLabel>(wide(l.profile))));
    pset->m_HasProperties.push_back(property("DimmingPercent", make_shared<IfcReal>(100.0 * l.dimming)));
    pset->m_HasProperties.push_back(property("LuminousFlux", make_shared<IfcLuminousFluxMeasure>(l.flux_lm)));
    pset->m_HasProperties.push_back(property("Power", make_shared<IfcPowerMeasure>(l.power_w)));
    auto defines = make_shared<IfcRelDefinesByProperties>();
    defines->m_GlobalId = make_shared<IfcGloballyUniqueId>(global_id(key + "#defines" + std::to_string(j)));
    defines->m_OwnerHistory = owner;
    defines->m_RelatedObjects.push_back(fixture);
    defines->m_RelatingPropertyDefinition = pset;
    for (const shared_ptr<BuildingEntity>& e : std::initializer_list<shared_ptr<BuildingEntity>>{fixture, placement, pset, defines}) added.push_back(e);
    for (const auto& p : pset->m_HasProperties) added.push_back(p);
    if (where) {
      auto& entry = contained[where.get()];
      entry.first = where;
      entry.second.push_back(fixture);
    }
  }
  size_t k = 0;
  // Referenced in their space, not contained: Debian's assimp 5.2 reads IFC by IFC2X3's schema and
  // crashes on a contained element it does not know (IfcLightFixture is IFC4's), and hilight reads
  // scenes through it (docs/interchange.md, "IFC").
  for (auto& [raw, entry] : contained) {
    auto rel = make_shared<IfcRelReferencedInSpatialStructure>();
    rel->m_GlobalId = make_shared<IfcGloballyUniqueId>(global_id(key + "#contained" + std::to_string(k++)));
    rel->m_OwnerHistory = owner;
    rel->m_Name = make_shared<IfcLabel>(L"hilight luminaires");
    rel->m_RelatedElements = entry.second;
    rel->m_RelatingStructure = entry.first;
    added.push_back(rel);
  }
  // New ids after the file's, in order; the entities they point to that are new get theirs too.
  int next = model->getMaxUsedEntityId() + 1;
  for (const auto& e : added) {
    std::map<BuildingEntity*, shared_ptr<BuildingEntity>> dependents;
    BuildingModel::collectDependentEntities(e, dependents);
    dependents[e.get()] = e;
    for (auto& [raw, dep] : dependents)
      if (dep && dep->m_entity_id < 0) {
        dep->m_entity_id = next++;
        model->insertEntity(dep);
      }
  }
  model->initFileHeader(wide(out.filename().string()));
  WriterSTEP writer;
  std::stringstream text;
  writer.writeModelToStream(text, model);
  write_atomically(out, text.str());
  return written;
}

std::vector<IfcFixture> read_ifc_fixtures(const std::filesystem::path& file) {
  shared_ptr<BuildingModel> model = load(file);
  const double metres = model->getUnitConverter()->getLengthInMeterFactor();
  model->resolveInverseAttributes();
  std::map<BuildingEntity*, std::string> container;
  const auto name_of = [](const shared_ptr<IfcSpatialElement>& s) {
    const auto& label = s->m_LongName ? s->m_LongName : s->m_Name;
    return label ? narrow(label->m_value) : std::string();
  };
  for (const auto& [id, e] : model->getMapIfcEntities()) {
    if (const auto rel = dynamic_pointer_cast<IfcRelContainedInSpatialStructure>(e); rel && rel->m_RelatingStructure)
      for (const auto& p : rel->m_RelatedElements) container[p.get()] = name_of(rel->m_RelatingStructure);
    if (const auto rel = dynamic_pointer_cast<IfcRelReferencedInSpatialStructure>(e); rel && rel->m_RelatingStructure)
      for (const auto& p : rel->m_RelatedElements) container[p.get()] = name_of(rel->m_RelatingStructure);
  }
  std::vector<IfcFixture> out;
  for (const auto& [id, e] : model->getMapIfcEntities())
    if (const auto f = dynamic_pointer_cast<IfcLightFixture>(e)) {
      IfcFixture x;
      x.name = f->m_Name ? narrow(f->m_Name->m_value) : "";
      x.container = container.count(f.get()) ? container[f.get()] : "";
      x.position = from_ifc(glm::dvec3(placement_matrix(f->m_ObjectPlacement)[3]) * (metres > 0 ? metres : 1.0));
      out.push_back(x);
    }
  return out;
}

#endif

} // namespace hilight::cli
