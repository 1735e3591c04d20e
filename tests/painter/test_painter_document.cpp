// The painter's document: undo/redo of whole snapshots, the brush and its
// strokes, and the target and lights files (round trips through the same
// readers `hilight solve` uses).
#include "core/brush.hpp"
#include "core/document.hpp"
#include "hilight/error.hpp"
#include "hilight/io/lights_json.hpp"
#include "hilight/io/ply.hpp"
#include "painter_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace hilight;
using namespace hilight::painter;
using painter_test::make_world;

namespace {

size_t painted(const PaintState& s) {
  size_t n = 0;
  for (float w : s.weight) n += w > 0.f;
  return n;
}

} // namespace

TEST_CASE("painter: undo and redo restore every state exactly", "[painter]") {
  auto world = make_world(builders::plane(2.f), 0.25f);
  auto doc = world.document();
  const PaintState empty = doc->state();
  CHECK_FALSE(doc->can_undo());

  BrushSettings brush;
  brush.radius = 0.6f;
  brush.colour = Rgb(1.f, 0.5f, 0.25f);
  paint_stroke(*doc, brush, BrushMode::Paint, {Vec3(0.f), Vec3(0.3f, 0.f, 0.f)});
  const PaintState one_stroke = doc->state();
  REQUIRE(painted(one_stroke) > 0);
  CHECK(doc->undo_label() == "paint");

  doc->set_lights({Light::point({0.f, 1.f, 0.f}, Rgb(2.f))}, "solve");
  const PaintState with_lights = doc->state();
  paint_stroke(*doc, brush, BrushMode::Erase, {Vec3(0.f)});
  const PaintState erased = doc->state();
  CHECK(painted(erased) < painted(with_lights));

  doc->undo();
  CHECK(doc->state() == with_lights);
  doc->undo();
  CHECK(doc->state() == one_stroke);
  doc->undo();
  CHECK(doc->state() == empty);
  CHECK_FALSE(doc->can_undo());
  doc->redo();
  doc->redo();
  CHECK(doc->state() == with_lights);
  CHECK(doc->redo_label() == "erase");
  doc->redo();
  CHECK(doc->state() == erased);
  CHECK_FALSE(doc->can_redo());

  // A new edit after undo drops the redo list; an edit that changes nothing leaves no step.
  doc->undo();
  doc->set_lights({}, "clear");
  CHECK_FALSE(doc->can_redo());
  const auto revision = doc->revision();
  doc->set_lights({}, "clear again");
  CHECK(doc->undo_label() == "clear");
  CHECK(doc->revision() == revision);
}

TEST_CASE("painter: a stroke is one undo step and cancel restores", "[painter]") {
  auto world = make_world(builders::plane(2.f), 0.25f);
  auto doc = world.document();
  BrushSettings brush;
  brush.radius = 0.3f;
  {
    Stroke stroke(*doc, brush, BrushMode::Paint);
    for (int i = 0; i <= 20; ++i) REQUIRE(stroke.dab_at({-1.f + 0.1f * float(i), 0.f, 0.f}));
    CHECK(painted(doc->state()) > 0);  // visible while the stroke is open
    CHECK(stroke.points().size() == 21);
  }
  CHECK(doc->can_undo());
  doc->undo();
  CHECK(painted(doc->state()) == 0);
  CHECK_FALSE(doc->can_undo());

  doc->begin_edit().weight[0] = 1.f;
  doc->cancel_edit();
  CHECK(painted(doc->state()) == 0);
  CHECK_FALSE(doc->can_undo());
}

TEST_CASE("painter: brush coverage, colour and the thin-wall rule", "[painter]") {
  BrushSettings brush;
  brush.radius = 1.f;
  brush.hardness = 1.f;
  CHECK(brush_coverage(brush, 0.99f) == 1.f);
  CHECK(brush_coverage(brush, 1.01f) == 0.f);
  brush.hardness = 0.f;
  CHECK(brush_coverage(brush, 0.f) == 1.f);
  CHECK(brush_coverage(brush, 0.5f) == Approx(0.5f));
  CHECK(brush_coverage(brush, 0.9f) < brush_coverage(brush, 0.5f));

  // A wall 2 cm thick: a dab on its +x face with a 30 cm radius must not
  // reach the -x face, though it lies within the radius.
  Scene raw = builders::plane(2.f);
  builders::add_box(raw, {-0.01f, 0.f, -1.f}, {0.01f, 1.5f, 1.f}, Rgb(0.5f), false, "wall");
  auto world = make_world(std::move(raw), 0.1f);
  auto doc = world.document();
  brush = BrushSettings{0.3f, Rgb(0.2f, 0.4f, 0.8f), 2.f, 0.5f};
  Stroke stroke(*doc, brush, BrushMode::Paint);
  stroke.dab({{0.01f, 0.7f, 0.f}, {1.f, 0.f, 0.f}});
  stroke.finish();
  const Scene& scene = *world.scene;
  size_t front = 0, back = 0;
  for (size_t v = 0; v < scene.positions.size(); ++v) {
    if (!(doc->state().weight[v] > 0.f)) continue;
    if (scene.normals[v].x > 0.5f) ++front;
    if (scene.normals[v].x < -0.5f) ++back;
    if (glm::length(scene.positions[v] - Vec3(0.01f, 0.7f, 0.f)) < 0.149f) {  // inside the hard core
      CHECK(doc->state().psi[v] == Rgb(0.4f, 0.8f, 1.6f));
      CHECK(doc->state().weight[v] == 1.f);
    }
  }
  CHECK(front > 0);
  CHECK(back == 0);
}

TEST_CASE("painter: the saved target reads back through read_target", "[painter]") {
  auto world = make_world(builders::box_room({3.f, 2.f, 3.f}), 0.4f);
  auto doc = world.document();
  BrushSettings brush;
  brush.radius = 0.5f;
  brush.colour = Rgb(0.9f, 0.6f, 0.3f);
  brush.hardness = 0.3f;
  paint_stroke(*doc, brush, BrushMode::Paint, {{1.f, 0.f, 1.f}, {1.5f, 0.f, 1.2f}, {0.f, 1.f, 1.5f}});
  const size_t n = doc->painted_count();
  REQUIRE(n > 10);
  const auto dir = test::output_dir("painter_target_roundtrip");
  doc->save_target(dir / "target.ply");

  Target read = read_target(dir / "target.ply", *world.scene, *world.rays);
  Target direct = doc->target();
  REQUIRE(read.size() == n);
  REQUIRE(direct.size() == n);
  for (size_t i = 0; i < n; ++i) {
    CHECK(read.value[i] == direct.value[i]);
    CHECK(read.weight[i] == direct.weight[i]);
    CHECK(read.binding[i].triangle == direct.binding[i].triangle);
  }
  // Loading it back paints exactly the same vertices with the same values.
  const PaintState before = doc->state();
  auto other = world.document();
  other->load_target(dir / "target.ply");
  CHECK(other->state().psi == before.psi);
  CHECK(other->state().weight == before.weight);

  // A rendered PLY (what `hilight render` writes: every vertex, no weights)
  // loads as a target on every vertex with its exact colours.
  std::vector<Rgb> radiance(world.scene->positions.size());
  for (size_t v = 0; v < radiance.size(); ++v) radiance[v] = Rgb(0.01f * float(v % 97), 0.5f, 0.25f);
  write_illuminated_ply(dir / "rendered.ply", *world.scene, radiance);
  auto rendered = world.document();
  rendered->load_target(dir / "rendered.ply");
  CHECK(rendered->painted_count() == radiance.size());
  size_t exact = 0;
  for (size_t v = 0; v < radiance.size(); ++v) exact += rendered->state().psi[v] == radiance[v];
  CHECK(exact == radiance.size());

  // Lights through the lights JSON.
  Lighting lights = {Light::point({1.f, 1.5f, 1.f}, Rgb(3.f, 2.f, 1.f)),
                     Light::spot({1.5f, 1.9f, 1.5f}, {0.f, -1.f, 0.f}, 25.f, Rgb(4.f), 5.f)};
  doc->set_lights(lights, "lights");
  doc->save_lights(dir / "lights.json");
  other->load_lights(dir / "lights.json");
  CHECK(read_lights_json(dir / "lights.json").size() == 2);
  CHECK(other->state().lights.size() == 2);
  CHECK(other->state().lights[1].type == LightType::Spot);

  // Nothing painted: a clear error and no file.
  auto blank = world.document();
  CHECK_THROWS_AS(blank->save_target(dir / "blank.ply"), InputError);
  CHECK_FALSE(std::filesystem::exists(dir / "blank.ply"));
  CHECK_THROWS_AS(blank->target(), InputError);
}
