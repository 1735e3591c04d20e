#include "hilight/io/lights_json.hpp"
#include "hilight/io/text_file.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "hilight/io/gltf.hpp"
#include "hilight/io/photometry_io.hpp"
#include "hilight/scene_origin.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

namespace hilight {

using nlohmann::json;

namespace {

glm::dvec3 read_dvec3(const json& obj, const char* key, const std::string& where) {
  if (!obj.contains(key)) throw InputError(where + ": missing \"" + key + "\"");
  const json& v = obj.at(key);
  if (!v.is_array() || v.size() != 3) throw InputError(where + ": \"" + key + "\" must be an array of 3 numbers");
  glm::dvec3 out;
  for (int i = 0; i < 3; ++i) {
    if (!v[i].is_number()) throw InputError(where + ": \"" + key + "\" must be an array of 3 numbers");
    out[i] = v[i].get<double>();
  }
  return out;
}

Vec3 read_vec3(const json& obj, const char* key, const std::string& where) {
  const Vec3 out(read_dvec3(obj, key, where));
  if (!is_finite(out)) throw InputError(where + ": \"" + key + "\" is not finite");
  return out;
}

/// A position, moved into the scene's frame in double precision (a float
/// at 10⁶ m rounds to 6 cm; scene_origin.hpp).
Vec3 read_position(const json& obj, const std::string& where, const SceneFrame* frame) {
  const glm::dvec3 world = read_dvec3(obj, "position", where);
  const Vec3 out = frame ? to_local(world, *frame) : Vec3(world);
  if (!is_finite(out)) throw InputError(where + ": \"position\" is not finite");
  return out;
}

float read_number(const json& obj, const char* key, float fallback, const std::string& where) {
  if (!obj.contains(key)) return fallback;
  if (!obj.at(key).is_number()) throw InputError(where + ": \"" + key + "\" must be a number");
  float v = obj.at(key).get<float>();
  if (!std::isfinite(v)) throw InputError(where + ": \"" + key + "\" is not finite");
  return v;
}

/// Profiles already read in this file (lights of one luminaire share one).
using ProfileCache = std::map<std::string, std::shared_ptr<const Photometry>>;

Light read_luminaire(const json& obj, Light light, const std::string& where, const std::filesystem::path& base,
                     ProfileCache& profiles) {
  light.type = LightType::Luminaire;
  if (!obj.contains("profile") || !obj.at("profile").is_string()) throw InputError(where + ": a luminaire needs \"profile\": the .ies or .ldt file");
  light.profile_path = obj.at("profile").get<std::string>();
  const std::filesystem::path file = std::filesystem::path(light.profile_path).is_absolute() ? std::filesystem::path(light.profile_path)
                                                                                               : base / light.profile_path;
  light.profile_path = std::filesystem::absolute(file).lexically_normal().string();  // valid wherever the lights are written
  auto& profile = profiles[light.profile_path];
  if (!profile) profile = std::make_shared<const Photometry>(read_photometry(file));
  light.profile = profile;
  light.direction = Vec3(0.f, -1.f, 0.f);  // mounted as measured: aimed straight down
  if (obj.contains("direction")) {
    const Vec3 dir = read_vec3(obj, "direction", where);
    if (!(glm::length(dir) > 1e-12f)) throw InputError(where + ": zero-length luminaire direction");
    light.direction = glm::normalize(dir);
  }
  light.spin_deg = read_number(obj, "spin_deg", 0.f, where);
  if (obj.contains("cutoff_deg") || obj.contains("falloff_deg")) throw InputError(where + ": a luminaire's shape is its profile (no cutoff_deg or falloff_deg)");
  const bool has_intensity = obj.contains("intensity"), has_dimming = obj.contains("dimming");
  if (has_intensity == has_dimming) throw InputError(where + ": give a luminaire either \"intensity\" (W/sr at its peak) or \"dimming\" (0-1 of its rated output)");
  if (has_intensity) {
    light.intensity = read_vec3(obj, "intensity", where);
    if (glm::any(glm::lessThan(light.intensity, Vec3(0.f)))) throw InputError(where + ": negative intensity");
  } else {
    const float dimming = read_number(obj, "dimming", 1.f, where);
    if (dimming < 0.f) throw InputError(where + ": dimming must be ≥ 0");
    light.intensity = Rgb(float(dimming * profile->peak() / kCandelaPerWattPerSr));
  }
  return light;
}

/// A rectangle, disk or line: a shape, and a profile or Lambertian emission.
Light read_area(const json& obj, Light light, const std::string& where, const std::filesystem::path& base,
                ProfileCache& profiles) {
  if (obj.contains("cutoff_deg") || obj.contains("falloff_deg"))
    throw InputError(where + ": an area or line source has no cutoff_deg or falloff_deg");
  if (obj.contains("spin_deg") && !obj.contains("profile"))
    throw InputError(where + ": spin_deg turns a profile (an area source's C0 plane is along \"up\", turned spin_deg)");
  light.direction = read_vec3(obj, "direction", where);
  if (light.type == LightType::Disk && !obj.contains("up")) {  // a disk's up only orients a profile
    const Vec3 d = light.direction;
    light.up = std::abs(d.x) > 0.9f ? Vec3(0.f, 0.f, 1.f) : Vec3(1.f, 0.f, 0.f);
  } else {
    light.up = read_vec3(obj, "up", where);
  }
  if (!obj.contains("size") || !obj.at("size").is_array()) throw InputError(where + ": missing \"size\" (an array)");
  const json& size = obj.at("size");
  const size_t want = light.type == LightType::Rectangle ? 2 : 1;
  const char* shape = light.type == LightType::Rectangle ? "[width, height]" : light.type == LightType::Disk ? "[diameter]" : "[length]";
  if (size.size() != want) throw InputError(where + ": \"size\" must be " + shape);
  for (size_t i = 0; i < want; ++i) {
    if (!size[i].is_number()) throw InputError(where + ": \"size\" must be " + shape + " in numbers");
    light.size[int(i)] = size[i].get<float>();
  }
  if (const std::string problem = area_light_problem(light); !problem.empty()) throw InputError(where + ": " + problem);
  light.up = glm::normalize(light.up - glm::dot(light.up, light.direction) * light.direction);
  if (obj.contains("profile")) {
    if (!obj.at("profile").is_string()) throw InputError(where + ": \"profile\" must be the .ies or .ldt file");
    Light lum = read_luminaire(obj, light, where, base, profiles);  // the profile and its intensity or dimming
    light.profile = lum.profile;
    light.profile_path = lum.profile_path;
    light.intensity = lum.intensity;
    light.spin_deg = lum.spin_deg;
    return light;
  }
  if (obj.contains("dimming")) throw InputError(where + ": \"dimming\" needs a \"profile\"");
  light.intensity = read_vec3(obj, "intensity", where);
  if (glm::any(glm::lessThan(light.intensity, Vec3(0.f)))) throw InputError(where + ": negative intensity");
  return light;
}

Light read_light(const json& obj, const std::string& where, const std::filesystem::path& base, ProfileCache& profiles,
                 const SceneFrame* frame) {
  if (!obj.is_object()) throw InputError(where + ": must be an object");
  static const char* kKnown[] = {"type", "position", "intensity", "direction", "cutoff_deg", "falloff_deg", "name",
                                 "profile", "spin_deg", "dimming", "up", "size"};
  for (const auto& [key, value] : obj.items())
    if (std::find(std::begin(kKnown), std::end(kKnown), key) == std::end(kKnown))
      throw InputError(where + ": unknown field \"" + key + "\"");
  if (obj.contains("type") && !obj.at("type").is_string()) throw InputError(where + ": \"type\" must be a string");
  std::string type = obj.value("type", std::string("point"));
  Light light;
  light.position = read_position(obj, where, frame);
  if (type == "luminaire") return read_luminaire(obj, std::move(light), where, base, profiles);
  if (LightType t; light_type_from_string(type, t) && is_area(t)) {
    light.type = t;
    return read_area(obj, std::move(light), where, base, profiles);
  }
  if (obj.contains("up") || obj.contains("size"))
    throw InputError(where + ": up and size belong to an area or line source (\"type\": rectangle, disk or line)");
  if (obj.contains("profile") || obj.contains("spin_deg") || obj.contains("dimming"))
    throw InputError(where + ": profile, spin_deg and dimming belong to a luminaire (\"type\":\"luminaire\")");
  light.intensity = read_vec3(obj, "intensity", where);
  if (glm::any(glm::lessThan(light.intensity, Vec3(0.f)))) throw InputError(where + ": negative intensity");
  if (type == "point") {
    light.type = LightType::Point;
    if (obj.contains("direction") || obj.contains("cutoff_deg") || obj.contains("falloff_deg"))
      throw InputError(where + ": a point light has no direction or cone (use \"type\":\"spot\")");
  } else if (type == "spot") {
    light.type = LightType::Spot;
    Vec3 dir = read_vec3(obj, "direction", where);
    if (!(glm::length(dir) > 1e-12f)) throw InputError(where + ": zero-length spot direction");
    light.direction = glm::normalize(dir);
    light.cutoff_deg = read_number(obj, "cutoff_deg", -1.f, where);
    if (!obj.contains("cutoff_deg")) throw InputError(where + ": missing \"cutoff_deg\"");
    if (!(light.cutoff_deg > 0.f && light.cutoff_deg < 180.f)) throw InputError(where + ": cutoff_deg must be in (0, 180)");
    light.falloff_deg = read_number(obj, "falloff_deg", 0.f, where);
    if (light.falloff_deg < 0.f || light.falloff_deg > light.cutoff_deg)
      throw InputError(where + ": falloff_deg must be in [0, cutoff_deg]");
  } else {
    throw InputError(where + ": unknown light type \"" + type + "\" (point, spot, luminaire, rectangle, disk or line)");
  }
  return light;
}

} // namespace

Lighting parse_lights_json(const std::string& text, const std::string& source, const SceneFrame* frame, std::string* intensity_unit) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {  // a syntax error, or a number beyond a double (1e400)
    throw InputError(source, std::string("malformed JSON: ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("lights") || !doc["lights"].is_array())
    throw InputError(source, "expected an object with a \"lights\" array");
  std::string unit;
  if (doc.contains("intensity_unit")) {
    const json& u = doc["intensity_unit"];
    if (!u.is_string() || (u.get<std::string>() != "W/sr" && u.get<std::string>() != "cd"))
      throw InputError(source, "\"intensity_unit\" must be \"W/sr\" or \"cd\" (got " + u.dump() + ")");
    unit = u.get<std::string>();
  }
  if (intensity_unit) *intensity_unit = unit;
  Lighting lights;
  const json& arr = doc["lights"];
  ProfileCache profiles;
  const std::filesystem::path base = std::filesystem::path(source).parent_path();
  try {
    for (size_t i = 0; i < arr.size(); ++i) {
      lights.push_back(read_light(arr[i], source + ": light " + std::to_string(i), base, profiles, frame));
      if (frame) lights.back().size *= float(frame->scale);  // a length in the file's unit
    }
  } catch (const json::exception& e) {  // a value of an unexpected JSON type
    throw InputError(source, std::string("malformed light: ") + e.what());
  }
  return lights;
}

Lighting read_lights_json(const std::filesystem::path& path, const SceneFrame* frame, std::string* intensity_unit) {
  return parse_lights_json(read_text_file(path, "lights"), path.string(), frame, intensity_unit);
}

std::string lights_to_json(const Lighting& lights, const std::string& length_unit, const SceneFrame* frame,
                           const std::string& intensity_unit) {
  json arr = json::array();
  for (size_t j = 0; j < lights.size(); ++j) {
    const Light& l = lights[j];
    // JSON has no NaN: nlohmann writes null, which no reader takes back
    // (issue 35). Input checks keep such numbers out: one here is a bug.
    if (!is_finite(l.position) || !is_finite(l.intensity) || !is_finite(l.direction) || !std::isfinite(l.cutoff_deg) ||
        !std::isfinite(l.falloff_deg) || !std::isfinite(l.spin_deg))
      throw std::logic_error("light " + std::to_string(j) + " to be written has a NaN or infinite value");
    json o;
    o["type"] = to_string(l.type);
    // In the world's frame, moved out in double (float would round a far position).
    const glm::dvec3 position = frame ? to_world(l.position, *frame) : glm::dvec3(l.position);
    o["position"] = {position.x, position.y, position.z};
    if (l.type == LightType::Spot) {
      o["direction"] = {l.direction.x, l.direction.y, l.direction.z};
      o["cutoff_deg"] = l.cutoff_deg;
      o["falloff_deg"] = l.falloff_deg;
    }
    if (l.type == LightType::Luminaire) {
      o["profile"] = l.profile_path;
      o["direction"] = {l.direction.x, l.direction.y, l.direction.z};
      o["spin_deg"] = l.spin_deg;
    }
    if (is_area(l.type)) {
      o["direction"] = {l.direction.x, l.direction.y, l.direction.z};
      o["up"] = {l.up.x, l.up.y, l.up.z};
      const double per_unit = frame ? 1.0 / frame->scale : 1.0;  // sizes in the file's unit
      o["size"] = l.type == LightType::Rectangle ? json{l.size[0] * per_unit, l.size[1] * per_unit} : json{l.size[0] * per_unit};
      if (l.profile) {
        o["profile"] = l.profile_path;
        o["spin_deg"] = l.spin_deg;
      }
    }
    o["intensity"] = {l.intensity.r, l.intensity.g, l.intensity.b};
    arr.push_back(o);
  }
  return json{{"length_unit", length_unit}, {"intensity_unit", intensity_unit}, {"lights", arr}}.dump(2) + "\n";
}

void write_lights_json(const std::filesystem::path& path, const Lighting& lights, const std::string& length_unit,
                       const SceneFrame* frame, const std::string& intensity_unit) {
  std::string text = lights_to_json(lights, length_unit, frame, intensity_unit);
  write_atomically(path, text);
}

} // namespace hilight
