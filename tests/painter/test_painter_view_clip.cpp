// Inside buildings (issue 20): the section and the cutaway hide surfaces
// from the view, from picking and from paint, never from the scene. A room
// with walls 0.2 thick (an inner box wound inward, an outer one outward), as
// buildings are modelled: from outside one sees only the outer shell.
#include "core/brush.hpp"
#include "core/session_player.hpp"
#include "core/view_clip.hpp"
#include "hilight/error.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace hilight;
using namespace hilight::painter;
using Catch::Matchers::Contains;

namespace {

/// A 6 x 3 x 4 room inside walls, floor and roof 0.2 thick.
painter_test::World walled_room() {
  Scene raw = builders::box_room(Vec3(6.f, 3.f, 4.f));
  builders::add_box(raw, Vec3(-0.2f), Vec3(6.2f, 3.2f, 4.2f), Rgb(0.5f), false, "shell");
  return painter_test::make_world(std::move(raw), 0.5f);
}

/// Shown triangles whose centre lies within `tolerance` of the plane axis = value.
size_t shown_on_plane(const Scene& scene, const Visibility& visible, int axis, float value, float tolerance = 1e-3f) {
  size_t n = 0;
  for (uint32_t t = 0; t < scene.triangles.size(); ++t) {
    const auto& tri = scene.triangles[t];
    const Vec3 c = (scene.positions[tri[0]] + scene.positions[tri[1]] + scene.positions[tri[2]]) / 3.f;
    n += std::abs(c[axis] - value) < tolerance && visible.triangle(t);
  }
  return n;
}

} // namespace

TEST_CASE("painter view clip: the cutaway hides the roof and ceiling from above and the near walls from the side",
          "[painter][clip]") {
  const auto world = walled_room();
  const Scene& scene = *world.scene;
  const Vec3 floor_centre(3.f, 0.f, 2.f);
  ViewClip clip;
  clip.cutaway = true;
  const Visibility from_above = Visibility::compute(scene, clip, Vec3(3.f, 12.f, 2.f), floor_centre);
  CHECK(shown_on_plane(scene, from_above, 1, 3.2f) == 0);  // the roof
  CHECK(shown_on_plane(scene, from_above, 1, 3.f) == 0);   // the ceiling
  CHECK(shown_on_plane(scene, from_above, 1, 0.f) > 0);    // the floor looked at
  CHECK(shown_on_plane(scene, from_above, 0, 0.f) > 0);    // walls are not in the way from above
  CHECK(shown_on_plane(scene, from_above, 1, -0.2f) > 0);  // the underside, behind the floor, is not in the way

  const Visibility from_side = Visibility::compute(scene, clip, Vec3(3.f, 1.5f, -12.f), Vec3(3.f, 1.f, 2.f));
  CHECK(shown_on_plane(scene, from_side, 2, -0.2f) == 0);  // the near wall, outside
  CHECK(shown_on_plane(scene, from_side, 2, 0.f) == 0);    // and inside
  CHECK(shown_on_plane(scene, from_side, 2, 4.f) > 0);     // the far wall stays
  CHECK(shown_on_plane(scene, from_side, 1, 0.f) > 0);     // and the floor
  CHECK(shown_on_plane(scene, from_side, 1, 3.f) > 0);     // the ceiling is above the eye, not in front of the room

  // Off, nothing is hidden.
  const Visibility none = Visibility::compute(scene, ViewClip{}, Vec3(3.f, 12.f, 2.f), floor_centre);
  CHECK(none.all_visible());
  CHECK(shown_on_plane(scene, none, 1, 3.2f) > 0);
}

TEST_CASE("painter view clip: the section hides what is above it, cutting triangles through", "[painter][clip]") {
  const auto world = walled_room();
  const Scene& scene = *world.scene;
  ViewClip clip;
  clip.section = 1.5f;
  const Visibility visible = Visibility::compute(scene, clip, Vec3(3.f, 12.f, 2.f), Vec3(3.f, 0.f, 2.f));
  CHECK(shown_on_plane(scene, visible, 1, 3.f) == 0);
  CHECK(shown_on_plane(scene, visible, 1, 0.f) > 0);
  size_t above = 0, below = 0;
  for (uint32_t v = 0; v < scene.positions.size(); ++v) {
    if (scene.positions[v].y > 1.5f) above += visible.vertex(v);
    else below += visible.vertex(v);
  }
  CHECK(above == 0);
  CHECK(below > 0);
  // A wall triangle crossing the section is drawn clipped: its lower part picks, its upper does not.
  uint32_t crossing = ~0u;
  for (uint32_t t = 0; t < scene.triangles.size() && crossing == ~0u; ++t) {
    float lo = 1e9f, hi = -1e9f;
    for (uint32_t v : scene.triangles[t]) lo = std::min(lo, scene.positions[v].y), hi = std::max(hi, scene.positions[v].y);
    if (lo < 1.4f && hi > 1.6f) crossing = t;
  }
  REQUIRE(crossing != ~0u);
  CHECK(visible.triangle(crossing));
  CHECK(visible.point(crossing, Vec3(0.f, 1.4f, 0.f)));
  CHECK_FALSE(visible.point(crossing, Vec3(0.f, 1.6f, 0.f)));
}

TEST_CASE("painter view clip: clipped and cut-away surfaces get no paint", "[painter][clip]") {
  const auto world = walled_room();
  const Scene& scene = *world.scene;
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  PlayerHooks hooks;
  CameraPose camera{Vec3(3.f, 1.5f, -12.f), glm::normalize(Vec3(0.f, -0.5f, 14.f)), Vec3(3.f, 1.f, 2.f)};
  hooks.camera_pose = [&] { return camera; };
  SessionPlayer player(*doc, job, hooks, {});
  player.apply({"brush", {{"radius", 0.6}, {"brightness", 0.5}, {"hardness", 1}}});

  SECTION("a stroke on a wall across the section paints only below it") {
    player.apply({"section", {{"height", 1.5}}});
    player.apply({"stroke", {{"world", {{3.0, 1.4, 4.0}}}}});  // the far wall, inside
    size_t painted_below = 0;
    for (uint32_t v = 0; v < scene.positions.size(); ++v) {
      if (doc->state().weight[v] <= 0.f) continue;
      INFO("vertex at height " << scene.positions[v].y);
      CHECK(scene.positions[v].y <= 1.5f);
      ++painted_below;
    }
    CHECK(painted_below > 0);
    // A point above the section is not paintable at all; off again, it is.
    CHECK_THROWS_WITH(player.apply({"stroke", {{"world", {{3.0, 2.5, 4.0}}}}}, 7),
                      Contains("action 7 (stroke): every point is on a surface the section or cutaway hides"));
    player.apply({"section", {{"off", true}}});
    player.apply({"stroke", {{"world", {{3.0, 2.5, 4.0}}}}});
    size_t painted_above = 0;
    for (uint32_t v = 0; v < scene.positions.size(); ++v) painted_above += scene.positions[v].y > 1.5f && doc->state().weight[v] > 0.f;
    CHECK(painted_above > 0);
  }

  SECTION("the cutaway's near wall takes no paint, from a stroke or from a dab beside it") {
    player.apply({"cutaway", {{"on", true}}});
    CHECK_THROWS_WITH(player.apply({"stroke", {{"world", {{3.0, 1.0, 0.0}}}}}), Contains("hides"));
    // A dab centred on the near wall's face (as a brush sweeping past would be): nothing changes.
    const PaintState before = doc->state();
    Stroke stroke(*doc, player.brush(), BrushMode::Paint, &player.visibility());
    stroke.dab(SurfacePick{Vec3(3.f, 1.f, 0.f), Vec3(0.f, 0.f, 1.f)});
    stroke.finish();
    CHECK(doc->state().weight == before.weight);
    // Without the cutaway the same dab paints the wall.
    Stroke plain(*doc, player.brush(), BrushMode::Paint);
    plain.dab(SurfacePick{Vec3(3.f, 1.f, 0.f), Vec3(0.f, 0.f, 1.f)});
    plain.finish();
    CHECK(doc->painted_count() > 0);
    // The far wall is in view: it takes paint with the cutaway on.
    const size_t painted = doc->painted_count();
    player.apply({"stroke", {{"world", {{3.0, 1.0, 4.0}}}}});
    CHECK(doc->painted_count() > painted);
  }
}

TEST_CASE("painter view clip: bad section and cutaway fields are input errors naming the script", "[painter][clip][bad-input]") {
  auto error_of = [](const std::string& text) {
    try {
      parse_session(text, "s.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(error_of(R"({"actions": [{"type": "section", "height": "high"}]})"),
             Contains("s.json: action 0: section: 'height' must be a number"));
  CHECK_THAT(error_of(R"({"actions": [{"type": "section"}]})"), Contains("section: needs exactly one of height, off"));
  CHECK_THAT(error_of(R"({"actions": [{"type": "section", "off": false}]})"), Contains("section: 'off' must be true"));
  CHECK_THAT(error_of(R"({"actions": [{"type": "cutaway", "on": "yes"}]})"), Contains("cutaway: 'on' must be true or false"));
  CHECK(error_of(R"({"actions": [{"type": "section", "height": 1.5}, {"type": "cutaway", "on": false}]})").empty());
}

TEST_CASE("painter view clip: hidden surfaces still cast shadows and bounce light, the solve is the same", "[painter][clip]") {
  // The same painted floor solved with nothing hidden and with the roof,
  // ceiling and upper walls hidden: the same lights, to the bit.
  const auto world = walled_room();
  auto solve_with = [&](const std::vector<Action>& clip) {
    auto doc = world.document();
    SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
    PlayerHooks hooks;
    hooks.camera_pose = [] { return CameraPose{Vec3(3.f, 12.f, 2.f), Vec3(0.f, -1.f, 0.f), Vec3(3.f, 0.f, 2.f)}; };
    SessionPlayer player(*doc, job, hooks, {});
    for (const Action& a : clip) player.apply(a);
    player.apply({"brush", {{"radius", 1.5}, {"brightness", 0.3}, {"hardness", 0.8}}});
    player.apply({"stroke", {{"world", {{2.0, 0.0, 2.0}}}}});
    player.apply({"solve", nlohmann::json::object()});
    return doc->state().lights;
  };
  const Lighting open = solve_with({});
  const Lighting hidden = solve_with({{"cutaway", {{"on", true}}}, {"section", {{"height", 1.0}}}});
  REQUIRE(!open.empty());
  CHECK(hidden == open);
}
