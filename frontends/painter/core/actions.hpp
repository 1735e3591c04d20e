#pragma once
/// The painter's actions, typed: one struct per action type, what a session
/// script's JSON object holds (docs/painter.md, "Session scripts"). Each
/// type has one spec (core/action_specs.cpp): its JSON schema, its reading
/// from and writing to JSON, and the SessionPlayer's apply function for it.
/// Recorded sessions stay JSON (`Action`); the player and the UI work on
/// these.
#include "core/session.hpp"
#include "hilight/math.hpp"
#include "hilight/solve/criteria_in_scene.hpp"
#include "hilight/units.hpp"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace hilight::painter {

using Vec2 = glm::vec2;

/// The painter's tools (the `tool` action).
enum class Tool { Brush, Eraser, Shadow, EraseShadow, Spot, Adjust };
const char* to_string(Tool tool);
/// nullopt for an unknown name.
std::optional<Tool> tool_from_string(const std::string& name);

/// What the window shows (the `view` action).
enum class ViewShown { Result, Target, Difference };
const char* to_string(ViewShown view);

/// Points given either on the surface in world space (with their normals
/// when recorded from strokes) or as window pixels to pick.
struct PointSet {
  std::vector<Vec3> world;
  std::vector<Vec2> screen;
  std::vector<Vec3> normals;  ///< per world point, or empty
};

struct CameraAction {
  static constexpr const char* kType = "camera";
  std::optional<Vec2> orbit, pan;
  std::optional<float> zoom, fov;
  std::optional<Vec3> eye, target;
};
struct ToolAction {
  static constexpr const char* kType = "tool";
  Tool tool = Tool::Brush;
};
struct ViewAction {
  static constexpr const char* kType = "view";
  ViewShown show = ViewShown::Result;
};
/// A horizontal section: surfaces above `height` are hidden (`off`: none).
struct SectionAction {
  static constexpr const char* kType = "section";
  std::optional<float> height;  ///< absent: "off"
};
/// The cutaway (doll's-house view): hides the walls and ceilings in front of what the camera looks at.
struct CutawayAction {
  static constexpr const char* kType = "cutaway";
  bool on = true;
};
/// The plan view: an orthographic top view of the section (or of the focused rooms).
struct PlanAction {
  static constexpr const char* kType = "plan";
  bool on = true;
};
/// Room focus: the LightSpace regions (rooms, hilight/regions.hpp) the view
/// frames and the solves' lights are limited to; by number, or the room a
/// point stands in (a double-clicked floor), or none (`off`).
struct FocusAction {
  static constexpr const char* kType = "focus";
  std::vector<int> regions;
  std::optional<Vec3> world;
  bool off = false;
};
/// Walk mode: `on` enters (true) or leaves (false) it; `move` [forward,
/// right] in scene units, stopped by walls; `turn` [yaw°, pitch°] looks around.
struct WalkAction {
  static constexpr const char* kType = "walk";
  std::optional<bool> on;
  std::optional<Vec2> move, turn;
};
struct BrushAction {
  static constexpr const char* kType = "brush";
  std::optional<float> radius, brightness, hardness;
  std::optional<Rgb> colour;
  std::optional<std::string> meaning;  ///< "lamp" or "reflected" (core/paint_meaning.hpp)
};
struct StrokeAction {
  static constexpr const char* kType = "stroke";
  PointSet points;
  std::optional<bool> erase;  ///< "mode": paint or erase; absent: the current tool decides
};
struct EraseAction {
  static constexpr const char* kType = "erase";
  PointSet points;
};
struct ShadowAction {
  static constexpr const char* kType = "shadow";
  struct Pair {
    std::optional<Vec3> occluder;
    std::optional<Vec2> occluder_screen;
    PointSet points;  ///< where the shadow should fall
  };
  std::vector<Pair> pairs;
};
struct EraseShadowAction {
  static constexpr const char* kType = "erase_shadow";
  std::optional<Vec3> world;
  std::optional<Vec2> screen;
  std::optional<size_t> pick;
};
struct SpotRegionAction {
  static constexpr const char* kType = "spot_region";
  PointSet points;
  std::optional<Vec3> eye, direction;
  std::optional<float> falloff_deg;
  std::optional<Rgb> intensity;
};
struct AdjustRegionAction {
  static constexpr const char* kType = "adjust_region";
  PointSet points;
  Rgb multiplier{1.f};
  std::optional<float> radius;
  std::optional<double> min_share;
};
struct SolveAction {
  static constexpr const char* kType = "solve";
};
struct FineTuneAction {
  static constexpr const char* kType = "fine_tune";
};
struct AddLightsAction {
  static constexpr const char* kType = "add_lights";
};
struct CutAction {
  static constexpr const char* kType = "cut";
  size_t k = 1;
};
struct PlaceAction {
  static constexpr const char* kType = "place";
  std::string rules;
};
struct UndoAction {
  static constexpr const char* kType = "undo";
};
struct RedoAction {
  static constexpr const char* kType = "redo";
};
struct SaveTargetAction {
  static constexpr const char* kType = "save_target";
  std::string path;
};
struct SaveLightsAction {
  static constexpr const char* kType = "save_lights";
  std::string path;
};
struct LoadTargetAction {
  static constexpr const char* kType = "load_target";
  std::string path;
};
struct LoadLightsAction {
  static constexpr const char* kType = "load_lights";
  std::string path;
};
/// The 3D view as the window shows it, or (`panels`) the whole window with its panels.
struct ScreenshotAction {
  static constexpr const char* kType = "screenshot";
  std::string path;
  bool panels = false;
};
/// Another scene: the window starts again on it (painted target, lights,
/// undo history and view left behind); the session's later actions apply there.
struct OpenSceneAction {
  static constexpr const char* kType = "open_scene";
  std::string path;
};

/// What painted values and lights files mean (`--units`,
/// `--target-quantity`): a session started with others than the defaults
/// records them first, so that its replay paints, reads and writes the same.
struct UnitsAction {
  static constexpr const char* kType = "units";
  Units units = Units::Radiometric;
  TargetQuantity quantity = TargetQuantity::Radiance;
};

/// A lux target instead of paint (`--target C.json` and the criteria
/// options): a session started with one records it first, so that its
/// replay's solve places the luminaires for the same criteria (given the
/// same --luminaire; the solve's renderer and bounces are the command
/// line's, as for every session).
struct CriteriaAction {
  static constexpr const char* kType = "criteria";
  std::string path;
  CriteriaDesign design;
};

/// Every action type, in the order docs/painter.md lists them.
using TypedAction =
    std::variant<CameraAction, ToolAction, ViewAction, SectionAction, CutawayAction, PlanAction, FocusAction, WalkAction, BrushAction, StrokeAction, EraseAction, ShadowAction, EraseShadowAction,
                 SpotRegionAction, AdjustRegionAction, SolveAction, FineTuneAction, AddLightsAction, CutAction, PlaceAction,
                 UndoAction, RedoAction, SaveTargetAction, SaveLightsAction, LoadTargetAction, LoadLightsAction, ScreenshotAction,
                 OpenSceneAction, UnitsAction, CriteriaAction>;

/// The typed form of a valid action (validate_action first: it assumes the schema holds).
TypedAction typed(const Action& action);
/// The JSON form, as recorded.
Action untyped(const TypedAction& action);
/// The type name of a typed action.
const char* type_of(const TypedAction& action);

} // namespace hilight::painter
