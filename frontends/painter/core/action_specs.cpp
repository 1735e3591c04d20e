// One spec per painter action (core/actions.hpp): its JSON schema (the
// fields, their kinds and which go together), how it reads from and writes to
// JSON, here side by side; its apply function is SessionPlayer::run for the
// same struct (session_player.cpp). The table of specs is generated from the
// TypedAction variant, so the variant is the one list of action types.
#include "core/actions.hpp"
#include "core/paint_meaning.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace hilight::painter {

using json = nlohmann::json;

const char* to_string(Tool tool) {
  switch (tool) {
  case Tool::Brush: return "brush";
  case Tool::Eraser: return "eraser";
  case Tool::Shadow: return "shadow";
  case Tool::EraseShadow: return "erase_shadow";
  case Tool::Spot: return "spot";
  case Tool::Adjust: return "adjust";
  }
  return "?";
}

std::optional<Tool> tool_from_string(const std::string& name) {
  for (Tool t : {Tool::Brush, Tool::Eraser, Tool::Shadow, Tool::EraseShadow, Tool::Spot, Tool::Adjust})
    if (name == to_string(t)) return t;
  return std::nullopt;
}

const char* to_string(ViewShown view) {
  return view == ViewShown::Target ? "target" : view == ViewShown::Difference ? "difference" : "result";
}

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
  Bool,         ///< true or false
  Indices,      ///< non-empty [i, ...] of integers ≥ 0
  True,         ///< true (a switch that is only ever given on: "off": true)
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

/// Each action's schema (schema_of<T>) and JSON reading (read(json, Is<T>))
/// and writing (write(const T&)), below per action.
template <class T>
Spec schema_of();
template <class T>
struct Is {};

Vec2 vec2(const json& v) { return Vec2(v[0].get<float>(), v[1].get<float>()); }
Vec3 vec3(const json& v) { return Vec3(v[0].get<float>(), v[1].get<float>(), v[2].get<float>()); }
Rgb colour(const json& v) { return v.is_array() ? vec3(v) : Rgb(v.get<float>()); }
json of(const Vec2& v) { return {v.x, v.y}; }
json of(const Vec3& v) { return {v.x, v.y, v.z}; }

PointSet read_points(const json& p) {
  PointSet s;
  if (p.contains("world"))
    for (const auto& q : p["world"]) s.world.push_back(vec3(q));
  if (p.contains("screen"))
    for (const auto& q : p["screen"]) s.screen.push_back(vec2(q));
  if (p.contains("normals"))
    for (const auto& q : p["normals"]) s.normals.push_back(vec3(q));
  return s;
}

json write_points(const PointSet& s) {
  json p = json::object();
  auto list = [](const auto& points) {
    json out = json::array();
    for (const auto& q : points) out.push_back(of(q));
    return out;
  };
  if (!s.world.empty()) p["world"] = list(s.world);
  if (!s.screen.empty()) p["screen"] = list(s.screen);
  if (!s.normals.empty()) p["normals"] = list(s.normals);
  return p;
}

// CameraAction
template <>
Spec schema_of<CameraAction>() {
  return {{{"orbit", Kind::Vec2}, {"pan", Kind::Vec2}, {"zoom", Kind::Positive}, {"eye", Kind::Vec3},
         {"target", Kind::Vec3}, {"fov", Kind::Positive}},
        {}, {}, {{"eye", "target"}}, true};
}
CameraAction read(const json& p, Is<CameraAction>) {
  CameraAction a;
  if (p.contains("orbit")) a.orbit = vec2(p["orbit"]);
  if (p.contains("pan")) a.pan = vec2(p["pan"]);
  if (p.contains("zoom")) a.zoom = p["zoom"].get<float>();
  if (p.contains("fov")) a.fov = p["fov"].get<float>();
  if (p.contains("eye")) a.eye = vec3(p["eye"]);
  if (p.contains("target")) a.target = vec3(p["target"]);
  return a;
}
json write(const CameraAction& a) {
  json p = json::object();
  if (a.orbit) p["orbit"] = of(*a.orbit);
  if (a.pan) p["pan"] = of(*a.pan);
  if (a.zoom) p["zoom"] = *a.zoom;
  if (a.eye) p["eye"] = of(*a.eye);
  if (a.target) p["target"] = of(*a.target);
  if (a.fov) p["fov"] = *a.fov;
  return p;
}

// ToolAction
template <>
Spec schema_of<ToolAction>() {
  return {{{"tool", Kind::String}}, {"tool"}, {}, {}, false};
}
ToolAction read(const json& p, Is<ToolAction>) { return {*tool_from_string(p["tool"].get<std::string>())}; }
json write(const ToolAction& a) { return {{"tool", to_string(a.tool)}}; }

// ViewAction
template <>
Spec schema_of<ViewAction>() {
  return {{{"show", Kind::String}}, {"show"}, {}, {}, false};
}
ViewAction read(const json& p, Is<ViewAction>) {
  const std::string show = p["show"].get<std::string>();
  return {show == "target" ? ViewShown::Target : show == "difference" ? ViewShown::Difference : ViewShown::Result};
}
json write(const ViewAction& a) { return {{"show", to_string(a.show)}}; }

// SectionAction
template <>
Spec schema_of<SectionAction>() {
  return {{{"height", Kind::Number}, {"off", Kind::True}}, {}, {{"height", "off"}}, {}, false};
}
SectionAction read(const json& p, Is<SectionAction>) {
  SectionAction a;
  if (p.contains("height")) a.height = p["height"].get<float>();
  return a;
}
json write(const SectionAction& a) {
  if (a.height) return {{"height", *a.height}};
  return {{"off", true}};
}

// CutawayAction
template <>
Spec schema_of<CutawayAction>() {
  return {{{"on", Kind::Bool}}, {"on"}, {}, {}, false};
}
CutawayAction read(const json& p, Is<CutawayAction>) { return {p["on"].get<bool>()}; }
json write(const CutawayAction& a) { return {{"on", a.on}}; }

// PlanAction
template <>
Spec schema_of<PlanAction>() {
  return {{{"on", Kind::Bool}}, {"on"}, {}, {}, false};
}
PlanAction read(const json& p, Is<PlanAction>) { return {p["on"].get<bool>()}; }
json write(const PlanAction& a) { return {{"on", a.on}}; }

// FocusAction
template <>
Spec schema_of<FocusAction>() {
  return {{{"regions", Kind::Indices}, {"world", Kind::Vec3}, {"off", Kind::True}}, {}, {{"regions", "world", "off"}}, {}, false};
}
FocusAction read(const json& p, Is<FocusAction>) {
  FocusAction a;
  if (p.contains("regions"))
    for (const auto& r : p["regions"]) a.regions.push_back(r.get<int>());
  if (p.contains("world")) a.world = vec3(p["world"]);
  a.off = p.contains("off");
  return a;
}
json write(const FocusAction& a) {
  if (a.world) return {{"world", of(*a.world)}};
  if (a.off) return {{"off", true}};
  return {{"regions", a.regions}};
}

// WalkAction
template <>
Spec schema_of<WalkAction>() {
  return {{{"on", Kind::Bool}, {"move", Kind::Vec2}, {"turn", Kind::Vec2}}, {}, {}, {}, true};
}
WalkAction read(const json& p, Is<WalkAction>) {
  WalkAction a;
  if (p.contains("on")) a.on = p["on"].get<bool>();
  if (p.contains("move")) a.move = vec2(p["move"]);
  if (p.contains("turn")) a.turn = vec2(p["turn"]);
  return a;
}
json write(const WalkAction& a) {
  json p = json::object();
  if (a.on) p["on"] = *a.on;
  if (a.move) p["move"] = of(*a.move);
  if (a.turn) p["turn"] = of(*a.turn);
  return p;
}

// BrushAction
template <>
Spec schema_of<BrushAction>() {
  return {{{"radius", Kind::Positive}, {"colour", Kind::Colour}, {"brightness", Kind::NonNegative}, {"hardness", Kind::Unit},
           {"meaning", Kind::String}},
        {}, {}, {}, true};
}
BrushAction read(const json& p, Is<BrushAction>) {
  BrushAction a;
  if (p.contains("radius")) a.radius = p["radius"].get<float>();
  if (p.contains("colour")) a.colour = colour(p["colour"]);
  if (p.contains("brightness")) a.brightness = p["brightness"].get<float>();
  if (p.contains("hardness")) a.hardness = p["hardness"].get<float>();
  if (p.contains("meaning")) a.meaning = p["meaning"].get<std::string>();
  return a;
}
json write(const BrushAction& a) {
  json p = json::object();
  if (a.radius) p["radius"] = *a.radius;
  if (a.colour) p["colour"] = of(*a.colour);
  if (a.brightness) p["brightness"] = *a.brightness;
  if (a.hardness) p["hardness"] = *a.hardness;
  if (a.meaning) p["meaning"] = *a.meaning;
  return p;
}

// StrokeAction
template <>
Spec schema_of<StrokeAction>() {
  return {{{"world", Kind::Points3}, {"screen", Kind::Points2}, {"mode", Kind::String}, {"normals", Kind::Points3}},
        {}, {{"world", "screen"}}, {}, false};
}
StrokeAction read(const json& p, Is<StrokeAction>) {
  StrokeAction a{read_points(p), std::nullopt};
  if (p.contains("mode")) a.erase = p["mode"] == "erase";
  return a;
}
json write(const StrokeAction& a) {
  json p = write_points(a.points);
  if (a.erase) p["mode"] = *a.erase ? "erase" : "paint";
  return p;
}

// EraseAction
template <>
Spec schema_of<EraseAction>() {
  return {{{"world", Kind::Points3}, {"screen", Kind::Points2}, {"normals", Kind::Points3}}, {}, {{"world", "screen"}}, {}, false};
}
EraseAction read(const json& p, Is<EraseAction>) { return {read_points(p)}; }
json write(const EraseAction& a) { return write_points(a.points); }

// ShadowAction
template <>
Spec schema_of<ShadowAction>() {
  return {{{"pairs", Kind::ShadowPairs}}, {"pairs"}, {}, {}, false};
}
ShadowAction read(const json& p, Is<ShadowAction>) {
  ShadowAction a;
  for (const auto& pair : p["pairs"]) {
    ShadowAction::Pair q;
    if (pair.contains("occluder")) q.occluder = vec3(pair["occluder"]);
    if (pair.contains("occluder_screen")) q.occluder_screen = vec2(pair["occluder_screen"]);
    q.points = read_points(pair);
    a.pairs.push_back(std::move(q));
  }
  return a;
}
json write(const ShadowAction& a) {
  json pairs = json::array();
  for (const auto& q : a.pairs) {
    json pair = write_points(q.points);
    if (q.occluder) pair["occluder"] = of(*q.occluder);
    if (q.occluder_screen) pair["occluder_screen"] = of(*q.occluder_screen);
    pairs.push_back(std::move(pair));
  }
  return {{"pairs", pairs}};
}

// EraseShadowAction
template <>
Spec schema_of<EraseShadowAction>() {
  return {{{"world", Kind::Vec3}, {"screen", Kind::Vec2}, {"pick", Kind::Index}}, {}, {{"world", "screen"}}, {}, false};
}
EraseShadowAction read(const json& p, Is<EraseShadowAction>) {
  EraseShadowAction a;
  if (p.contains("world")) a.world = vec3(p["world"]);
  if (p.contains("screen")) a.screen = vec2(p["screen"]);
  if (p.contains("pick")) a.pick = p["pick"].get<size_t>();
  return a;
}
json write(const EraseShadowAction& a) {
  json p = json::object();
  if (a.world) p["world"] = of(*a.world);
  if (a.screen) p["screen"] = of(*a.screen);
  if (a.pick) p["pick"] = *a.pick;
  return p;
}

// SpotRegionAction
template <>
Spec schema_of<SpotRegionAction>() {
  return {{{"world", Kind::Points3}, {"screen", Kind::Points2}, {"eye", Kind::Vec3}, {"direction", Kind::Vec3},
         {"falloff_deg", Kind::NonNegative}, {"intensity", Kind::Colour}},
        {}, {{"world", "screen"}}, {{"eye", "direction"}}, false};
}
SpotRegionAction read(const json& p, Is<SpotRegionAction>) {
  SpotRegionAction a;
  a.points = read_points(p);
  if (p.contains("eye")) a.eye = vec3(p["eye"]);
  if (p.contains("direction")) a.direction = vec3(p["direction"]);
  if (p.contains("falloff_deg")) a.falloff_deg = p["falloff_deg"].get<float>();
  if (p.contains("intensity")) a.intensity = colour(p["intensity"]);
  return a;
}
json write(const SpotRegionAction& a) {
  json p = write_points(a.points);
  if (a.eye) p["eye"] = of(*a.eye);
  if (a.direction) p["direction"] = of(*a.direction);
  if (a.falloff_deg) p["falloff_deg"] = *a.falloff_deg;
  if (a.intensity) p["intensity"] = of(*a.intensity);
  return p;
}

// AdjustRegionAction
template <>
Spec schema_of<AdjustRegionAction>() {
  return {{{"world", Kind::Points3}, {"screen", Kind::Points2}, {"multiplier", Kind::Colour}, {"radius", Kind::Positive},
         {"min_share", Kind::Unit}},
        {"multiplier"}, {{"world", "screen"}}, {}, false};
}
AdjustRegionAction read(const json& p, Is<AdjustRegionAction>) {
  AdjustRegionAction a;
  a.points = read_points(p);
  a.multiplier = colour(p["multiplier"]);
  if (p.contains("radius")) a.radius = p["radius"].get<float>();
  if (p.contains("min_share")) a.min_share = p["min_share"].get<double>();
  return a;
}
json write(const AdjustRegionAction& a) {
  json p = write_points(a.points);
  p["multiplier"] = of(a.multiplier);
  if (a.radius) p["radius"] = *a.radius;
  if (a.min_share) p["min_share"] = *a.min_share;
  return p;
}

// SolveAction
template <>
Spec schema_of<SolveAction>() {
  return {};
}
SolveAction read(const json&, Is<SolveAction>) { return {}; }
json write(const SolveAction&) { return json::object(); }

// FineTuneAction
template <>
Spec schema_of<FineTuneAction>() {
  return {};
}
FineTuneAction read(const json&, Is<FineTuneAction>) { return {}; }
json write(const FineTuneAction&) { return json::object(); }

// AddLightsAction
template <>
Spec schema_of<AddLightsAction>() {
  return {};
}
AddLightsAction read(const json&, Is<AddLightsAction>) { return {}; }
json write(const AddLightsAction&) { return json::object(); }

// CutAction
template <>
Spec schema_of<CutAction>() {
  return {{{"k", Kind::Count}}, {"k"}, {}, {}, false};
}
CutAction read(const json& p, Is<CutAction>) { return {p["k"].get<size_t>()}; }
json write(const CutAction& a) { return {{"k", a.k}}; }

// PlaceAction
template <>
Spec schema_of<PlaceAction>() {
  return {{{"rules", Kind::String}}, {"rules"}, {}, {}, false};
}
PlaceAction read(const json& p, Is<PlaceAction>) { return {p["rules"].get<std::string>()}; }
json write(const PlaceAction& a) { return {{"rules", a.rules}}; }

// UndoAction
template <>
Spec schema_of<UndoAction>() {
  return {};
}
UndoAction read(const json&, Is<UndoAction>) { return {}; }
json write(const UndoAction&) { return json::object(); }

// RedoAction
template <>
Spec schema_of<RedoAction>() {
  return {};
}
RedoAction read(const json&, Is<RedoAction>) { return {}; }
json write(const RedoAction&) { return json::object(); }

// SaveTargetAction
template <>
Spec schema_of<SaveTargetAction>() {
  return {{{"path", Kind::String}}, {"path"}, {}, {}, false};
}
SaveTargetAction read(const json& p, Is<SaveTargetAction>) { return {p["path"].get<std::string>()}; }
json write(const SaveTargetAction& a) { return {{"path", a.path}}; }

// SaveLightsAction
template <>
Spec schema_of<SaveLightsAction>() {
  return {{{"path", Kind::String}}, {"path"}, {}, {}, false};
}
SaveLightsAction read(const json& p, Is<SaveLightsAction>) { return {p["path"].get<std::string>()}; }
json write(const SaveLightsAction& a) { return {{"path", a.path}}; }

// LoadTargetAction
template <>
Spec schema_of<LoadTargetAction>() {
  return {{{"path", Kind::String}}, {"path"}, {}, {}, false};
}
LoadTargetAction read(const json& p, Is<LoadTargetAction>) { return {p["path"].get<std::string>()}; }
json write(const LoadTargetAction& a) { return {{"path", a.path}}; }

// LoadLightsAction
template <>
Spec schema_of<LoadLightsAction>() {
  return {{{"path", Kind::String}}, {"path"}, {}, {}, false};
}
LoadLightsAction read(const json& p, Is<LoadLightsAction>) { return {p["path"].get<std::string>()}; }
json write(const LoadLightsAction& a) { return {{"path", a.path}}; }

// UnitsAction
template <>
Spec schema_of<UnitsAction>() {
  return {{{"units", Kind::String}, {"quantity", Kind::String}}, {"units"}, {}, {}, false};
}
UnitsAction read(const json& p, Is<UnitsAction>) {
  return {parse_units(p["units"].get<std::string>()),
          p.contains("quantity") ? parse_target_quantity(p["quantity"].get<std::string>()) : TargetQuantity::Radiance};
}
json write(const UnitsAction& a) { return {{"units", units_name(a.units)}, {"quantity", target_quantity_name(a.quantity)}}; }

// CriteriaAction: the path and the criteria options, by hilight solve's names (without the dashes).
const char* layout_name(LayoutChoice c) { return c == LayoutChoice::Array ? "array" : c == LayoutChoice::Free ? "free" : "auto"; }
template <>
Spec schema_of<CriteriaAction>() {
  return {{{"path", Kind::String},
           {"maintenance_factor", Kind::Positive},
           {"margin", Kind::NonNegative},
           {"layout", Kind::String},
           {"ceiling_grid", Kind::NonNegative},
           {"ceiling_grid_origin", Kind::Vec2},
           {"min_spacing", Kind::NonNegative},
           {"max_spacing_ratio", Kind::NonNegative},
           {"ugr_max", Kind::NonNegative},
           {"posture", Kind::String},
           {"cylindrical_min", Kind::NonNegative},
           {"tilt_max", Kind::NonNegative}},
          {"path"}, {}, {}, false};
}
CriteriaAction read(const json& p, Is<CriteriaAction>) {
  CriteriaAction a;
  a.path = p["path"].get<std::string>();
  DesignSettings& s = a.design.settings;
  s.maintenance_factor = p.value("maintenance_factor", s.maintenance_factor);
  s.margin = p.value("margin", s.margin);
  const std::string layout = p.value("layout", std::string("auto"));
  s.layout = layout == "array" ? LayoutChoice::Array : layout == "free" ? LayoutChoice::Free : LayoutChoice::Auto;
  s.ceiling_grid = p.value("ceiling_grid", s.ceiling_grid);
  if (p.contains("ceiling_grid_origin"))
    a.design.grid_origin_world = glm::dvec2(p["ceiling_grid_origin"][0].get<double>(), p["ceiling_grid_origin"][1].get<double>());
  s.spacing.min_spacing = p.value("min_spacing", s.spacing.min_spacing);
  s.spacing.max_spacing_ratio = p.value("max_spacing_ratio", s.spacing.max_spacing_ratio);
  s.ugr_max = p.value("ugr_max", s.ugr_max);
  s.posture = p.value("posture", std::string("seated")) == "standing" ? DesignSettings::Posture::Standing : DesignSettings::Posture::Seated;
  s.cylindrical_min = p.value("cylindrical_min", s.cylindrical_min);
  s.tilt_max_deg = p.value("tilt_max", s.tilt_max_deg);
  return a;
}
json write(const CriteriaAction& a) {
  const DesignSettings& s = a.design.settings;
  json p = {{"path", a.path},
            {"maintenance_factor", s.maintenance_factor},
            {"margin", s.margin},
            {"layout", layout_name(s.layout)},
            {"ceiling_grid", s.ceiling_grid},
            {"min_spacing", s.spacing.min_spacing},
            {"max_spacing_ratio", s.spacing.max_spacing_ratio},
            {"ugr_max", s.ugr_max},
            {"posture", s.posture == DesignSettings::Posture::Standing ? "standing" : "seated"},
            {"cylindrical_min", s.cylindrical_min},
            {"tilt_max", s.tilt_max_deg}};
  if (a.design.grid_origin_world) p["ceiling_grid_origin"] = {a.design.grid_origin_world->x, a.design.grid_origin_world->y};
  return p;
}

// ScreenshotAction
template <>
Spec schema_of<ScreenshotAction>() {
  return {{{"path", Kind::String}, {"panels", Kind::Bool}}, {"path"}, {}, {}, false};
}
ScreenshotAction read(const json& p, Is<ScreenshotAction>) { return {p["path"].get<std::string>(), p.value("panels", false)}; }
json write(const ScreenshotAction& a) {
  json p = {{"path", a.path}};
  if (a.panels) p["panels"] = true;
  return p;
}

// OpenSceneAction
template <>
Spec schema_of<OpenSceneAction>() {
  return {{{"path", Kind::String}}, {"path"}, {}, {}, false};
}
OpenSceneAction read(const json& p, Is<OpenSceneAction>) { return {p["path"].get<std::string>()}; }
json write(const OpenSceneAction& a) { return {{"path", a.path}}; }

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
  case Kind::Bool: return v.is_boolean() ? "" : "true or false";
  case Kind::Indices: {
    bool ok = v.is_array() && !v.empty();
    if (ok)
      for (const auto& x : v) ok = ok && x.is_number_integer() && x.get<long long>() >= 0 && x.get<long long>() <= 1000000;
    return ok ? "" : "a non-empty list of integers ≥ 0";
  }
  case Kind::True: return v.is_boolean() && v.get<bool>() ? "" : "true";
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

struct ActionSpec {
  const char* type;
  Spec schema;
  TypedAction (*read)(const json& params);
};

template <class T>
TypedAction read_as(const json& params) {
  return read(params, Is<T>{});
}

/// The specs in the variant's order (the order docs/painter.md lists them).
const std::vector<ActionSpec>& action_specs() {
  static const std::vector<ActionSpec> table = []<size_t... I>(std::index_sequence<I...>) {
    return std::vector<ActionSpec>{ActionSpec{std::variant_alternative_t<I, TypedAction>::kType,
                                              schema_of<std::variant_alternative_t<I, TypedAction>>(),
                                              &read_as<std::variant_alternative_t<I, TypedAction>>}...};
  }(std::make_index_sequence<std::variant_size_v<TypedAction>>{});
  return table;
}

const ActionSpec* spec_of(const std::string& type) {
  for (const ActionSpec& spec : action_specs())
    if (type == spec.type) return &spec;
  return nullptr;
}

} // namespace

const std::vector<std::string>& action_types() {
  static const std::vector<std::string> types = [] {
    std::vector<std::string> out;
    for (const ActionSpec& spec : action_specs()) out.push_back(spec.type);
    return out;
  }();
  return types;
}

void validate_action(const Action& action, const std::string& source, size_t index) {
  auto fail = [&](const std::string& problem) {
    throw InputError(source, "action " + std::to_string(index) + ": " + problem);
  };
  const ActionSpec* found = spec_of(action.type);
  if (!found) fail("unknown type '" + action.type + "'");
  const Spec& spec = found->schema;
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
  if (action.type == "brush" && action.params.contains("meaning")) {
    const std::string meaning = action.params["meaning"].get<std::string>();
    if (!paint_meaning_from_string(meaning)) fail("brush: 'meaning' must be lamp or reflected, not '" + meaning + "'");
  }
  if (action.type == "units") {  // the names the CLI's --units and --target-quantity read (hilight/units.hpp)
    const std::string units = action.params["units"].get<std::string>();
    const std::string quantity = action.params.value("quantity", std::string(target_quantity_name(TargetQuantity::Radiance)));
    std::optional<Units> u;
    std::optional<TargetQuantity> q;
    try { u = parse_units(units); } catch (const InputError&) {}
    try { q = parse_target_quantity(quantity); } catch (const InputError&) {}
    if (!u) fail("units: 'units' must be radiometric or photometric, not '" + units + "'");
    if (!q) fail("units: 'quantity' must be luminance (radiance) or illuminance, not '" + quantity + "'");
    if (*q == TargetQuantity::Illuminance && *u != Units::Photometric) fail("units: illuminance is in lux: it needs 'units': 'photometric'");
  }
  if (action.type == "criteria") {  // as hilight solve's --layout, --maintenance-factor, --margin and --ugr-max take them
    const json& p = action.params;
    const std::string layout = p.value("layout", std::string("auto"));
    if (layout != "auto" && layout != "array" && layout != "free") fail("criteria: 'layout' must be auto, array or free, not '" + layout + "'");
    const std::string posture = p.value("posture", std::string("seated"));
    if (posture != "seated" && posture != "standing") fail("criteria: 'posture' must be seated or standing, not '" + posture + "'");
    if (p.contains("maintenance_factor") && p["maintenance_factor"].get<double>() > 1) fail("criteria: 'maintenance_factor' must be in (0, 1]");
    if (p.contains("margin") && p["margin"].get<double>() >= 1) fail("criteria: 'margin' must be in [0, 1)");
    if (p.contains("ugr_max") && p["ugr_max"].get<double>() != 0 && !(p["ugr_max"].get<double>() >= 1 && p["ugr_max"].get<double>() <= 40))
      fail("criteria: 'ugr_max' must be 0 (none) or in [1, 40]");
    if (p.contains("tilt_max") && !(p["tilt_max"].get<double>() <= 60)) fail("criteria: 'tilt_max' must be in [0, 60] degrees");
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


TypedAction typed(const Action& action) {
  const ActionSpec* spec = spec_of(action.type);
  if (!spec) throw std::logic_error("typed: unknown action type '" + action.type + "'");
  return spec->read(action.params.is_null() ? json::object() : action.params);
}

Action untyped(const TypedAction& action) {
  return std::visit([](const auto& a) { return Action{a.kType, write(a)}; }, action);
}

const char* type_of(const TypedAction& action) {
  return std::visit([](const auto& a) { return a.kType; }, action);
}

} // namespace hilight::painter
