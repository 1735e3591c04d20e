#include "core/session.hpp"

#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace hilight::painter {

using json = nlohmann::json;

namespace {

enum class Kind {
  Number,       ///< any finite number
  Positive,     ///< > 0
  NonNegative,  ///< ≥ 0
  Unit,         ///< in [0, 1]
  Count,        ///< integer ≥ 1
  Index,        ///< integer ≥ 0
  Vec2,         ///< [x, y]
  Vec3,         ///< [x, y, z]
  Colour,       ///< [r, g, b] ≥ 0, or one number ≥ 0 for grey
  Points2,      ///< non-empty [[x, y], ...]
  Points3,      ///< non-empty [[x, y, z], ...]
  String,
  ShadowPairs,  ///< non-empty [{"occluder"|"occluder_screen", "world"|"screen"}, ...]
};

struct Field {
  const char* name;
  Kind kind;
};

struct Spec {
  std::vector<Field> fields;
  std::vector<const char*> required;
  /// Groups of fields of which exactly one must be given.
  std::vector<std::vector<const char*>> exactly_one;
  /// Groups given all together or not at all.
  std::vector<std::vector<const char*>> together;
  bool needs_some = false;  ///< at least one field (camera, brush)
};

/// Every action's fields, in the order docs/painter.md lists them: the one
/// list of action types (action_types() reads it).
const std::vector<std::pair<std::string, Spec>>& specs() {
  static const std::vector<std::pair<std::string, Spec>> table = {
      {"camera",
       {{{"orbit", Kind::Vec2}, {"pan", Kind::Vec2}, {"zoom", Kind::Positive}, {"eye", Kind::Vec3},
         {"target", Kind::Vec3}, {"fov", Kind::Positive}},
        {}, {}, {{"eye", "target"}}, true}},
      {"tool", {{{"tool", Kind::String}}, {"tool"}, {}, {}, false}},
      {"view", {{{"show", Kind::String}}, {"show"}, {}, {}, false}},
      {"brush",
       {{{"radius", Kind::Positive}, {"colour", Kind::Colour}, {"brightness", Kind::NonNegative}, {"hardness", Kind::Unit}},
        {}, {}, {}, true}},
      {"stroke",
       {{{"world", Kind::Points3}, {"screen", Kind::Points2}, {"mode", Kind::String}, {"normals", Kind::Points3}},
        {}, {{"world", "screen"}}, {}, false}},
      {"erase", {{{"world", Kind::Points3}, {"screen", Kind::Points2}, {"normals", Kind::Points3}}, {}, {{"world", "screen"}}, {}, false}},
      {"shadow", {{{"pairs", Kind::ShadowPairs}}, {"pairs"}, {}, {}, false}},
      {"erase_shadow", {{{"world", Kind::Vec3}, {"screen", Kind::Vec2}, {"pick", Kind::Index}}, {}, {{"world", "screen"}}, {}, false}},
      {"spot_region",
       {{{"world", Kind::Points3}, {"screen", Kind::Points2}, {"eye", Kind::Vec3}, {"direction", Kind::Vec3},
         {"falloff_deg", Kind::NonNegative}, {"intensity", Kind::Colour}},
        {}, {{"world", "screen"}}, {{"eye", "direction"}}, false}},
      {"adjust_region",
       {{{"world", Kind::Points3}, {"screen", Kind::Points2}, {"multiplier", Kind::Colour}, {"radius", Kind::Positive},
         {"min_share", Kind::Unit}},
        {"multiplier"}, {{"world", "screen"}}, {}, false}},
      {"solve", {}},
      {"fine_tune", {}},
      {"add_lights", {}},
      {"cut", {{{"k", Kind::Count}}, {"k"}, {}, {}, false}},
      {"place", {{{"rules", Kind::String}}, {"rules"}, {}, {}, false}},
      {"undo", {}},
      {"redo", {}},
      {"save_target", {{{"path", Kind::String}}, {"path"}, {}, {}, false}},
      {"save_lights", {{{"path", Kind::String}}, {"path"}, {}, {}, false}},
      {"load_target", {{{"path", Kind::String}}, {"path"}, {}, {}, false}},
      {"load_lights", {{{"path", Kind::String}}, {"path"}, {}, {}, false}},
      {"screenshot", {{{"path", Kind::String}}, {"path"}, {}, {}, false}},
  };
  return table;
}

/// Finite as the float the painter computes with (1e300 is a valid double but inf as float).
bool finite_number(const json& v) {
  return v.is_number() && std::isfinite(v.get<double>()) && std::abs(v.get<double>()) <= double(std::numeric_limits<float>::max());
}
/// > 0 also as float (1e-300 would be 0).
bool positive_number(const json& v) { return finite_number(v) && float(v.get<double>()) > 0.f; }

bool numbers(const json& v, size_t n) {
  if (!v.is_array() || v.size() != n) return false;
  for (const auto& x : v)
    if (!finite_number(x)) return false;
  return true;
}

bool point_list(const json& v, size_t n) {
  if (!v.is_array() || v.empty()) return false;
  for (const auto& p : v)
    if (!numbers(p, n)) return false;
  return true;
}

/// "" when `v` is a valid `kind`, else what it should be.
std::string check_kind(const json& v, Kind kind) {
  switch (kind) {
  case Kind::Number: return finite_number(v) ? "" : "a number (finite as a float)";
  case Kind::Positive: return positive_number(v) ? "" : "a number > 0 (and below 3.4e38, as a float)";
  case Kind::NonNegative: return finite_number(v) && v.get<double>() >= 0 ? "" : "a number ≥ 0 (and below 3.4e38, as a float)";
  case Kind::Unit: return finite_number(v) && v.get<double>() >= 0 && v.get<double>() <= 1 ? "" : "a number in [0, 1]";
  case Kind::Count: return v.is_number_integer() && v.get<long long>() >= 1 ? "" : "an integer ≥ 1";
  case Kind::Index: return v.is_number_integer() && v.get<long long>() >= 0 ? "" : "an integer ≥ 0";
  case Kind::Vec2: return numbers(v, 2) ? "" : "[x, y] (finite as floats)";
  case Kind::Vec3: return numbers(v, 3) ? "" : "[x, y, z] (finite as floats)";
  case Kind::Colour: {
    bool ok = (finite_number(v) && v.get<double>() >= 0) || numbers(v, 3);
    if (ok && v.is_array())
      for (const auto& x : v) ok = ok && x.get<double>() >= 0;
    return ok ? "" : "[r, g, b] (≥ 0) or one number ≥ 0 (finite as floats)";
  }
  case Kind::Points2: return point_list(v, 2) ? "" : "a non-empty list of [x, y]";
  case Kind::Points3: return point_list(v, 3) ? "" : "a non-empty list of [x, y, z]";
  case Kind::String: return v.is_string() ? "" : "a string";
  case Kind::ShadowPairs: {
    if (!v.is_array() || v.empty()) return "a non-empty list of {\"occluder\": [x, y, z], \"world\": [[x, y, z], ...]}";
    for (size_t i = 0; i < v.size(); ++i) {
      const json& p = v[i];
      const std::string at = "pair " + std::to_string(i) + ": ";
      if (!p.is_object()) return at + "an object";
      for (const auto& [key, value] : p.items()) {
        if (key != "occluder" && key != "occluder_screen" && key != "world" && key != "screen")
          return at + "no field '" + key + "' (occluder, occluder_screen, world, screen)";
        (void)value;
      }
      if (p.contains("occluder") == p.contains("occluder_screen")) return at + "exactly one of occluder, occluder_screen";
      if (p.contains("world") == p.contains("screen")) return at + "exactly one of world, screen";
      if (p.contains("occluder") && !numbers(p["occluder"], 3)) return at + "occluder: [x, y, z]";
      if (p.contains("occluder_screen") && !numbers(p["occluder_screen"], 2)) return at + "occluder_screen: [x, y]";
      if (p.contains("world") && !point_list(p["world"], 3)) return at + "world: a non-empty list of [x, y, z]";
      if (p.contains("screen") && !point_list(p["screen"], 2)) return at + "screen: a non-empty list of [x, y]";
    }
    return "";
  }
  }
  return "?";
}

std::string join(const std::vector<const char*>& names) {
  std::string s;
  for (const char* n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

} // namespace

const std::vector<std::string>& action_types() {
  static const std::vector<std::string> types = [] {
    std::vector<std::string> out;
    for (const auto& [type, spec] : specs()) out.push_back(type);
    return out;
  }();
  return types;
}

void validate_action(const Action& action, const std::string& source, size_t index) {
  auto fail = [&](const std::string& problem) {
    throw InputError(source, "action " + std::to_string(index) + ": " + problem);
  };
  auto it = std::find_if(specs().begin(), specs().end(), [&](const auto& entry) { return entry.first == action.type; });
  if (it == specs().end()) fail("unknown type '" + action.type + "'");
  const Spec& spec = it->second;
  if (!action.params.is_object() && !action.params.is_null()) fail(action.type + ": parameters must be an object");
  for (const auto& [key, value] : action.params.items()) {
    const Field* field = nullptr;
    for (const Field& f : spec.fields)
      if (key == f.name) field = &f;
    if (!field) fail(action.type + ": unknown field '" + key + "'");
    std::string expected = check_kind(value, field->kind);
    if (!expected.empty()) fail(action.type + ": '" + key + "' must be " + expected);
  }
  for (const char* name : spec.required)
    if (!action.params.contains(name)) fail(action.type + ": missing '" + name + "'");
  for (const auto& group : spec.exactly_one) {
    size_t given = 0;
    for (const char* name : group) given += action.params.contains(name);
    if (given != 1) fail(action.type + ": needs exactly one of " + join(group));
  }
  for (const auto& group : spec.together) {
    size_t given = 0;
    for (const char* name : group) given += action.params.contains(name);
    if (given != 0 && given != group.size()) fail(action.type + ": give " + join(group) + " together");
  }
  if (spec.needs_some && (action.params.is_null() || action.params.empty())) fail(action.type + ": needs at least one setting");
  if (action.type == "tool") {
    static const std::vector<std::string> tools = {"brush", "eraser", "shadow", "erase_shadow", "spot", "adjust"};
    const std::string name = action.params["tool"].get<std::string>();
    if (std::find(tools.begin(), tools.end(), name) == tools.end())
      fail("tool: unknown tool '" + name + "' (brush, eraser, shadow, erase_shadow, spot, adjust)");
  }
  if (action.type == "view") {
    const std::string show = action.params["show"].get<std::string>();
    if (show != "result" && show != "target" && show != "difference")
      fail("view: 'show' must be result, target or difference, not '" + show + "'");
  }
  if (action.type == "stroke" && action.params.contains("mode")) {
    const std::string mode = action.params["mode"].get<std::string>();
    if (mode != "paint" && mode != "erase") fail("stroke: mode must be 'paint' or 'erase', not '" + mode + "'");
  }
  if ((action.type == "stroke" || action.type == "erase") && action.params.contains("normals")) {
    const json& normals = action.params["normals"];
    if (!action.params.contains("world") || normals.size() != action.params["world"].size())
      fail(action.type + ": 'normals' needs 'world' and one normal per point");
    for (const auto& n : normals) {
      const double l2 = n[0].get<double>() * n[0].get<double>() + n[1].get<double>() * n[1].get<double>() +
                        n[2].get<double>() * n[2].get<double>();
      if (!(l2 > 1e-12) || !std::isfinite(l2)) fail(action.type + ": a normal must be a non-zero [x, y, z]");
    }
  }
  if (action.type == "camera" && action.params.contains("fov") && action.params["fov"].get<double>() >= 180)
    fail("camera: 'fov' must be below 180");
}

Session parse_session(const std::string& text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    throw InputError(source, "not valid JSON (" + what.substr(what.find(']') + 2) + ")");
  }
  if (!doc.is_object() || !doc.contains("actions") || !doc["actions"].is_array())
    throw InputError(source, "a session is a JSON object {\"actions\": [...]}");
  for (const auto& [key, value] : doc.items()) {
    (void)value;
    if (key != "actions") throw InputError(source, "unknown field '" + key + "' (a session has only \"actions\")");
  }
  Session session;
  const json& actions = doc["actions"];
  for (size_t i = 0; i < actions.size(); ++i) {
    const json& a = actions[i];
    if (!a.is_object()) throw InputError(source, "action " + std::to_string(i) + ": must be an object with \"type\"");
    if (!a.contains("type") || !a["type"].is_string())
      throw InputError(source, "action " + std::to_string(i) + ": missing \"type\" (a string)");
    Action action;
    action.type = a["type"].get<std::string>();
    for (const auto& [key, value] : a.items())
      if (key != "type") action.params[key] = value;
    validate_action(action, source, i);
    session.actions.push_back(std::move(action));
  }
  return session;
}

Session read_session(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "cannot be read");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_session(ss.str(), path.string());
}

std::string session_to_json(const Session& session) {
  std::string text = "{\"actions\": [";
  for (size_t i = 0; i < session.actions.size(); ++i) {
    json a = json::object();
    a["type"] = session.actions[i].type;
    for (const auto& [key, value] : session.actions[i].params.items()) a[key] = value;
    text += (i ? ",\n  " : "\n  ") + a.dump();
  }
  text += session.actions.empty() ? "]}\n" : "\n]}\n";
  return text;
}

void write_session(const std::filesystem::path& path, const Session& session) {
  const std::string text = session_to_json(session);
  write_atomically(path, [&](const std::filesystem::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    if (!out) throw InputError(path.string(), "write failed");
  });
}

void SessionRecorder::record(Action action) {
  try {
    validate_action(action, "recorded session", m_session.actions.size());
  } catch (const InputError& e) {
    throw std::logic_error(e.what());
  }
  m_session.actions.push_back(std::move(action));
}

} // namespace hilight::painter
