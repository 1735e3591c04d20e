// Illuminance criteria files (io/criteria_file.hpp).
#include "hilight/io/criteria_file.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/text_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

namespace hilight {

namespace {

using json = nlohmann::json;

double number(const json& obj, const char* key, const std::string& where) {
  if (!obj.contains(key)) throw InputError(where + ": missing \"" + key + "\"");
  const json& v = obj.at(key);
  if (!v.is_number() || !std::isfinite(v.get<double>())) throw InputError(where + ": \"" + key + "\" must be a finite number");
  return v.get<double>();
}

std::vector<Vec3> vectors(const json& arr, const std::string& where) {
  if (!arr.is_array()) throw InputError(where + ": expected an array of [x, y, z]");
  std::vector<Vec3> out;
  out.reserve(arr.size());
  for (size_t i = 0; i < arr.size(); ++i) {
    const json& p = arr[i];
    if (!p.is_array() || p.size() != 3) throw InputError(where + " " + std::to_string(i) + ": expected [x, y, z]");
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
      if (!p[k].is_number() || !std::isfinite(p[k].get<double>()) || std::abs(p[k].get<double>()) > 1e30)
        throw InputError(where + " " + std::to_string(i) + ": coordinates must be finite numbers");
      v[k] = p[k].get<float>();
    }
    out.push_back(v);
  }
  return out;
}

CriterionGrid::Kind kind_named(const std::string& name, const std::string& where) {
  for (auto k : {CriterionGrid::Kind::WorkPlane, CriterionGrid::Kind::Walls, CriterionGrid::Kind::Ceiling})
    if (name == to_string(k)) return k;
  throw InputError(where + ": kind must be workplane, walls or ceiling, not \"" + name + "\"");
}

} // namespace

IlluminanceCriteria parse_criteria(const std::string& text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {  // syntax, or a number beyond a double
    throw InputError(source, std::string("malformed JSON: ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("illuminance_criteria"))
    throw InputError(source, "not an illuminance criteria file (hilight target workplane writes them)");
  static const std::vector<std::string> kUnits = {"mm", "cm", "m", "in", "ft"};
  const std::string unit = doc.contains("length_unit") && doc["length_unit"].is_string() ? doc["length_unit"].get<std::string>() : "m";
  if (std::find(kUnits.begin(), kUnits.end(), unit) == kUnits.end())
    throw InputError(source, "length_unit must be mm, cm, m, in or ft, not \"" + unit + "\"");
  if (!doc.contains("grids") || !doc["grids"].is_array() || doc["grids"].empty())
    throw InputError(source, "expected a non-empty \"grids\" array");
  IlluminanceCriteria c;
  c.source = source;
  c.length_unit = unit;
  try {
    for (size_t g = 0; g < doc["grids"].size(); ++g) {
      const json& obj = doc["grids"][g];
      const std::string where = source + ": grid " + std::to_string(g);
      if (!obj.is_object()) throw InputError(where + ": expected an object");
      CriterionGrid grid;
      grid.kind = kind_named(obj.value("kind", std::string("workplane")), where);
      grid.name = obj.value("name", std::string(to_string(grid.kind)));
      grid.lux = number(obj, "lux", where);
      grid.u0 = obj.contains("u0") ? number(obj, "u0", where) : 0.0;
      grid.spacing = obj.contains("spacing") ? number(obj, "spacing", where) : 0.0;
      if (grid.lux < 0 || grid.lux > 1e7) throw InputError(where + ": lux must be in [0, 1e7]");
      if (grid.u0 < 0 || grid.u0 > 1) throw InputError(where + ": u0 must be in [0, 1]");
      if (!obj.contains("points")) throw InputError(where + ": missing \"points\"");
      grid.points = vectors(obj["points"], where + ": point");
      if (grid.points.empty()) throw InputError(where + ": no points");
      if (obj.contains("normals")) {
        grid.normals = vectors(obj["normals"], where + ": normal");
        if (grid.normals.size() != grid.points.size())
          throw InputError(where + ": " + std::to_string(grid.normals.size()) + " normals for " +
                           std::to_string(grid.points.size()) + " points");
        for (size_t i = 0; i < grid.normals.size(); ++i) {
          const float len = glm::length(grid.normals[i]);
          if (!(len > 1e-6f) || !std::isfinite(len)) throw InputError(where + ": normal " + std::to_string(i) + " has no direction");
          grid.normals[i] /= len;
        }
      } else {
        grid.normals.assign(grid.points.size(), Vec3(0.f, 1.f, 0.f));
      }
      c.grids.push_back(std::move(grid));
    }
  } catch (const json::exception& e) {  // a field of an unexpected JSON type
    throw InputError(source, std::string("malformed criteria: ") + e.what());
  }
  return c;
}

IlluminanceCriteria read_criteria(const std::filesystem::path& path) {
  return parse_criteria(read_text_file(path, "criteria"), path.string());
}

void write_criteria(const std::filesystem::path& path, const IlluminanceCriteria& criteria) {
  json grids = json::array();
  for (const auto& g : criteria.grids) {
    json points = json::array(), normals = json::array();
    for (size_t i = 0; i < g.points.size(); ++i) {
      points.push_back({g.points[i].x, g.points[i].y, g.points[i].z});
      normals.push_back({g.normals[i].x, g.normals[i].y, g.normals[i].z});
    }
    grids.push_back({{"name", g.name}, {"kind", to_string(g.kind)}, {"lux", g.lux}, {"u0", g.u0}, {"spacing", g.spacing},
                     {"points", points}, {"normals", normals}});
  }
  const std::string text = json{{"illuminance_criteria", 1}, {"length_unit", criteria.length_unit}, {"grids", grids}}.dump(1) + "\n";
  write_atomically(path, text);
}

} // namespace hilight
