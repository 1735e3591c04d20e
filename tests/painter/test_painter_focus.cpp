// Room focus (issue 20): the `focus` action names LightSpace regions (by
// number or by a point in the room); solves then fit only what is painted in
// the focused rooms and put their lights there. Two rooms behind a closed
// wall, both floors painted: focused on one, every light stands in it.
#include "core/session_player.hpp"
#include "hilight/error.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace hilight;
using namespace hilight::painter;
using Catch::Matchers::Contains;

namespace {

/// Two 3 x 3 x 4 rooms side by side, a closed wall 0.2 thick at x = 3.
painter_test::World two_rooms() {
  Scene raw = builders::box_room(Vec3(6.f, 3.f, 4.f));
  builders::add_box(raw, Vec3(2.9f, 0.f, 0.f), Vec3(3.1f, 3.f, 4.f), Rgb(0.8f), false, "wall");
  return painter_test::make_world(std::move(raw), 0.4f);
}

} // namespace

TEST_CASE("painter focus: a focused solve fits and lights only the focused room", "[painter][focus]") {
  const auto world = two_rooms();
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  std::optional<Bounds> framed;
  PlayerHooks hooks;
  hooks.frame = [&](const Bounds& box) { framed = box; };
  SessionPlayer player(*doc, job, hooks, {});
  player.apply({"brush", {{"radius", 1.0}, {"brightness", 0.4}, {"hardness", 0.8}}});
  player.apply({"stroke", {{"world", {{1.5, 0.0, 2.0}}}}});
  player.apply({"stroke", {{"world", {{4.5, 0.0, 2.0}}}}});
  const int left = player.regions().at(Vec3(1.5f, 1.5f, 2.f)), right = player.regions().at(Vec3(4.5f, 1.5f, 2.f));
  REQUIRE(left >= 0);
  REQUIRE(right >= 0);
  REQUIRE(left != right);

  // By a point on the left room's floor: its room, framed.
  player.apply({"focus", {{"world", {1.5, 0.0, 2.0}}}});
  REQUIRE(player.focus() == std::vector<int>{left});
  REQUIRE(framed);
  CHECK(framed->contains(Vec3(1.5f, 1.5f, 2.f)));
  CHECK_FALSE(framed->contains(Vec3(4.5f, 1.5f, 2.f)));
  player.apply({"solve", nlohmann::json::object()});
  REQUIRE(!doc->state().lights.empty());
  for (const Light& light : doc->state().lights) {
    INFO("light at " << light.position.x << " " << light.position.y << " " << light.position.z);
    CHECK(player.regions().at(light.position) == left);
  }

  // By number, the other room; a `place` rule keeps the focus beside it.
  player.apply({"focus", {{"regions", {right}}}});
  player.apply({"place", {{"rules", "height:1.5:2.9"}}});
  player.apply({"solve", nlohmann::json::object()});
  for (const Light& light : doc->state().lights) {
    INFO("light at " << light.position.x << " " << light.position.y << " " << light.position.z);
    CHECK(player.regions().at(light.position) == right);
    CHECK(light.position.y >= 1.5f - 1e-3f);
  }

  // Nothing painted in a focused room: the solve says so; a room that does not exist is named.
  player.apply({"undo", nlohmann::json::object()});  // the second solve
  player.apply({"undo", nlohmann::json::object()});  // the first
  player.apply({"undo", nlohmann::json::object()});  // the right room's stroke
  CHECK_THROWS_WITH(player.apply({"solve", nlohmann::json::object()}, 9), Contains("action 9 (solve): nothing is painted in the focused rooms"));
  CHECK_THROWS_WITH(player.apply({"focus", {{"regions", {7}}}}, 3), Contains("action 3 (focus): no region 7 (the scene has 2, 0 to 1)"));
  CHECK_THROWS_WITH(player.apply({"focus", {{"world", {30.0, 0.0, 2.0}}}}), Contains("is not on any surface"));
  // Off: the whole scene again.
  player.apply({"focus", {{"off", true}}});
  CHECK(player.focus().empty());
  player.apply({"solve", nlohmann::json::object()});
  CHECK(!doc->state().lights.empty());
}
