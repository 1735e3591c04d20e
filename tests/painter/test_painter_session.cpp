// Session scripts: parsing (good and bad input, one-line errors that name the
// action), serializing (what the painter records reads back the same), and
// headless replays of world-space scripts through Document + SolveJob.
#include "core/session.hpp"
#include "core/session_player.hpp"
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/surface_points.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <limits>
#include <thread>

using namespace hilight;
using namespace hilight::painter;
using Catch::Matchers::Contains;

namespace {

std::string parse_error(const std::string& text) {
  try {
    parse_session(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("painter: session scripts parse, serialize and reject bad input", "[painter]") {
  const std::string text = R"({"actions": [
    {"type": "camera", "orbit": [30, -10]},
    {"type": "camera", "eye": [1, 2, 3], "target": [0, 0, 0], "fov": 45},
    {"type": "tool", "tool": "eraser"},
    {"type": "brush", "radius": 0.3, "colour": [1, 0.9, 0.8], "brightness": 2, "hardness": 0.5},
    {"type": "stroke", "world": [[0, 0, 0], [1, 0, 0]]},
    {"type": "stroke", "screen": [[100, 200]], "mode": "erase"},
    {"type": "shadow", "pairs": [{"occluder": [0, 0.5, 0], "world": [[1, 0, 1]]}]},
    {"type": "erase_shadow", "world": [1, 0, 1], "pick": 0},
    {"type": "spot_region", "world": [[0, 0, 0]], "eye": [0, 3, 3], "direction": [0, -1, -1]},
    {"type": "adjust_region", "world": [[0, 0, 0]], "multiplier": 1.5},
    {"type": "solve"}, {"type": "fine_tune"}, {"type": "add_lights"}, {"type": "cut", "k": 2},
    {"type": "undo"}, {"type": "redo"}, {"type": "save_target", "path": "t.ply"},
    {"type": "save_lights", "path": "l.json"}, {"type": "screenshot", "path": "s.png"}]})";
  Session s = parse_session(text, "s.json");
  REQUIRE(s.actions.size() == 19);
  CHECK(s.actions[3].params["radius"] == 0.3);
  CHECK(parse_session(session_to_json(s), "again") == s);
  CHECK(parse_session(R"({"actions": []})", "empty").actions.empty());

  CHECK_THAT(parse_error(R"({"actions": [{"type": "solve"}, {"type": "foo"}]})"),
             Contains("s.json: action 1: unknown type 'foo'"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "stroke"}]})"), Contains("action 0: stroke: needs exactly one of world, screen"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "stroke", "world": [[0, 0]]}]})"), Contains("'world' must be a non-empty list of [x, y, z]"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "brush", "hardness": 2}]})"), Contains("'hardness' must be a number in [0, 1]"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "cut", "k": 0}]})"), Contains("'k' must be an integer ≥ 1"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "cut"}]})"), Contains("cut: missing 'k'"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "solve", "fast": true}]})"), Contains("solve: unknown field 'fast'"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "tool", "tool": "hammer"}]})"), Contains("unknown tool 'hammer'"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "camera", "eye": [0, 0, 1]}]})"), Contains("give eye, target together"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "shadow", "pairs": [{"world": [[0, 0, 0]]}]}]})"),
             Contains("pair 0: exactly one of occluder, occluder_screen"));
  CHECK_THAT(parse_error(R"({"actions": [3]})"), Contains("action 0: must be an object"));
  CHECK_THAT(parse_error(R"({"actions": [{"k": 3}]})"), Contains("action 0: missing \"type\""));
  CHECK_THAT(parse_error(R"({"steps": []})"), Contains("s.json: a session is a JSON object"));
  CHECK_THAT(parse_error(R"({"actions": [)"), Contains("s.json: not valid JSON"));
  CHECK(test::line_count(parse_error(R"({"actions": [{"type": "foo"}]})")) == 1);

  SessionRecorder recorder;
  recorder.record({"brush", {{"radius", 0.5}}});
  CHECK_THROWS_AS(recorder.record({"nonsense", {}}), std::logic_error);
  const auto dir = test::output_dir("painter_session_parse");
  recorder.save(dir / "session.json");
  CHECK(read_session(dir / "session.json") == recorder.session());
  CHECK_THROWS_AS(read_session(dir / "missing.json"), InputError);
}

TEST_CASE("painter: a replayed script paints a bright patch, solves and lights it", "[painter]") {
  auto world = painter_test::make_world(builders::box_room({4.f, 3.f, 4.f}), 0.4f);
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  const auto dir = test::output_dir("painter_session_replay");
  std::vector<std::string> log;
  PlayerOptions options;
  options.base_dir = dir;
  options.source = "replay.json";
  PlayerHooks hooks;
  hooks.log = [&](const std::string& line) { log.push_back(line); };
  SessionPlayer player(*doc, job, hooks, options);

  // A dim floor with a bright patch near one corner.
  std::string dim_floor;
  for (float x = 0.25f; x < 4.f; x += 0.5f)
    for (float z = 0.25f; z < 4.f; z += 0.5f)
      dim_floor += std::string(dim_floor.empty() ? "" : ", ") + "[" + std::to_string(x) + ", 0, " + std::to_string(z) + "]";
  const std::string script = R"({"actions": [
    {"type": "brush", "radius": 0.45, "colour": [1, 1, 1], "brightness": 0.02, "hardness": 1},
    {"type": "stroke", "world": [)" + dim_floor + R"(]},
    {"type": "brush", "radius": 0.5, "brightness": 0.6, "hardness": 0.8},
    {"type": "stroke", "world": [[1, 0, 1], [1.2, 0, 1.1]]},
    {"type": "camera", "orbit": [10, 0]},
    {"type": "screenshot", "path": "ignored.png"},
    {"type": "solve"},
    {"type": "save_target", "path": "target.ply"},
    {"type": "save_lights", "path": "lights.json"}]})";
  player.play(parse_session(script, "replay.json"));

  const Lighting lights = doc->state().lights;
  REQUIRE(!lights.empty());
  CHECK(read_lights_json(dir / "lights.json").size() == lights.size());
  CHECK(read_target(dir / "target.ply", *world.scene, *world.rays).size() == doc->painted_count());
  auto renderer = test::make_renderer("embree", world.scene, {"bounce_samples=16"});
  SurfacePoints probes;
  probes.positions = {{1.1f, 0.f, 1.05f}, {3.5f, 0.f, 3.5f}};
  probes.normals = {{0.f, 1.f, 0.f}, {0.f, 1.f, 0.f}};
  probes.albedo = {Rgb(0.8f), Rgb(0.8f)};
  std::vector<Rgb> lit = renderer->illuminate(probes, lights);
  INFO("patch " << lit[0].g << ", far corner " << lit[1].g);
  CHECK(lit[0].g > 0.3f);
  CHECK(lit[0].g > 4.f * lit[1].g);
  CHECK(doc->undo_label().rfind("solve", 0) == 0);
  REQUIRE(!log.empty());

  // Count control, undo and redo through the player.
  player.apply({"cut", {{"k", 1}}}, 0);
  CHECK(doc->state().lights.size() == 1);
  player.apply({"undo", {}}, 1);
  REQUIRE(doc->state().lights.size() == lights.size());
  for (size_t j = 0; j < lights.size(); ++j) CHECK(doc->state().lights[j].position == lights[j].position);
  player.apply({"redo", {}}, 2);
  CHECK(doc->state().lights.size() == 1);

  // Screen coordinates without a window: a clear error naming the action.
  try {
    player.apply({"stroke", {{"screen", {{10, 10}}}}}, 7);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK_THAT(std::string(e.what()), Contains("replay.json: action 7 (stroke): screen coordinates need the painter's window"));
  }
}

TEST_CASE("painter: the shadow and spotlight tools keep the painter's placement rules", "[painter][placement]") {
  auto world = painter_test::floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}});
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  SessionPlayer player(*doc, job, {}, {});
  const nlohmann::json shadow = {{"pairs", {{{"occluder", {0.5, 0.5, 0.0}},
                                             {"world", {{-1.0, 0.0, 0.0}, {-1.4, 0.0, 0.2}, {-1.2, 0.0, -0.2}, {-0.8, 0.0, 0.1}}}}}}};
  const nlohmann::json spot = {{"world", {{2.0, 0.0, 2.0}, {2.5, 0.0, 2.4}}}, {"eye", {2.0, 2.5, 0.0}}, {"direction", {0.1, -1.0, 0.8}}};
  constexpr float kTop = 1.5f;  // the rule: lights at most this high
  auto highest = [](const std::vector<Vec3>& points) {
    float y = -std::numeric_limits<float>::infinity();
    for (const Vec3& p : points) y = std::max(y, p.y);
    return y;
  };

  // Without a rule, the shadow's candidates and the spotlight's apex (the eye) stand higher.
  player.apply({"shadow", shadow}, 0);
  REQUIRE(player.last_shadow_estimate());
  REQUIRE(player.last_shadow_estimate()->requests.size() == 1);
  CHECK(highest(player.last_shadow_estimate()->requests[0].casting) > kTop);
  player.apply({"spot_region", spot}, 1);
  CHECK(doc->state().lights.back().position.y == Approx(2.5f));
  doc->undo();
  doc->undo();

  // With `place height:0:1.5`, every candidate, the estimated light and the spotlight keep it.
  player.apply({"place", {{"rules", "height:0:" + std::to_string(kTop)}}}, 2);
  player.apply({"shadow", shadow}, 3);
  const auto& estimate = *player.last_shadow_estimate();
  REQUIRE(estimate.requests.size() == 1);
  REQUIRE_FALSE(estimate.requests[0].casting.empty());
  CHECK(highest(estimate.requests[0].casting) <= kTop);
  REQUIRE(doc->state().lights.size() == 1);
  const Light estimated = doc->state().lights[0];
  CHECK(estimated.position.y <= kTop);
  CHECK(estimated.position.x > 0.5f);  // still on the side the shadow says
  player.apply({"spot_region", spot}, 4);
  REQUIRE(doc->state().lights.size() == 2);
  const Light& spotlight = doc->state().lights[1];
  INFO("spot at " << spotlight.position.x << " " << spotlight.position.y << " " << spotlight.position.z);
  CHECK(spotlight.type == LightType::Spot);
  CHECK(spotlight.position.y <= kTop);
  CHECK(player.light_space().admissible(spotlight.position));

  // A rule no place between the camera and the region keeps: the tool says so, naming the rule.
  player.apply({"place", {{"rules", "height:0:0.01"}}}, 5);
  CHECK_THROWS_WITH(player.apply({"spot_region", spot}, 6), Contains("height:0:0.01"));
}

TEST_CASE("painter: replayed shadow, spotlight, adjust and erase-shadow actions", "[painter]") {
  auto world = painter_test::floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}});
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  SessionPlayer player(*doc, job, {}, {});
  // Shadow stroked on the floor behind the box, away from +x: the light is on the +x side.
  player.apply({"shadow", {{"pairs", {{{"occluder", {0.5, 0.5, 0.0}},
                                        {"world", {{-1.0, 0.0, 0.0}, {-1.4, 0.0, 0.2}, {-1.2, 0.0, -0.2}, {-0.8, 0.0, 0.1}}}}}}}},
               0);
  REQUIRE(doc->state().lights.size() == 1);
  const Light estimated = doc->state().lights[0];
  CHECK(estimated.position.x > 0.5f);
  REQUIRE(player.last_shadow_estimate());

  // The estimated light now casts a shadow there: clicking it finds the box and that light.
  player.apply({"erase_shadow", {{"world", {-1.0, 0.0, 0.0}}}}, 1);
  REQUIRE(player.last_shadow_pairs().size() == 1);
  CHECK(player.last_shadow_pairs()[0].occluder == 1);
  CHECK(doc->undo_label() == "erase shadow");

  player.apply({"spot_region", {{"world", {{2.0, 0.0, 2.0}, {2.5, 0.0, 2.4}}}, {"eye", {2.0, 2.5, 0.0}}, {"direction", {0.1, -1.0, 0.8}}}}, 2);
  REQUIRE(doc->state().lights.size() == 2);
  CHECK(doc->state().lights[1].type == LightType::Spot);
  CHECK(doc->state().spot_hints.size() == 1);

  const Rgb before = doc->state().lights[0].intensity;
  player.apply({"adjust_region", {{"world", {{3.0, 0.0, -2.0}}}, {"multiplier", 2.0}, {"radius", 0.5}}}, 3);
  CHECK(doc->state().lights[0].intensity == 2.f * before);

  // Four undoable steps, all undone back to the empty document.
  for (int i = 0; i < 4; ++i) doc->undo();
  CHECK(doc->state().lights.empty());
  CHECK(doc->painted_count() == 0);
}

TEST_CASE("painter: an interactive solve result waits for the stroke in progress, then is dropped", "[painter]") {
  auto world = painter_test::make_world(builders::box_room({4.f, 3.f, 4.f}), 0.5f);
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  PlayerOptions options;
  options.wait_for_solves = false;
  SessionPlayer player(*doc, job, {}, options);
  player.apply({"brush", {{"radius", 0.6}, {"brightness", 0.5}}}, 0);
  player.apply({"stroke", {{"world", {{1.0, 0.0, 1.0}, {2.0, 0.0, 1.5}}}}}, 1);
  player.apply({"solve", {}}, 2);
  {
    Stroke stroke(*doc, player.brush(), BrushMode::Paint);
    stroke.dab_at({3.f, 0.f, 3.f});
    while (job.busy()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    CHECK_FALSE(player.poll());  // mid-stroke: not yet
  }
  // The stroke changed the target the solve answered: its result is dropped
  // (a replay, which waits for each solve, could not reproduce it otherwise).
  std::optional<JobResult> result = player.poll();
  REQUIRE(result);
  CHECK(result->outcome == JobOutcome::Superseded);
  CHECK(doc->state().lights.empty());
  CHECK(doc->undo_label() == "paint");  // the stroke kept its own step
  CHECK(job.cut_count() == 0);          // and a `cut` cannot take the dropped solve's lights
  // Undisturbed, a result is committed as one step.
  player.apply({"solve", {}}, 3);
  while (job.busy()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  result = player.poll();
  REQUIRE(result);
  REQUIRE(result->outcome == JobOutcome::Done);
  CHECK(doc->state().lights.size() == result->lights.size());
  CHECK(doc->undo_label().rfind("solve", 0) == 0);
}

TEST_CASE("painter: stroke, fine-tune and an undo while it runs: interactive and replay agree", "[painter]") {
  auto world = painter_test::make_world(builders::box_room({4.f, 3.f, 4.f}), 0.5f);
  const Session start = parse_session(R"({"actions": [
    {"type": "brush", "radius": 0.6, "brightness": 0.5},
    {"type": "stroke", "world": [[1, 0, 1], [2, 0, 1.5]]},
    {"type": "solve"},
    {"type": "brush", "brightness": 2},
    {"type": "stroke", "world": [[3, 0, 3]]}]})", "start");
  // Interactive: the fine-tune starts, the designer undoes the stroke while it runs.
  auto live = world.document();
  SolveJob live_job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  SessionRecorder recorder;
  {
    SessionPlayer replaying(*live, live_job, {}, {});
    replaying.play(start);
    for (const Action& a : start.actions) recorder.record(a);
  }
  PlayerOptions interactive;
  interactive.wait_for_solves = false;
  SessionPlayer player(*live, live_job, {}, interactive);
  const PaintState before = live->state();
  player.apply({"fine_tune", {}}, 5);
  // While it runs, saving lights waits (the replay would save the job's result).
  const auto dir = test::output_dir("painter_superseded");
  bool refused = false;
  try {
    player.apply({"save_lights", {{"path", (dir / "l.json").string()}}}, 6);
  } catch (const InputError& e) {
    refused = std::string(e.what()).find("wait for the running solve") != std::string::npos;
  }
  CHECK((refused || !live_job.busy()));
  player.apply({"undo", {}}, 6);
  recorder.record({"undo", {}});  // the window unrecords a job whose result is dropped
  while (live_job.busy()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::optional<JobResult> result = player.poll();
  REQUIRE(result);
  CHECK(result->outcome == JobOutcome::Superseded);
  CHECK(live->state().lights == before.lights);  // the tuned lights did not come back over the undo

  // The replay of the recording ends in the same state.
  auto replayed = world.document();
  SolveJob replay_job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  SessionPlayer(*replayed, replay_job, {}, {}).play(recorder.session());
  CHECK(replayed->state() == live->state());
}

TEST_CASE("painter: numbers must fit a float and points must be near the scene", "[painter]") {
  // Finite doubles that overflow (or underflow) float are refused before anything runs.
  CHECK_THAT(parse_error(R"({"actions": [{"type": "camera", "pan": [1e300, 0]}]})"), Contains("action 0: camera: 'pan' must be [x, y]"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "adjust_region", "world": [[0, 0, 0]], "multiplier": 1e300}]})"),
             Contains("'multiplier' must be"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "brush", "brightness": 1e300}]})"), Contains("'brightness' must be a number ≥ 0"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "brush", "radius": 1e-300}]})"), Contains("'radius' must be a number > 0"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "stroke", "world": [[0, 0, 0]], "normals": [[0, 0, 0]]}]})"),
             Contains("stroke: a normal must be a non-zero"));
  CHECK_THAT(parse_error(R"({"actions": [{"type": "stroke", "world": [[0, 0, 0]], "normals": [[0, 1, 0], [0, 1, 0]]}]})"),
             Contains("one normal per point"));

  auto world = painter_test::floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}});
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  std::vector<std::string> cameras;
  PlayerHooks hooks;
  hooks.camera = [&](const CameraAction& a) { cameras.push_back(untyped(a).params.dump()); };
  SessionPlayer player(*doc, job, hooks, {true, ".", "far.json"});
  auto error_of = [&](const std::string& script) {
    try {
      player.play(parse_session(script, "far.json"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Finite as float, but far beyond the scene: Embree's arithmetic would overflow.
  CHECK_THAT(error_of(R"({"actions": [{"type": "camera", "eye": [1e19, 1e19, 1e19], "target": [0, 0, 0]}]})"),
             Contains("far.json: action 0 (camera): camera: eye"));
  CHECK(cameras.empty());
  CHECK_THAT(error_of(R"({"actions": [{"type": "spot_region", "world": [[2, 0, 2]], "eye": [1e30, 2, 1], "direction": [-1, 0, 0]}]})"),
             Contains("spot_region: eye (1e+30, 2, 1) is more than 1e+06 scene diagonals from the scene"));
  CHECK_THAT(error_of(R"({"actions": [{"type": "stroke", "world": [[1e30, 0, 0]]}]})"), Contains("scene diagonals from the scene"));
  // Points off every surface are errors, not silently skipped (docs: snapped within 1% of the diagonal).
  CHECK_THAT(error_of(R"({"actions": [{"type": "stroke", "world": [[2, 0, 2], [2, 3, 2]]}]})"),
             Contains("far.json: action 0 (stroke): point 1 (2, 3, 2) is not on any surface"));
  CHECK(doc->painted_count() == 0);  // nothing of the stroke was applied
  CHECK_THAT(error_of(R"({"actions": [{"type": "adjust_region", "world": [[2, 3, 2]], "multiplier": 2}]})"),
             Contains("is not on any surface"));
  // World points a little above the floor snap onto it.
  CHECK(error_of(R"({"actions": [{"type": "stroke", "world": [[2, 0.05, 2]]}]})").empty());
  CHECK(doc->painted_count() > 0);
}

TEST_CASE("painter: values too large for a float are never written", "[painter]") {
  auto world = painter_test::floor_with_boxes({});
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  SessionPlayer player(*doc, job, {}, {});
  const auto dir = test::output_dir("painter_overflow");
  // Each valid as a float; their product is not.
  player.play(parse_session(R"({"actions": [{"type": "brush", "colour": 3e38, "brightness": 3e38},
                                             {"type": "stroke", "world": [[0, 0, 0]]}]})", "big.json"));
  CHECK_THROWS_WITH(doc->save_target(dir / "t.ply"), Contains("non-finite painted value"));
  CHECK_FALSE(std::filesystem::exists(dir / "t.ply"));
  doc->set_lights({Light::point({0.f, 2.f, 0.f}, Rgb(std::numeric_limits<float>::infinity()))}, "inf");
  CHECK_THROWS_WITH(doc->save_lights(dir / "l.json"), Contains("light 0 is not finite"));
  CHECK_FALSE(std::filesystem::exists(dir / "l.json"));
}

TEST_CASE("painter: recorded strokes carry their normals and brush values from the UI are clamped", "[painter]") {
  // A thin wall: both faces within a dab. The recorded normal picks the face painted.
  auto world = painter_test::floor_with_boxes({{{-1.f, 0.f, -0.01f}, {1.f, 1.f, 0.01f}}}, 0.2f);
  auto painted_with = [&](const nlohmann::json& normal) {
    auto doc = world.document();
    SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
    SessionPlayer player(*doc, job, {}, {});
    Action stroke{"stroke", {{"world", {{0.0, 0.5, 0.01}}}}};
    if (!normal.is_null()) stroke.params["normals"] = {normal};
    player.apply({"brush", {{"radius", 0.3}, {"hardness", 1.0}}}, 0);
    player.apply(stroke, 1);
    std::vector<uint32_t> painted;
    for (uint32_t v = 0; v < doc->state().weight.size(); ++v)
      if (doc->state().weight[v] > 0.f) painted.push_back(v);
    return std::pair(painted, world.scene->normals[painted.at(0)]);
  };
  const auto [front, front_normal] = painted_with({0.0, 0.0, 1.0});
  const auto [back, back_normal] = painted_with({0.0, 0.0, -1.0});
  CHECK(front_normal.z > 0.9f);
  CHECK(back_normal.z < -0.9f);
  CHECK(front != back);

  // What a typed-in slider value becomes is always a valid brush action.
  BrushSettings typed;
  typed.radius = 0.f;
  typed.colour = Rgb(-1.f, std::numeric_limits<float>::quiet_NaN(), 2.f);
  typed.brightness = 1e30f;
  typed.hardness = 3.f;
  const BrushSettings brush = clamped_brush(typed, 10.f);
  CHECK(brush.radius > 0.f);
  CHECK(brush.colour == Rgb(0.f, 0.f, 2.f));
  CHECK(brush.brightness <= 1e6f);
  CHECK(brush.hardness == 1.f);
  CHECK_NOTHROW(validate_action(brush_action(brush), "ui", 0));
  SessionRecorder recorder;
  CHECK_NOTHROW(recorder.record(brush_action(brush)));
}

TEST_CASE("painter: a replayed patch-and-shadow script yields a light in the shadow's cone that lights the patch", "[painter]") {
  auto world = painter_test::floor_with_boxes({{{-0.5f, 0.f, -0.5f}, {0.5f, 1.f, 0.5f}}});
  auto doc = world.document();
  SolveJob job(test::registry(), world.scene, world.rays, painter_test::quick_options());
  SessionPlayer player(*doc, job, {}, {});
  // The shadow the designer wants: behind the box as seen from (2.5, 3, 1).
  const Vec3 light_side(2.5f, 3.f, 1.f);
  nlohmann::json shadow = nlohmann::json::array();
  const Scene& scene = *world.scene;
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    const Vec3& p = scene.positions[v];
    if (p.y != 0.f || scene.normals[v].y < 0.9f || (std::abs(p.x) < 0.5f + 1e-4f && std::abs(p.z) < 0.5f + 1e-4f)) continue;
    const Vec3 d = light_side - p;
    if (world.rays->occluded(p + Vec3(0.f, 1e-3f, 0.f), glm::normalize(d), glm::length(d))) shadow.push_back({p.x, p.y, p.z});
  }
  REQUIRE(shadow.size() > 10);
  // Roughly what such a light gives: the shadow's surroundings at a quarter
  // of the patch's brightness (a designer's guess, not a rendering).
  Vec3 centre(0.f);
  for (const auto& p : shadow) centre += Vec3(p[0].get<float>(), 0.f, p[2].get<float>());
  centre /= float(shadow.size());
  const nlohmann::json actions = {
      {{"type", "brush"}, {"radius", 2.0}, {"colour", 1.0}, {"brightness", 0.2}, {"hardness", 0.7}},
      {{"type", "stroke"}, {"world", {{centre.x, 0, centre.z}}}},
      {{"type", "brush"}, {"radius", 0.6}, {"brightness", 0.8}},
      {{"type", "stroke"}, {"world", {{2.0, 0, 0.8}}}},  // the bright patch
      {{"type", "brush"}, {"radius", 0.25}, {"brightness", 0.01}},
      {{"type", "stroke"}, {"world", shadow}},
      {{"type", "shadow"}, {"pairs", {{{"occluder", {0.0, 1.0, 0.0}}, {"world", shadow}}}}},
      {{"type", "fine_tune"}}};
  std::string text = R"({"actions": [)";
  for (size_t i = 0; i < actions.size(); ++i) text += (i ? "," : "") + actions[i].dump();
  player.play(parse_session(text + "]}", "patch-and-shadow.json"));

  REQUIRE(player.last_shadow_estimate());
  const RequestCandidates& cone = player.last_shadow_estimate()->requests.at(0);
  REQUIRE(doc->state().lights.size() == 1);
  const Light light = doc->state().lights[0];
  const Vec3 axis = cone.occluder_centre - cone.shadow_centre;
  const double angle = std::acos(std::clamp(double(glm::dot(glm::normalize(light.position - cone.occluder_centre),
                                                            glm::normalize(axis))), -1.0, 1.0)) * 180.0 / kPi;
  INFO("light at " << light.position.x << ", " << light.position.y << ", " << light.position.z << ": " << angle
                   << "° off the cone's axis (half-angle " << cone.cone_angle_deg << "°)");
  // The cone the shadow implies, physically: from the light, the box shadows
  // the stroke. The paper's cone (axis from the shadow's centroid through the
  // box centre) is 10-16° off the true direction for a box (tools test), so
  // the refined light may leave it by up to that much.
  size_t covered = 0;
  for (const auto& p : shadow) {
    const Vec3 q(p[0].get<float>(), 0.001f, p[2].get<float>());
    const Vec3 d = light.position - q;
    covered += world.rays->occluded(q, glm::normalize(d), glm::length(d));
  }
  CHECK(double(covered) >= 0.7 * double(shadow.size()));
  CHECK(angle <= cone.cone_angle_deg + 10.0);
  auto renderer = test::make_renderer("embree", world.scene, {"bounce_samples=16"});
  SurfacePoints probes;
  probes.positions = {{2.f, 0.f, 0.8f}, {shadow[0][0].get<float>(), 0.f, shadow[0][2].get<float>()}};
  probes.normals = {{0.f, 1.f, 0.f}, {0.f, 1.f, 0.f}};
  probes.albedo = {Rgb(0.7f), Rgb(0.7f)};
  const std::vector<Rgb> lit = renderer->illuminate(probes, doc->state().lights);
  INFO("patch " << lit[0].g << ", shadow " << lit[1].g);
  CHECK(lit[0].g > 0.3f);
  CHECK(lit[1].g < 0.2f * lit[0].g);
}

TEST_CASE("painter session: every action type is documented in docs/painter.md and validates", "[painter]") {
  const std::string docs = test::read_file(std::filesystem::path(HILIGHT_SOURCE_DIR) / "docs/painter.md");
  REQUIRE(!hilight::painter::action_types().empty());
  for (const std::string& type : hilight::painter::action_types()) {
    INFO(type);
    CHECK(docs.find("`" + type + "`") != std::string::npos);
  }
  CHECK_THROWS_AS(hilight::painter::validate_action({"no_such_action", {}}, "s", 0), hilight::InputError);
}
