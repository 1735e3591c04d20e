// The painter's typed actions (core/actions.hpp): one spec per type, its
// JSON read and written back unchanged, the variant the one list of types.
#include "core/actions.hpp"
#include "hilight/error.hpp"

#include <catch2/catch.hpp>
#include <map>

using namespace hilight;
using namespace hilight::painter;

namespace {

/// A canonical example of every action type (values exact as floats).
const std::map<std::string, std::string>& examples() {
  static const std::map<std::string, std::string> table = {
      {"camera", R"({"orbit": [0.5, -0.25], "pan": [1, 2], "zoom": 0.75, "eye": [1, 2, 3], "target": [0, 0.5, 0], "fov": 45})"},
      {"tool", R"({"tool": "erase_shadow"})"},
      {"view", R"({"show": "difference"})"},
      {"section", R"({"height": 1.5})"},
      {"cutaway", R"({"on": true})"},
      {"plan", R"({"on": false})"},
      {"focus", R"({"regions": [3, 1]})"},
      {"walk", R"({"on": true, "move": [1.5, -0.5], "turn": [30, -10]})"},
      {"brush", R"({"radius": 0.25, "colour": [1, 0.5, 0.25], "brightness": 2, "hardness": 0.5})"},
      {"stroke", R"({"world": [[0, 0, 0], [0.5, 0, 0]], "normals": [[0, 1, 0], [0, 1, 0]], "mode": "erase"})"},
      {"erase", R"({"screen": [[10, 20], [30.5, 40]]})"},
      {"shadow", R"({"pairs": [{"occluder": [0, 0.5, 0], "world": [[1, 0, 1]]}, {"occluder_screen": [4, 5], "screen": [[6, 7]]}]})"},
      {"erase_shadow", R"({"world": [1, 0, 1], "pick": 2})"},
      {"spot_region", R"({"world": [[1, 0, 1]], "eye": [0, 2, 0], "direction": [0, -1, 0], "falloff_deg": 5, "intensity": [2, 2, 1]})"},
      {"adjust_region", R"({"world": [[1, 0, 1]], "multiplier": [2, 1, 0.5], "radius": 0.5, "min_share": 0.25})"},
      {"solve", "{}"},
      {"fine_tune", "{}"},
      {"add_lights", "{}"},
      {"cut", R"({"k": 3})"},
      {"place", R"({"rules": "ceiling:0.2 height:1:2"})"},
      {"undo", "{}"},
      {"redo", "{}"},
      {"save_target", R"({"path": "t.ply"})"},
      {"save_lights", R"({"path": "l.json"})"},
      {"load_target", R"({"path": "t.glb"})"},
      {"load_lights", R"({"path": "l.gltf"})"},
      {"screenshot", R"({"path": "s.png"})"},
      {"open_scene", R"({"path": "room.obj"})"},
      {"units", R"({"units": "photometric", "quantity": "illuminance"})"},
      {"criteria", R"({"path": "desks.json", "maintenance_factor": 0.7, "margin": 0.05, "layout": "array", "ceiling_grid": 0.6,
                       "ceiling_grid_origin": [0.5, -1.25], "min_spacing": 1.2, "max_spacing_ratio": 1.5, "ugr_max": 19,
                       "posture": "standing", "cylindrical_min": 150, "tilt_max": 20})"}};
  return table;
}

} // namespace

TEST_CASE("painter actions: every type reads from JSON and writes back the same", "[painter][actions]") {
  REQUIRE(action_types().size() == std::variant_size_v<TypedAction>);
  for (const std::string& type : action_types()) {
    INFO(type);
    REQUIRE(examples().count(type));  // a new action type needs an example here
    Action action{type, nlohmann::json::parse(examples().at(type))};
    validate_action(action, "example", 0);
    const TypedAction t = typed(action);
    CHECK(std::string(type_of(t)) == type);
    const Action back = untyped(t);
    CHECK(back.type == type);
    CHECK(back.params == action.params);
  }
  // The variant's order is the list's (the order docs/painter.md gives).
  std::vector<std::string> from_variant;
  [&]<size_t... I>(std::index_sequence<I...>) {
    (from_variant.push_back(std::variant_alternative_t<I, TypedAction>::kType), ...);
  }(std::make_index_sequence<std::variant_size_v<TypedAction>>{});
  CHECK(from_variant == action_types());
  // Shorthands normalize: a grey colour is written as [g, g, g], a missing mode stays missing.
  const TypedAction grey = typed(Action{"brush", {{"colour", 0.5}}});
  CHECK(untyped(grey).params == nlohmann::json::parse(R"({"colour": [0.5, 0.5, 0.5]})"));
  CHECK(untyped(typed(Action{"stroke", {{"world", {{0, 0, 0}}}}})).params.count("mode") == 0);
}

TEST_CASE("painter actions: an unknown field in any action is named in the error", "[painter][actions]") {
  for (const std::string& type : action_types()) {
    INFO(type);
    nlohmann::json params = nlohmann::json::parse(examples().at(type));
    params["bogus"] = 1;
    try {
      validate_action(Action{type, params}, "s.json", 4);
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK_THAT(e.what(), Catch::Contains("s.json: action 4: " + type + ": unknown field 'bogus'"));
    }
  }
  CHECK_THROWS_WITH(validate_action(Action{"paint", {}}, "s.json", 0), Catch::Contains("unknown type 'paint'"));
}

TEST_CASE("painter actions: a number beyond a double is an input error naming the script", "[painter][actions][bad-input]") {
  // Found by fuzzing (tools/fuzz.sh): it escaped as an internal error.
  CHECK_THROWS_WITH(parse_session(R"({"actions": [{"type": "brush", "brightness": 888e767}]})", "s.json"),
                    Catch::StartsWith("s.json: not valid JSON"));
}
