// A stroke dragged from the floor onto a box top (issue 15): the fill-in
// dabs between the two picks snap onto surfaces or are left out, so the
// recorded stroke replays.
#include "core/brush.hpp"
#include "core/region.hpp"
#include "core/session_player.hpp"
#include "hilight/error.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace painter_test;
using namespace hilight::painter;

TEST_CASE("painter: a stroke dragged from the floor onto a box top records only points on surfaces", "[painter][replay]") {
  auto world = floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}}, 0.2f);
  auto doc = world.document();
  BrushSettings brush;
  brush.radius = 0.2f;
  Stroke stroke(*doc, brush, BrushMode::Paint);
  const auto floor = pick_near(*world.rays, Vec3(-2.f, 0.f, 0.f));
  const auto top = pick_near(*world.rays, Vec3(0.f, 1.f, 0.f));
  REQUIRE(floor);
  REQUIRE(top);
  stroke.drag_to(*floor);
  stroke.drag_to(*top);
  const std::vector<Vec3> points = stroke.points();
  stroke.finish();
  REQUIRE(points.size() > 2);
  for (const Vec3& p : points) {
    INFO(p.x << ", " << p.y << ", " << p.z);
    CHECK(pick_near(*world.rays, p));
  }
  // And it replays, as a recorded session would.
  SolveJob job(test::registry(), world.scene, world.rays, quick_options());
  auto replayed = world.document();
  SessionPlayer player(*replayed, job, {}, {true, ".", "stroke.json"});
  StrokeAction action;
  action.points.world = points;
  action.points.normals = stroke.normals();
  player.apply(brush_action(brush));  // the same brush
  CHECK_NOTHROW(player.apply(untyped(action)));
  CHECK(replayed->painted_count() == doc->painted_count());
}

TEST_CASE("painter: a script's save paths are checked before anything runs", "[painter][replay]") {
  auto world = floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}}, 0.4f);
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, quick_options());
  SessionPlayer player(*doc, job, {}, {true, ".", "s.json"});
  const Session session = parse_session(R"({"actions": [
    {"type": "stroke", "world": [[2, 0, 2], [2.2, 0, 2]]},
    {"type": "solve"},
    {"type": "save_lights", "path": "/no/such/folder/lights.json"}]})", "s.json");
  try {
    player.play(session);
    FAIL("played");
  } catch (const InputError& e) {
    CHECK_THAT(e.what(), Catch::Contains("s.json: action 2 (save_lights): cannot write /no/such/folder/lights.json"));
  }
  CHECK(doc->painted_count() == 0);  // nothing ran: not the stroke, not the solve
  CHECK(job.cut_count() == 0);
}
