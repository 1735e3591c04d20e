// Rooms by name in the painter (issue 34 §5): `hilight paint --place
// region:Wohnen` on the FZK house of assimp-testmodels resolves the IfcSpace
// as `hilight solve` does (frontends/common/ifc_spaces.hpp), hangs the lights
// from that room's ceiling (the building default, said on stderr and in the
// Placement panel), and a name no room or storey has is one line, exit 2.
// A recorded `place` action takes the same text as hilight solve does
// (cli::settle_placement): region:Wohnen adds the ceiling rule, and a region
// that is not a room (the outside) is refused, naming the action.
#include "../support.hpp"
#include "core/session_player.hpp"
#include "hilight/fixtures/real_model_scenes.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/scene_io.hpp"
#include "hilight/named_room.hpp"
#include "hilight/ray_scene.hpp"
#include "hilight/regions.hpp"

#ifdef HILIGHT_HAVE_IFCPP
#include "../frontends/common/ifc_spaces.hpp"
#endif

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using namespace hilight;

[[maybe_unused]] fs::path fzk_house() { return builders::testmodels_dir() / "IFC/AC14-FZK-Haus.ifc"; }

} // namespace

TEST_CASE("painter: a place action's text splits into rules and keeps a storey's name with its spaces whole", "[painter][placement][rooms]") {
  using V = std::vector<std::string>;
  CHECK(painter::split_place_rules("ceiling:0.2 region:0. Erdgeschoss count:1:2") == V{"ceiling:0.2", "region:0. Erdgeschoss", "count:1:2"});
  CHECK(painter::split_place_rules("not-region:Kind 1  anywhere") == V{"not-region:Kind 1", "anywhere"});
  CHECK(painter::split_place_rules("  ceiling  region:3 ") == V{"ceiling", "region:3"});
  CHECK(painter::split_place_rules("") == V{});
  // A word after another rule is its own (and refused as unknown by PlacementRules::add).
  CHECK(painter::split_place_rules("ceiling:0.2 Wohnen") == V{"ceiling:0.2", "Wohnen"});
}

#ifdef HILIGHT_HAVE_IFCPP
namespace {

/// The FZK house's living room (its IfcSpace "Wohnen") and its floor at the
/// middle: the first surface down from 1 m over it.
struct LivingRoom {
  std::shared_ptr<const RayScene> rays;  ///< the house's
  NamedRoom room;
  Vec3 floor;
};

LivingRoom living_room() {
  const auto house = std::make_shared<const Scene>(load_scene(fzk_house()));
  const auto rays = RayScene::shared(house);
  const auto rooms = cli::read_ifc_rooms(fzk_house(), *house).rooms;
  const auto living_found = rooms_named(rooms, "Wohnen");
  REQUIRE(living_found.size() == 1);
  const NamedRoom& living = *living_found.front();
  const Vec3 middle = living.box.center();
  const Hit floor_hit = rays->intersect(Vec3(middle.x, living.y0 + 1.f, middle.z), Vec3(0.f, -1.f, 0.f));
  REQUIRE(floor_hit.valid());
  return {rays, living, rays->hit_position(floor_hit)};
}

/// A session's first actions: the camera over `floor`, a brush, one stroke painting it.
nlohmann::json paint_floor(const Vec3& floor) {
  return nlohmann::json::array({
      {{"type", "camera"}, {"eye", {floor.x, floor.y + 12.f, floor.z + 5.f}}, {"target", {floor.x, floor.y, floor.z}}, {"fov", 40}},
      {{"type", "brush"}, {"radius", 0.8}, {"colour", 1.0}, {"brightness", 0.6}, {"hardness", 0.7}},
      {{"type", "stroke"}, {"world", {{floor.x, floor.y, floor.z}}}}});
}

} // namespace

TEST_CASE("painter ui: in the FZK house --place region:Wohnen hangs the lights from the living room's ceiling and a bad name is refused",
          "[painter-ui][placement][rooms]") {
  if (test::skip_without_display()) return;
  if (!fs::exists(fzk_house())) {
    WARN("SKIPPED: " << fzk_house() << " not found (apt install assimp-testmodels)");
    return;
  }
  test::CliOwnPlacement own;  // the building default under test
  const fs::path dir = test::output_dir("painter_ui_rooms");
  const LivingRoom home = living_room();
  const NamedRoom& living = home.room;
  const Vec3 floor = home.floor;

  nlohmann::json actions = paint_floor(floor);
  actions.push_back({{"type", "solve"}});
  actions.push_back({{"type", "save_lights"}, {"path", (dir / "lights.json").string()}});
  // The Placement panel's rules as typed: a storey's name, resolved as the command line's are.
  actions.push_back({{"type", "place"}, {"rules", "ceiling:0.2 region:0. Erdgeschoss"}});
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", fzk_house().string(), "--size", "360x270", "--bounces", "0", "--samples", "800",
                                                 "--no-cache", "--no-record", "--exit", "--place", "region:Wohnen", "--script",
                                                 (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.find("hilight: lights on the ceiling (an IFC building with storeys; --place anywhere lifts it)") != std::string::npos);
  CHECK(run.err.find("lights may stand: ceiling:0.2 region:0. Erdgeschoss") != std::string::npos);
  const Lighting lights = read_lights_json(dir / "lights.json");
  REQUIRE_FALSE(lights.empty());
  for (const auto& l : lights) {
    INFO("light at " << l.position.x << ", " << l.position.y << ", " << l.position.z);
    CHECK(living.contains(l.position));
    CHECK(l.position.y == Approx(2.3f).margin(0.01f));  // 0.2 under the living room's ceiling (2.5 m)
  }

  // A name no room or storey has: one line naming it (and the rooms there are), exit 2, no window.
  const test::RunResult bad = test::run_hilight({"paint", fzk_house().string(), "--place", "region:Keller", "--exit", "--screenshot",
                                                 (dir / "never.png").string()});
  INFO(bad.err);
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
  CHECK_THAT(bad.err, Catch::Contains("region:Keller") && Catch::Contains("Wohnen"));
  CHECK_FALSE(fs::exists(dir / "never.png"));
  // The same in a session's place action: the action named, exit 2, one line
  // (--place anywhere: no building note before it).
  test::write_text(dir / "bad.json", nlohmann::json{{"actions", {{{"type", "place"}, {"rules", "region:Dachboden"}}}}}.dump());
  const test::RunResult bad_action = test::run_hilight({"paint", fzk_house().string(), "--size", "320x240", "--no-record", "--exit", "--place",
                                                        "anywhere", "--script", (dir / "bad.json").string()});
  INFO(bad_action.err);
  CHECK(bad_action.exit_code == 2);
  CHECK(test::line_count(bad_action.err) == 1);
  CHECK_THAT(bad_action.err, Catch::Contains("action 0") && Catch::Contains("region:Dachboden"));
}

TEST_CASE("painter ui: in the FZK house a place action's region:Wohnen hangs the lights from its ceiling as hilight solve does, "
          "and a region that is not a room is refused",
          "[painter-ui][placement][rooms]") {
  if (test::skip_without_display()) return;
  if (!fs::exists(fzk_house())) {
    WARN("SKIPPED: " << fzk_house() << " not found (apt install assimp-testmodels)");
    return;
  }
  // No CliOwnPlacement: the command line says --place anywhere, so only the place action can add the ceiling.
  const fs::path dir = test::output_dir("painter_ui_place_action_rooms");
  const LivingRoom home = living_room();
  const NamedRoom& living = home.room;
  const Vec3 floor = home.floor;

  nlohmann::json actions = paint_floor(floor);
  actions.push_back({{"type", "place"}, {"rules", "region:Wohnen"}});
  actions.push_back({{"type", "solve"}});
  actions.push_back({{"type", "save_lights"}, {"path", (dir / "lights.json").string()}});
  test::write_text(dir / "session.json", nlohmann::json{{"actions", actions}}.dump());
  const test::RunResult run = test::run_hilight({"paint", fzk_house().string(), "--size", "320x240", "--bounces", "0", "--samples", "800",
                                                 "--no-cache", "--no-record", "--exit", "--place", "anywhere", "--script",
                                                 (dir / "session.json").string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.find("lights may stand: region:Wohnen; lights on the ceiling (an IFC building with storeys; --place anywhere lifts it)") !=
        std::string::npos);
  const Lighting lights = read_lights_json(dir / "lights.json");
  REQUIRE_FALSE(lights.empty());
  for (const auto& l : lights) {
    INFO("light at " << l.position.x << ", " << l.position.y << ", " << l.position.z);
    CHECK(living.contains(l.position));
    CHECK(l.position.y == Approx(2.3f).margin(0.01f));  // 0.2 under the living room's ceiling (2.5 m), as hilight solve puts it
  }

  // The outside (a region at the light bounds' border) is no room: hilight solve refuses
  // --place region:K of it, and so does the place action, naming it (one line, exit 2).
  const Regions regions(*home.rays);
  int outside = -1;
  for (size_t i = 0; i < regions.list().size() && outside < 0; ++i)
    if (regions.list()[i].at_border) outside = int(i);
  REQUIRE(outside >= 0);
  const std::string rule = "region:" + std::to_string(outside);
  test::write_text(dir / "bad.json", nlohmann::json{{"actions", {{{"type", "place"}, {"rules", rule}}}}}.dump());
  const test::RunResult bad = test::run_hilight({"paint", fzk_house().string(), "--size", "320x240", "--no-record", "--exit", "--place",
                                                 "anywhere", "--script", (dir / "bad.json").string()});
  INFO(bad.err);
  CHECK(bad.exit_code == 2);
  CHECK(test::line_count(bad.err) == 1);
  CHECK_THAT(bad.err, Catch::Contains("action 0 (place)") && Catch::Contains(rule + ": region " + std::to_string(outside) + " is not a room"));
  // The same on paint's command line, before any window opens.
  const test::RunResult bad_flag =
      test::run_hilight({"paint", fzk_house().string(), "--place", rule, "--exit", "--screenshot", (dir / "never.png").string()});
  INFO(bad_flag.err);
  CHECK(bad_flag.exit_code == 2);
  CHECK(test::line_count(bad_flag.err) == 1);
  CHECK(bad_flag.err.find("--place " + rule + ": region " + std::to_string(outside) + " is not a room") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "never.png"));
}
#endif
