// What the frontends' IFC code shares (ifc_model.hpp).
#include "ifc_model.hpp"

#ifdef HILIGHT_HAVE_IFCPP
#include "hilight/error.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>

#include <ifcpp/IFC4/include/IfcArbitraryClosedProfileDef.h>
#include <ifcpp/IFC4/include/IfcAxis2Placement2D.h>
#include <ifcpp/IFC4/include/IfcBooleanResult.h>
#include <ifcpp/IFC4/include/IfcExtrudedAreaSolid.h>
#include <ifcpp/IFC4/include/IfcLengthMeasure.h>
#include <ifcpp/IFC4/include/IfcLocalPlacement.h>
#include <ifcpp/IFC4/include/IfcPolyline.h>
#include <ifcpp/IFC4/include/IfcPositiveLengthMeasure.h>
#include <ifcpp/IFC4/include/IfcProductDefinitionShape.h>
#include <ifcpp/IFC4/include/IfcReal.h>
#include <ifcpp/IFC4/include/IfcRectangleProfileDef.h>
#include <ifcpp/IFC4/include/IfcRepresentation.h>
#include <ifcpp/reader/ReaderSTEP.h>

namespace hilight::cli::ifc {

std::wstring wide(const std::string& utf8) {
  std::wstring out;
  for (size_t i = 0; i < utf8.size();) {
    const unsigned char c = static_cast<unsigned char>(utf8[i]);
    const int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + size_t(extra) >= utf8.size() + (extra == 0 ? 1 : 0)) {
      out += L'?';
      ++i;
      continue;
    }
    uint32_t code = extra == 0 ? c : c & (0x3F >> extra);
    for (int k = 1; k <= extra; ++k) code = code << 6 | (static_cast<unsigned char>(utf8[i + size_t(k)]) & 0x3F);
    out += wchar_t(code);
    i += size_t(extra) + 1;
  }
  return out;
}

std::string narrow(const std::wstring& w) {
  std::string out;
  for (wchar_t wc : w) {
    const uint32_t c = uint32_t(wc);
    if (c < 0x80) out += char(c);
    else if (c < 0x800) out += char(0xC0 | c >> 6), out += char(0x80 | (c & 0x3F));
    else if (c < 0x10000) out += char(0xE0 | c >> 12), out += char(0x80 | (c >> 6 & 0x3F)), out += char(0x80 | (c & 0x3F));
    else out += char(0xF0 | c >> 18), out += char(0x80 | (c >> 12 & 0x3F)), out += char(0x80 | (c >> 6 & 0x3F)), out += char(0x80 | (c & 0x3F));
  }
  return out;
}


std::vector<double> coordinates(const shared_ptr<IfcCartesianPoint>& p) {
  std::vector<double> out;
  if (p)
    for (const auto& c : p->m_Coordinates) out.push_back(c ? c->m_value : 0.0);
  return out;
}

glm::dvec3 direction(const shared_ptr<IfcDirection>& d, const glm::dvec3& fallback) {
  if (!d) return fallback;
  glm::dvec3 v(0.0);
  for (size_t k = 0; k < d->m_DirectionRatios.size() && k < 3; ++k) v[int(k)] = d->m_DirectionRatios[k] ? d->m_DirectionRatios[k]->m_value : 0.0;
  return glm::length(v) > 1e-12 ? glm::normalize(v) : fallback;
}

Mat axis_matrix(const shared_ptr<IfcAxis2Placement3D>& a) {
  if (!a) return Mat(1.0);
  const auto c = coordinates(a->m_Location);
  const glm::dvec3 origin(c.size() > 0 ? c[0] : 0.0, c.size() > 1 ? c[1] : 0.0, c.size() > 2 ? c[2] : 0.0);
  const glm::dvec3 z = direction(a->m_Axis, {0, 0, 1});
  glm::dvec3 x = direction(a->m_RefDirection, {1, 0, 0});
  x = x - glm::dot(x, z) * z;
  if (glm::length(x) < 1e-9) x = std::abs(z.x) < 0.9 ? glm::dvec3(1, 0, 0) - z.x * z : glm::dvec3(0, 1, 0) - z.y * z;
  x = glm::normalize(x);
  const glm::dvec3 y = glm::cross(z, x);
  Mat m(1.0);
  m[0] = glm::dvec4(x, 0);
  m[1] = glm::dvec4(y, 0);
  m[2] = glm::dvec4(z, 0);
  m[3] = glm::dvec4(origin, 1);
  return m;
}

Mat placement_matrix(const shared_ptr<IfcObjectPlacement>& p, int depth) {
  const auto local = dynamic_pointer_cast<IfcLocalPlacement>(p);
  if (!local || depth > 64) return Mat(1.0);
  const Mat parent = local->m_PlacementRelTo ? placement_matrix(local->m_PlacementRelTo, depth + 1) : Mat(1.0);
  return parent * axis_matrix(dynamic_pointer_cast<IfcAxis2Placement3D>(local->m_RelativePlacement));
}

bool Footprint::contains(const glm::dvec3& p_world) const {
  const glm::dvec3 p(to_local * glm::dvec4(p_world, 1.0));
  if (p.z < z0 - 1e-6 || p.z > z1 + 1e-6 || polygon.size() < 3) return false;
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::dvec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

/// The footprint of a space whose body is an extruded polyline or rectangle (the usual case).
std::optional<Footprint> footprint(const shared_ptr<IfcSpace>& space, bool through_clipping) {
  if (!space->m_Representation) return std::nullopt;
  for (const auto& rep : space->m_Representation->m_Representations) {
    if (!rep) continue;
    for (const auto& item : rep->m_Items) {
      auto solid = dynamic_pointer_cast<IfcExtrudedAreaSolid>(item);
      // A space clipped by its roof (a gallery under the slopes): the extrusion it was cut from.
      shared_ptr<IfcBooleanOperand> operand = through_clipping ? dynamic_pointer_cast<IfcBooleanResult>(item) : nullptr;
      for (int depth = 0; !solid && operand && depth < 16; ++depth) {
        const auto boolean = dynamic_pointer_cast<IfcBooleanResult>(operand);
        operand = boolean ? boolean->m_FirstOperand : nullptr;
        solid = dynamic_pointer_cast<IfcExtrudedAreaSolid>(operand);
      }
      if (!solid || !solid->m_Depth) continue;
      Footprint f;
      const Mat body = axis_matrix(solid->m_Position);
      f.world = placement_matrix(space->m_ObjectPlacement) * body;
      f.to_local = glm::inverse(f.world);
      const glm::dvec3 up = direction(solid->m_ExtrudedDirection, {0, 0, 1});
      f.z1 = solid->m_Depth->m_value * up.z;
      if (f.z1 < 0) std::swap(f.z0, f.z1);
      if (const auto poly = dynamic_pointer_cast<IfcArbitraryClosedProfileDef>(solid->m_SweptArea)) {
        if (const auto line = dynamic_pointer_cast<IfcPolyline>(poly->m_OuterCurve))
          for (const auto& pt : line->m_Points) {
            const auto c = coordinates(pt);
            if (c.size() >= 2) f.polygon.push_back({c[0], c[1]});
          }
      } else if (const auto rect = dynamic_pointer_cast<IfcRectangleProfileDef>(solid->m_SweptArea)) {
        if (rect->m_XDim && rect->m_YDim) {
          const double hx = 0.5 * rect->m_XDim->m_value, hy = 0.5 * rect->m_YDim->m_value;
          Mat at(1.0);
          if (rect->m_Position) {
            const auto c = coordinates(rect->m_Position->m_Location);
            const glm::dvec3 x = direction(rect->m_Position->m_RefDirection, {1, 0, 0});
            at[0] = glm::dvec4(x.x, x.y, 0, 0);
            at[1] = glm::dvec4(-x.y, x.x, 0, 0);
            at[3] = glm::dvec4(c.size() > 0 ? c[0] : 0, c.size() > 1 ? c[1] : 0, 0, 1);
          }
          for (const glm::dvec2 corner : {glm::dvec2(-hx, -hy), glm::dvec2(hx, -hy), glm::dvec2(hx, hy), glm::dvec2(-hx, hy)})
            f.polygon.push_back(glm::dvec2(at * glm::dvec4(corner, 0, 1)));
        }
      }
      if (f.polygon.size() >= 3) return f;
    }
  }
  return std::nullopt;
}

shared_ptr<BuildingModel> load(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot open it to read");
  std::stringstream text;
  text << in.rdbuf();
  std::string content = text.str();
  if (content.find("ISO-10303-21") == std::string::npos) throw InputError(file.string(), "not an IFC file (STEP, ISO 10303-21)");
  auto model = make_shared<BuildingModel>();
  ReaderSTEP reader;
  try {
    reader.loadModelFromString(content, model);
  } catch (const std::exception& e) {
    throw InputError(file.string(), std::string("IfcPlusPlus cannot read it: ") + e.what());
  }
  if (model->getMapIfcEntities().empty()) throw InputError(file.string(), "IfcPlusPlus read no entity from it");
  return model;
}


} // namespace hilight::cli::ifc
#endif
